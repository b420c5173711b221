#include "dict_to_toml.hpp"

#include <sstream>

#include <toml++/toml.h>
#include <nlohmann/json.hpp>

#include <solver/util/InputError.hpp>

namespace beamimpact::python {
namespace {

using nlohmann::json;

toml::table to_table(const json& j, const std::string& label, const std::string& path);

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

template <typename T>
void put(toml::array& a, const std::string&, T&& x) {
  a.push_back(std::forward<T>(x));
}
template <typename T>
void put(toml::table& t, const std::string& key, T&& x) {
  t.insert_or_assign(key, std::forward<T>(x));
}

/// Puts value `v` into `into` (a table, under `key`, or an array); `where` is its dotted path.
template <typename Container>
void convert(Container& into, const std::string& key, const json& v, const std::string& label,
             const std::string& where) {
  switch (v.type()) {
    case json::value_t::object: put(into, key, to_table(v, label, where)); break;
    case json::value_t::array: {
      toml::array a;
      for (std::size_t i = 0; i < v.size(); ++i)
        convert(a, key, v[i], label, where + "[" + std::to_string(i) + "]");
      put(into, key, std::move(a));
      break;
    }
    case json::value_t::string: put(into, key, v.get<std::string>()); break;
    case json::value_t::boolean: put(into, key, v.get<bool>()); break;
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: put(into, key, v.get<std::int64_t>()); break;
    case json::value_t::number_float: put(into, key, v.get<double>()); break;
    default: throw InputError(label, where, "expected a number, string, boolean, list or dict, got None");
  }
}

toml::table to_table(const json& j, const std::string& label, const std::string& path) {
  toml::table t;
  for (const auto& [key, value] : j.items()) convert(t, key, value, label, join(path, key));
  return t;
}

}  // namespace

std::string toml_from_json(const std::string& json_text, const std::string& label) {
  const json j = json::parse(json_text);
  if (!j.is_object()) throw InputError(label, "", "expected a dict of the scene's tables and keys");
  std::ostringstream os;
  os << to_table(j, label, "");
  return os.str() + "\n";
}

}  // namespace beamimpact::python
