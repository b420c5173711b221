#include <verification/jobs/JobSpec.hpp>

#include <algorithm>
#include <cstdlib>

#include <fmt/format.h>

#include <api/accepts.hpp>
#include <api/methods_file.hpp>
#include <api/registry.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::jobs {
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
  return s;
}

std::string JobSpec::key() const {
  std::string k = scene_name() + "." + method;
  if (dt) k += fmt::format(".dt{:g}", *dt);
  if (!mesh.empty()) k += ".mesh" + mesh;
  for (const auto& o : set) k += "." + o;
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

void Launcher::check(const JobSpec& spec) const {
  const Method& m = method(spec.method, spec.scene.string(), "method");
  if (!spec.mesh.empty() && m.accepts.mesh_factor) (void)mesh_factor(spec.mesh, spec.scene.string(), m.name);
}

Launcher launcher_for(const std::filesystem::path& exe, int threads) {
  Launcher l;
  l.exe = exe;
  if (!exe.empty()) l.methods_files = loaded_methods_files();
  l.threads = threads;
  return l;
}

std::vector<std::string> Launcher::argv(const JobSpec& spec, const std::filesystem::path& out_dir) const {
  check(spec);
  const Method& m = method(spec.method, spec.scene.string(), "method");
  std::vector<std::string> a = {exe.string(),     "run",      spec.scene.string(), "--out",
                                out_dir.string(), "--method", spec.method,         "--quiet"};
  for (const auto& f : methods_files) a.insert(a.end(), {"--methods", f.string()});
  if (spec.dt) a.insert(a.end(), {"--dt", fmt::format("{:.17g}", *spec.dt)});
  if (!spec.mesh.empty()) a.insert(a.end(), {"--mesh", spec.mesh});
  if (threads > 0 && m.in_process()) a.insert(a.end(), {"--threads", std::to_string(threads)});
  for (const auto& s : spec.set) a.insert(a.end(), {"--set", s});
  a.insert(a.end(), {"--refusal", (out_dir / kRefusalFile).string()});
  return a;
}

RunOptions Launcher::run_options(const JobSpec& spec, const std::filesystem::path& out_dir) const {
  check(spec);
  const Method& m = method(spec.method, spec.scene.string(), "method");
  RunOptions o;
  o.set = spec.set;
  o.out = out_dir;
  o.dt = spec.dt;
  o.mesh = spec.mesh;
  if (threads > 0 && m.in_process()) o.threads = threads;
  return o;
}

}  // namespace beamimpact::jobs
