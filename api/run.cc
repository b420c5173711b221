#include <api/run.hpp>

#include <cstdint>

#include <fmt/format.h>

#include <api/accepts.hpp>
#include <api/external_method.hpp>
#include <api/registry.hpp>
#include <solver/record/FieldWriter.hpp>
#include <solver/record/output_files.hpp>
#include <solver/scene/Override.hpp>
#include <solver/scene/run_cost.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/OutputLock.hpp>
#include <solver/util/heap_policy.hpp>
#include <solver/util/write_file_atomic.hpp>

namespace beamimpact {
namespace {

/// The scene's warnings (legal input likely not meant) join the method's in r.extra["warnings"]:
/// summary.json lists them and `beamimpact run` prints them.
void add_scene_warnings(const Scene& scene, SimulationResult& r) {
  for (const std::string& w : scene.warnings) r.extra["warnings"].push_back(w);
}

/// Nothing of an earlier run in the directory may vouch for this one, nor survive a refusal.
void remove_run_outputs(const std::filesystem::path& out) {
  remove_stale_outputs(out, {"summary.json", "history.csv", kRejectedSummary});
  remove_stale_outputs(FieldWriter::collection(out).parent_path(), {"fields.pvd"});
}

/// The field files of the run directory `out`: a run that writes none, or failed, leaves none of
/// an earlier run's nor its own beside its summary.
void remove_fields(const std::filesystem::path& out) {
  std::error_code ec;
  std::filesystem::remove_all(out / "fields", ec);
  std::filesystem::remove(FieldWriter::collection(out), ec);
}

/// Every run passes here (its directory locked): the method's acceptance, then the in-process
/// solver (given the run's thread count, 0 when not asked) or the program.
SimulationResult run_method(const Scene& scene, const Method& m, const RunOptions& o,
                            const std::string& mesh) {
  const std::optional<std::filesystem::path>& out = o.out;
  if (out) remove_run_outputs(*out);
  check_accepts(m, scene, mesh);
  if (!m.in_process()) {
    if (!out)
      throw InputError(
          scene.file, "--out",
          "expected an output directory: the external method '" + m.name + "' writes its run there");
    SimulationResult r = run_external(m, scene, *out, mesh);
    add_scene_warnings(scene, r);
    return r;
  }
  // Before anything is allocated: refuse a run far beyond the ordinary (the estimate is printed).
  const RunCost cost = check_run_cost(scene, planned_dt(scene));
  // Asked for: the run's memory from a heap that keeps it for the next run and faults it in by
  // huge pages (the estimate is generous: what it reserves beyond the run's needs stays untouched).
  if (o.tune_heap) reserve_heap(cost.bytes);
  Method::Request request;
  request.threads = o.threads.value_or(0);
  if (scene.output.fields) {
    if (!m.writes_fields)
      throw InputError(scene.file, "output.fields",
                       "expected false for method '" + m.name + "': it writes no fields");
    if (!out)
      throw InputError(scene.file, "output.fields",
                       "expected an output directory to write the fields into (--out)");
    request.fields_dir = *out;
  }
  if (out && !scene.output.fields) remove_fields(*out);
  SimulationResult r;
  try {
    r = m.solve(scene, request);
  } catch (...) {  // a diverged or refused run: its fields vouch for nothing
    if (out && scene.output.fields) remove_fields(*out);
    throw;
  }
  add_scene_warnings(scene, r);
  if (out) write_outputs(scene, r, *out);
  return r;
}

/// Refuses a thread count outside 1..thread_limit() (the registry's), naming --threads.
void check_threads(const std::optional<int>& threads, const std::string& file) {
  if (threads && (*threads < 1 || *threads > thread_limit()))
    throw InputError(
        file, "--threads",
        fmt::format("expected a whole number of threads 1..{}, got {}", thread_limit(), *threads));
}

/// The run's step as an override of time.dt, recorded as `--set time.dt=` with 17 digits would be
/// (so that a run directory says the same whichever way the step was asked for).
Override step_override(double dt, const std::string& file) {
  if (!(dt > 0.0)) throw InputError(file, "--dt", fmt::format("expected a positive step (s), got {}", dt));
  return make_override("time.dt", toml::value<double>(dt), fmt::format("{:.17g}", dt));
}

/// The element counts of the file's bodies times `factor`, one override of bodies[i].elements each.
std::vector<Override> mesh_overrides(const Scene& file, int factor) {
  std::vector<Override> out;
  for (std::size_t i = 0; i < file.bodies.size(); ++i) {
    const std::int64_t n = std::int64_t{file.bodies[i].elements} * factor;
    out.push_back(make_override(fmt::format("bodies[{}].elements", i), toml::value<std::int64_t>(n),
                                std::to_string(n)));
  }
  return out;
}

}  // namespace

SimulationResult run(const Scene& scene, std::string_view method_name, const RunOptions& options) {
  if (!options.set.empty() || options.dt || !options.mesh.empty())
    throw InputError(scene.file, "set",
                     "expected no overrides, dt or mesh for a loaded scene; pass them to load_scene()");
  check_threads(options.threads, scene.file);
  const OutputLock lock(options.out.value_or(std::filesystem::path()));
  const Method& m = method(method_name, scene.file, "--method");
  return run_method(scene, m, options, "");
}

SimulationResult run(const std::filesystem::path& scene_file, std::string_view method_name,
                     const RunOptions& options) {
  const OutputLock lock(options.out.value_or(std::filesystem::path()));  // the only writer of the directory
  if (options.out) remove_run_outputs(*options.out);                     // before anything can refuse
  const Method& m = method(method_name, scene_file.string(), "--method");
  check_threads(options.threads, scene_file.string());
  std::vector<Override> edits = parse_overrides(options.set, scene_file.string());
  if (options.dt) edits.push_back(step_override(*options.dt, scene_file.string()));
  // An in-process method refines by element overrides (recorded in summary.json), the file's
  // element counts times the factor, applied last; an external one gets the mesh as {mesh}.
  if (!options.mesh.empty() && m.in_process() && m.accepts.mesh_factor) {
    const int f = mesh_factor(options.mesh, scene_file.string(), m.name);
    for (Override& o : mesh_overrides(load_scene(scene_file), f)) edits.push_back(std::move(o));
    return run_method(load_scene_with(scene_file, edits), m, options, "");
  }
  return run_method(load_scene_with(scene_file, edits), m, options, options.mesh);
}

}  // namespace beamimpact
