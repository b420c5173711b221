#include <verification/matrix/JobSpec.hpp>

#include <algorithm>
#include <cstdlib>

#include <fmt/format.h>

#include <api/accepts.hpp>
#include <api/registry.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::verification {
namespace {

std::string safe(std::string s) {
  for (char& c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')) c = '_';
  return s;
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

std::string Launcher::unavailable(const JobSpec& spec) const {
  const Method* m = find_method(spec.method);
  if (!m) return "method '" + spec.method + "' is not in the registry (" + method_names() + ")";
  return beamimpact::unavailable(*m);
}

std::vector<std::string> Launcher::argv(const JobSpec& spec, const std::filesystem::path& out_dir) const {
  const Method& m = method(spec.method, spec.scene.string(), "method");
  if (!spec.mesh.empty() && m.accepts.mesh_factor) (void)mesh_factor(spec.mesh, spec.scene.string(), m.name);
  std::vector<std::string> a = {exe.string(),     "run",      spec.scene.string(), "--out",
                                out_dir.string(), "--method", spec.method,         "--quiet"};
  for (const auto& f : methods_files) a.insert(a.end(), {"--methods", f.string()});
  if (spec.dt) a.insert(a.end(), {"--dt", fmt::format("{:.17g}", *spec.dt)});
  if (!spec.mesh.empty()) a.insert(a.end(), {"--mesh", spec.mesh});
  if (threads > 0 && m.in_process()) a.insert(a.end(), {"--threads", std::to_string(threads)});
  for (const auto& s : spec.set) a.insert(a.end(), {"--set", s});
  a.insert(a.end(), spec.args.begin(), spec.args.end());
  return a;
}

}  // namespace beamimpact::verification
