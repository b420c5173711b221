#include "verification/matrix/RunSpec.hpp"

#include <algorithm>
#include <cstdlib>

#include <fmt/format.h>

#include "scene/SceneError.hpp"
#include "scene/scene_io.hpp"
#include "verification/matrix/subprocess.hpp"

namespace beamimpact {
namespace {

std::string safe(std::string s) {
  for (char& c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')) c = '_';
  return s;
}

int mesh_factor(const RunSpec& s) {
  char* end = nullptr;
  const long m = std::strtol(s.mesh.c_str(), &end, 10);
  if (end == s.mesh.c_str() || *end != '\0' || m < 1 || m > 64) {
    throw SceneError(s.scene.string(), "mesh", "expected an element multiplier 1..64 for method '" + s.method +
                                                   "', got '" + s.mesh + "'");
  }
  return static_cast<int>(m);
}

}  // namespace

std::string RunSpec::scene_name() const { return scene.stem().string(); }

std::string RunSpec::settings_label() const {
  std::string s = method;
  if (dt) s += fmt::format(" dt={:g}", *dt);
  if (!mesh.empty()) s += " mesh=" + mesh;
  for (const auto& o : set) s += " " + o;
  for (const auto& a : args) s += " " + a;
  return s;
}

std::string RunSpec::key() const {
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

std::string Launcher::unavailable(const RunSpec& spec) const {
  if (spec.method == "fenicsx") {
    if (!fenicsx_reason_) {
      if (fenicsx.size() < 2) fenicsx_reason_ = "no FEniCSx command configured";
      else if (!std::filesystem::exists(fenicsx[0])) fenicsx_reason_ = "interpreter " + fenicsx[0] + " not found";
      else if (!std::filesystem::exists(fenicsx[1])) fenicsx_reason_ = "script " + fenicsx[1] + " not found";
      else {
        const auto r = run_process({fenicsx[0], "-c", "import dolfinx"}, "/dev/null", 120.0);
        fenicsx_reason_ = r.exit_code == 0 ? "" : "'" + fenicsx[0] + " -c \"import dolfinx\"' failed: dolfinx not installed";
      }
    }
    return *fenicsx_reason_;
  }
  if (std::find(builtin_methods.begin(), builtin_methods.end(), spec.method) == builtin_methods.end())
    return "method '" + spec.method + "' is not built into " + exe.filename().string();
  return "";
}

std::vector<std::string> Launcher::argv(const RunSpec& spec, const std::filesystem::path& out_dir) const {
  std::vector<std::string> a;
  if (spec.method == "fenicsx") {
    if (spec.dt || !spec.set.empty()) {
      throw SceneError(spec.scene.string(), "dt/set", "the FEniCSx reference takes no dt or --set overrides; "
                                                      "use args = [\"--fraction\", ...] or [\"--end\", ...]");
    }
    a = fenicsx;
    a.insert(a.end(), {spec.scene.string(), "--out", out_dir.string(), "--quiet"});
    if (!spec.mesh.empty()) a.insert(a.end(), {"--mesh", spec.mesh});
    a.insert(a.end(), spec.args.begin(), spec.args.end());
    return a;
  }
  a = {exe.string(), "run", spec.scene.string(), "--out", out_dir.string(), "--method", spec.method, "--quiet"};
  std::vector<std::string> sets = spec.set;
  if (spec.dt) sets.push_back(fmt::format("time.dt={:.17g}", *spec.dt));
  if (!spec.mesh.empty()) {
    const auto m = mesh_overrides(spec.scene, mesh_factor(spec));
    sets.insert(sets.end(), m.begin(), m.end());
  }
  for (const auto& s : sets) a.insert(a.end(), {"--set", s});
  a.insert(a.end(), spec.args.begin(), spec.args.end());
  return a;
}

}  // namespace beamimpact
