#include <api/registry.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <mutex>

#include <api/child_process.hpp>
#include <api/methods_file.hpp>
#include <solver/paper/method.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {

/// Appends the entry of every reference registered with beamimpact_method() (each written in its
/// own folder, references/NAME/method.cc), in folder order: defined in the file api/CMakeLists.txt
/// generates from that list.
void add_reference_methods(std::deque<Method>& t);

namespace {

/// The in-process methods of this build, paper first.
std::deque<Method> built_in() {
  std::deque<Method> t{paper::method()};
  add_reference_methods(t);
  for (Method& m : t) m.origin = "built-in";
  return t;
}

std::deque<Method>& table() {
  static std::deque<Method> t = built_in();
  return t;
}

}  // namespace

const std::deque<Method>& methods() {
  static const bool defaults_read = [] {
    for (const auto& f : default_methods_files()) load_methods_file(f);
    return true;
  }();
  (void)defaults_read;
  return table();
}

namespace {

/// Method names compare without case: "PAPER" names the paper's method, and no file may declare it.
bool same_name(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

}  // namespace

void add_method(Method m, const std::string& file, const std::string& key) {
  for (const Method& other : table())
    if (same_name(other.name, m.name))
      throw InputError(file, key,
                       "a method named '" + other.name + "' is already declared (" + other.origin +
                           "); expected a new name (names compare without case)");
  table().push_back(std::move(m));
}

const Method* find_method(std::string_view name) {
  for (const Method& m : methods())
    if (same_name(m.name, name)) return &m;
  return nullptr;
}

std::string method_names() {
  std::string names;
  for (const Method& m : methods()) names += (names.empty() ? "" : ", ") + m.name;
  return names;
}

const Method& method(std::string_view name, const std::string& file, const std::string& key) {
  if (const Method* m = find_method(name)) return *m;
  throw InputError(file, key,
                   "expected a method name (" + method_names() + "), got '" + std::string(name) + "'");
}

int thread_limit() {
  int most = 1;
  for (const Method& m : methods()) most = std::max(most, m.max_threads);
  return most;
}

const Method& default_method() { return methods().front(); }

std::string unavailable(const Method& m) {
  if (m.in_process() || m.check.empty()) return "";
  static std::mutex mu;
  static std::map<std::string, std::string> reasons;  // method -> why not ("" = it can run)
  std::lock_guard lock(mu);
  if (auto it = reasons.find(m.name); it != reasons.end()) return it->second;
  const ProcessResult r = spawn_and_wait(m.check, "/dev/null", m.check_timeout);
  std::string why;
  if (!r.error.empty() || r.exit_code != 0) {
    std::string cmd;
    for (const auto& a : m.check) cmd += (cmd.empty() ? "" : " ") + a;
    why = m.name + ": its check '" + cmd + "' " +
          (r.error.empty() ? "exited " + std::to_string(r.exit_code) : r.error) + " (not installed here?)";
  }
  return reasons[m.name] = why;
}

}  // namespace beamimpact
