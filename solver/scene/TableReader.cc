#include <solver/scene/TableReader.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace beamimpact {
namespace {

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    default: return "a date/time";
  }
}

/// The edit distance of a and b (insertions, deletions, substitutions).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string shortest(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

/// The innermost KeyLog alive on this thread, or null.
thread_local KeyLog* active_log = nullptr;

}  // namespace

KeyLog::KeyLog() : outer_(active_log) { active_log = this; }
KeyLog::~KeyLog() { active_log = outer_; }

TableReader::TableReader(const toml::table& table, std::string file, std::string prefix,
                         std::map<std::string, std::string>* assumed)
    : table_(table), file_(std::move(file)), prefix_(std::move(prefix)), assumed_(assumed) {}

std::string TableReader::path(const std::string& key) const {
  return prefix_.empty() ? key : prefix_ + "." + key;
}

void TableReader::fail(const std::string& key, const std::string& message) const {
  throw InputError(file_, path(key), message);
}

void TableReader::missing(const std::string& key, const std::string& what) const {
  // A key of this table that no read asked for and that is a key's spelling away from the one
  // missing is named: "dtt = 0.01" must not read as "time.dt missing" alone.
  std::string near;
  for (const auto& [k, v] : table_) {
    const std::string name(k.str());
    if (seen_.count(name) || name == key) continue;
    if (edit_distance(name, key) <= (key.size() <= 4 ? 1u : 2u))
      near += (near.empty() ? "" : ", ") + path(name);
  }
  fail(key, "missing; expected " + what +
                (near.empty() ? "" : " (the table has the unknown key " + near + ": a misspelling?)"));
}

void TableReader::mark(const std::string& key) {
  seen_.insert(key);
  if (active_log) active_log->keys_.insert(path(key));
}

const toml::node* TableReader::find(const std::string& key) {
  mark(key);
  return table_.get(key);
}

void TableReader::assume(const std::string& key, const std::string& value) {
  if (assumed_) (*assumed_)[path(key)] = value;
}

bool TableReader::has(const std::string& key) { return find(key) != nullptr; }
const toml::node* TableReader::raw(const std::string& key) { return find(key); }

double TableReader::number(const std::string& key, const std::string& what) {
  const toml::node* n = find(key);
  if (!n) missing(key, what);
  double v;
  if (auto i = n->as_integer())
    v = static_cast<double>(i->get());
  else if (auto f = n->as_floating_point())
    v = f->get();
  else
    fail(key, "expected " + what + ", got " + type_name(*n));
  if (!std::isfinite(v)) fail(key, "expected " + what + ", got a non-finite value");
  return v;
}

double TableReader::number_or(const std::string& key, double fallback, const std::string& what) {
  if (!table_.get(key)) {
    mark(key);
    assume(key, shortest(fallback));
    return fallback;
  }
  return number(key, what);
}

long TableReader::integer(const std::string& key, const std::string& what) {
  const toml::node* n = find(key);
  if (!n) missing(key, what);
  auto i = n->as_integer();
  if (!i) fail(key, "expected " + what + ", got " + type_name(*n));
  return static_cast<long>(i->get());
}

long TableReader::integer_or(const std::string& key, long fallback, const std::string& what) {
  if (!table_.get(key)) {
    mark(key);
    assume(key, std::to_string(fallback));
    return fallback;
  }
  return integer(key, what);
}

std::string TableReader::string(const std::string& key, const std::string& what) {
  const toml::node* n = find(key);
  if (!n) missing(key, what);
  auto s = n->as_string();
  if (!s) fail(key, "expected " + what + ", got " + type_name(*n));
  return s->get();
}

std::string TableReader::choice_or(const std::string& key, const std::string& fallback,
                                   const std::vector<std::string>& allowed) {
  std::string expected = "one of";
  for (const auto& a : allowed) expected += " \"" + a + "\"";
  if (!table_.get(key)) {
    mark(key);
    assume(key, fallback);
    return fallback;
  }
  const std::string v = string(key, expected);
  if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), v) == allowed.end())
    fail(key, "expected " + expected + ", got \"" + v + "\"");
  return v;
}

bool TableReader::boolean_or(const std::string& key, bool fallback) {
  const std::optional<bool> v = boolean_opt(key);
  if (!v) assume(key, fallback ? "true" : "false");
  return v.value_or(fallback);
}

std::optional<bool> TableReader::boolean_opt(const std::string& key) {
  const toml::node* n = find(key);
  if (!n) return std::nullopt;
  auto b = n->as_boolean();
  if (!b) fail(key, "expected true or false, got " + type_name(*n));
  return b->get();
}

std::vector<std::string> TableReader::strings(const std::string& key, bool required) {
  std::vector<std::string> out;
  const toml::node* n = find(key);
  if (!n) {
    if (required) missing(key, "an array of strings");
    return out;
  }
  const toml::array* a = n->as_array();
  if (!a) fail(key, "expected an array of strings");
  for (const auto& e : *a) {
    const auto v = e.value<std::string>();
    if (!v) fail(key, "expected an array of strings");
    out.push_back(*v);
  }
  return out;
}

Vec2 TableReader::vec2(const std::string& key, const std::string& what) {
  const toml::node* n = find(key);
  if (!n) missing(key, what);
  const toml::array* a = n->as_array();
  if (!a || a->size() != 2) fail(key, "expected " + what + " (an array of two numbers)");
  Vec2 v{};
  for (std::size_t i = 0; i < 2; ++i) {
    const toml::node& e = *a->get(i);
    if (auto x = e.as_integer())
      v[i] = static_cast<double>(x->get());
    else if (auto f = e.as_floating_point())
      v[i] = f->get();
    else
      fail(key, "expected " + what + " (an array of two numbers), element " + std::to_string(i) + " is " +
                    type_name(e));
    if (!std::isfinite(v[i])) fail(key, "expected " + what + ", got a non-finite value");
  }
  return v;
}

void TableReader::finish() const {
  for (auto&& [k, v] : table_) {
    const std::string key(k.str());
    if (!seen_.count(key)) fail(key, "unknown key (a typo? unknown keys are errors)");
  }
}

MethodOptions::MethodOptions(const Scene& scene, const std::string& method,
                             std::map<std::string, std::string>* assumed)
    : reader_(
          [&]() -> const toml::table& {
            const auto it = scene.method_tables.find(method);
            return it == scene.method_tables.end() ? empty_ : it->second;
          }(),
          scene.file, method, assumed) {}

}  // namespace beamimpact
