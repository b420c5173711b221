#include <verification/matrix/JobSpec.hpp>

#include <algorithm>
#include <cstdlib>

#include <fmt/format.h>

#include <api/registry.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/InputError.hpp>
#include <verification/matrix/child_process.hpp>

namespace beamimpact::verification {
namespace {

std::string safe(std::string s) {
  for (char& c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')) c = '_';
  return s;
}

int mesh_factor(const JobSpec& s) {
  char* end = nullptr;
  const long m = std::strtol(s.mesh.c_str(), &end, 10);
  if (end == s.mesh.c_str() || *end != '\0' || m < 1 || m > 64) {
    throw InputError(
        s.scene.string(), "mesh",
        "expected an element multiplier 1..64 for method '" + s.method + "', got '" + s.mesh + "'");
  }
  return static_cast<int>(m);
}

}  // namespace

std::string JobSpec::scene_name() const { return scene.stem().string(); }

std::string JobSpec::settings_label() const {
  std::string s = method;
  if (dt) s += fmt::format(" dt={:g}", *dt);
  if (!mesh.empty()) s += " mesh=" + mesh;
  for (const auto& o : set) s += " " + o;
  for (const auto& a : args) s += " " + a;
  return s;
}

std::string JobSpec::key() const {
  std::string k = scene_name() + "." + method;
  if (dt) k += fmt::format(".dt{:g}", *dt);
  if (!mesh.empty()) k += ".mesh" + mesh;
  for (const auto& o : set) k += "." + o;
  for (const auto& a : args) k += "." + a;
  return safe(k);
}

std::vector<std::string> mesh_overrides(const std::filesystem::path& scene, int m) {
  const Scene sc = load_scene(scene);
  std::vector<std::string> out;
  for (std::size_t i = 0; i < sc.bodies.size(); ++i)
    out.push_back(fmt::format("bodies[{}].elements={}", i, sc.bodies[i].elements * m));
  return out;
}

std::vector<std::string> Launcher::resolve(const std::vector<std::string>& command) const {
  std::vector<std::string> a = command;
  for (std::string& x : a)
    if (!x.empty() && x[0] != '/' && x[0] != '-' && x.find('/') != std::string::npos) x = (root / x).string();
  return a;
}

std::string Launcher::unavailable(const JobSpec& spec) const {
  const Method* m = find_method(spec.method);
  if (!m) return "method '" + spec.method + "' is not in the registry (" + method_names() + ")";
  if (m->in_process()) return "";
  if (auto it = reasons_.find(m->name); it != reasons_.end()) return it->second;
  std::string& why = reasons_[m->name];
  for (const std::string& p : resolve(m->command))
    if (p[0] == '/' && !std::filesystem::exists(p)) why = m->name + ": " + p + " not found";
  if (why.empty() && !m->check.empty()) {
    const auto check = resolve(m->check);
    const auto r = spawn_and_wait(check, "/dev/null", 120.0);
    if (r.exit_code != 0)
      why = m->name + ": '" + fmt::format("{}", fmt::join(check, " ")) + "' failed (not installed?)";
  }
  return why;
}

std::vector<std::string> Launcher::argv(const JobSpec& spec, const std::filesystem::path& out_dir) const {
  const Method& m = method(spec.method, spec.scene.string(), "method");
  if ((spec.dt && !m.accepts.dt) || (!spec.set.empty() && !m.accepts.overrides))
    throw InputError(spec.scene.string(), spec.dt ? "dt" : "set",
                     "the method '" + m.name + "' takes no " + (spec.dt ? "dt" : "--set overrides") +
                         "; use args = [...] with its own options");
  std::vector<std::string> a;
  if (!m.in_process()) {
    a = resolve(m.command);
    a.insert(a.end(), {spec.scene.string(), "--out", out_dir.string(), "--quiet"});
    if (!spec.mesh.empty()) a.insert(a.end(), {m.mesh_option, spec.mesh});
    a.insert(a.end(), spec.args.begin(), spec.args.end());
    return a;
  }
  a = {exe.string(),     "run",      spec.scene.string(), "--out",
       out_dir.string(), "--method", spec.method,         "--quiet"};
  std::vector<std::string> sets = spec.set;
  if (spec.dt) sets.push_back(fmt::format("time.dt={:.17g}", *spec.dt));
  if (!spec.mesh.empty()) {
    const auto mo = mesh_overrides(spec.scene, mesh_factor(spec));
    sets.insert(sets.end(), mo.begin(), mo.end());
  }
  for (const auto& s : sets) a.insert(a.end(), {"--set", s});
  a.insert(a.end(), spec.args.begin(), spec.args.end());
  return a;
}

std::filesystem::path find_source_root(const std::filesystem::path& start) {
  namespace fs = std::filesystem;
  std::vector<fs::path> needed;
  for (const Method& m : methods())
    for (const std::string& x : m.command)
      if (!x.empty() && x[0] != '/' && x.find('/') != std::string::npos) needed.emplace_back(x);
  std::error_code unreadable;  // a path the file system refuses (too long) counts as absent
  auto holds_all = [&](const fs::path& d) {
    for (const fs::path& p : needed)
      if (!fs::exists(d / p, unreadable)) return false;
    return true;
  };
  fs::path d = fs::absolute(start);
  if (!fs::is_directory(d, unreadable)) d = d.parent_path();
  for (; !d.empty(); d = d.parent_path()) {
    if (holds_all(d)) return d;
    if (d == d.parent_path()) break;
  }
  return fs::current_path();
}

}  // namespace beamimpact::verification
