#include "dict_to_toml.hpp"

#include <cstdint>
#include <memory>

#include <solver/util/InputError.hpp>

namespace py = pybind11;

namespace beamimpact::python {
namespace {

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

toml::table to_table(const py::dict& d, const std::string& label, const std::string& path);

/// The TOML value of a Python value; `where` is its dotted path for messages.
std::unique_ptr<toml::node> to_node(py::handle v, const std::string& label, const std::string& where) {
  if (v.is_none())
    throw InputError(label, where, "expected a number, string, boolean, list or dict, got None");
  if (py::isinstance<py::bool_>(v)) return std::make_unique<toml::value<bool>>(v.cast<bool>());
  if (py::isinstance<py::int_>(v)) {
    try {
      return std::make_unique<toml::value<std::int64_t>>(v.cast<std::int64_t>());
    } catch (const py::cast_error&) {
      throw InputError(label, where,
                       "expected an integer of at most 64 bits, got " + py::str(v).cast<std::string>());
    }
  }
  if (py::isinstance<py::float_>(v)) return std::make_unique<toml::value<double>>(v.cast<double>());
  if (py::isinstance<py::str>(v)) return std::make_unique<toml::value<std::string>>(v.cast<std::string>());
  if (py::isinstance<py::dict>(v))
    return std::make_unique<toml::table>(to_table(v.cast<py::dict>(), label, where));
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    auto a = std::make_unique<toml::array>();
    std::size_t i = 0;
    for (py::handle e : v) {
      std::unique_ptr<toml::node> n = to_node(e, label, where + "[" + std::to_string(i++) + "]");
      n->visit([&](auto& x) { a->push_back(std::move(x)); });
    }
    return a;
  }
  if (py::hasattr(v, "tolist") && py::hasattr(v, "dtype"))  // a numpy scalar or array: its plain values
    return to_node(v.attr("tolist")(), label, where);
  throw py::type_error(py::str(v.get_type().attr("__name__")).cast<std::string>() +
                       " is not a scene value (numbers, strings, booleans, lists, dicts)");
}

toml::table to_table(const py::dict& d, const std::string& label, const std::string& path) {
  toml::table t;
  for (const auto& [k, v] : d) {
    const std::string key = py::str(k).cast<std::string>();
    std::unique_ptr<toml::node> n = to_node(v, label, join(path, key));
    n->visit([&](auto& x) { t.insert_or_assign(key, std::move(x)); });
  }
  return t;
}

}  // namespace

toml::table table_from_dict(const py::dict& tables, const std::string& label) {
  return to_table(tables, label, "");
}

std::vector<Override> overrides_from_python(const py::list& items, const std::string& label) {
  std::vector<Override> out;
  for (py::handle item : items) {
    if (py::isinstance<py::str>(item)) {
      out.push_back(parse_override(item.cast<std::string>(), label));
      continue;
    }
    const auto t = item.cast<py::tuple>();
    if (t.size() != 3) throw py::type_error("an override is \"key=value\" or (key, value, text)");
    const auto key = t[0].cast<std::string>();
    const std::unique_ptr<toml::node> value = to_node(t[1], label, key);
    out.push_back(make_override(key, *value, t[2].cast<std::string>()));
  }
  return out;
}

}  // namespace beamimpact::python
