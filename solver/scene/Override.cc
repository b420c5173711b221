#include <solver/scene/Override.hpp>

#include <cstdlib>
#include <type_traits>

#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

/// Splits "bodies[1].elements" / "bodies.B.elements" / "time.dt" into segments.
std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : key) {
    if (c == '.' || c == '[') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else if (c != ']') {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

/// The entry `sel` (an index from 0 or a body name) of an array of tables, or null.
toml::table* array_entry(toml::array& arr, const std::string& sel) {
  char* endp = nullptr;
  const long idx = std::strtol(sel.c_str(), &endp, 10);
  if (*endp == '\0' && idx >= 0 && static_cast<std::size_t>(idx) < arr.size())
    return arr.get(static_cast<std::size_t>(idx))->as_table();
  toml::table* found = nullptr;
  for (auto& el : arr)
    if (auto* tb = el.as_table(); tb && tb->get("name") && tb->get("name")->value<std::string>() == sel)
      found = tb;
  return found;
}

}  // namespace

Override make_override(std::string key, const toml::node& value, std::string text) {
  auto copy = value.visit([](const auto& n) -> std::shared_ptr<const toml::node> {
    return std::make_shared<std::remove_cvref_t<decltype(n)>>(n);
  });
  return Override{std::move(key), std::move(copy), std::move(text)};
}

Override parse_override(const std::string& assignment, const std::string& file) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(file, assignment, "--set expects key=value (e.g. time.dt=0.005)");
  std::string key = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  // The value is TOML ("0.005", "[1, 0]", "true", "\"lumped\""); a bare word is a string.
  auto parsed = std::make_shared<toml::table>();
  try {
    *parsed = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    *parsed = toml::table{{"v", text}};
  }
  const toml::node* value = parsed->get("v");
  return Override{std::move(key), std::shared_ptr<const toml::node>(parsed, value), std::move(text)};
}

std::vector<Override> parse_overrides(const std::vector<std::string>& assignments, const std::string& file) {
  std::vector<Override> out;
  out.reserve(assignments.size());
  for (const std::string& a : assignments) out.push_back(parse_override(a, file));
  return out;
}

void apply_override(toml::table& root, const std::string& file, const Override& o) {
  const std::string& key = o.key;
  const std::vector<std::string> seg = split_key(key);
  if (seg.empty()) throw InputError(file, key, "--set: empty key");
  toml::table* t = &root;
  for (std::size_t i = 0; i + 1 < seg.size(); ++i) {
    toml::node* next = t->get(seg[i]);
    if (!next) {  // a new sub-table ([ida] options and the like)
      t->insert_or_assign(seg[i], toml::table{});
      next = t->get(seg[i]);
    }
    if (toml::array* arr = next->as_array()) {  // array of tables: an index or a body name
      const std::string& sel = seg[++i];
      toml::table* found = array_entry(*arr, sel);
      if (!found)
        throw InputError(
            file, key,
            "--set: no entry '" + sel + "' in '" + seg[i - 1] + "' (use an index from 0 or a body name)");
      if (i + 1 == seg.size()) throw InputError(file, key, "--set: expected a key after '" + sel + "'");
      t = found;
      continue;
    }
    t = next->as_table();
    if (!t) throw InputError(file, key, "--set: '" + seg[i] + "' is not a table");
  }
  t->insert_or_assign(seg.back(), *o.value);
}

}  // namespace beamimpact
