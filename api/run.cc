#include <api/run.hpp>

#include <api/registry.hpp>
#include <solver/record/FieldWriter.hpp>
#include <solver/record/output_files.hpp>
#include <solver/scene/SceneError.hpp>
#include <solver/scene/run_cost.hpp>
#include <solver/scene/scene_io.hpp>

namespace beamimpact {

SimulationResult run(const Scene& scene, std::string_view method_name, const RunOptions& options) {
  if (!options.set.empty())
    throw SceneError(scene.file, "set",
                     "expected no overrides for a loaded scene; pass them to load_scene()");
  const Method& m = method(method_name, scene.file, "--method");
  if (!m.in_process())
    throw SceneError(scene.file, "--method",
                     "'" + m.name + "' is an external program, not callable in-process; it runs as: " +
                         m.command.front() + " " + m.command.back() + " SCENE --out DIR");
  if (options.out) {  // nothing of an earlier run in the directory may vouch for this one
    std::filesystem::remove(*options.out / "summary.json");
    std::filesystem::remove(FieldWriter::collection(*options.out));
  }
  // Before anything is allocated: refuse a run far beyond the ordinary (the estimate is printed).
  check_run_cost(scene, planned_dt(scene));
  SimulationResult r;
  if (scene.output.fields) {
    if (!m.solve_with_fields)
      throw SceneError(scene.file, "output.fields",
                       "expected false for method '" + m.name +
                           "': fields are written by the methods paper and fenicsx");
    if (!options.out)
      throw SceneError(scene.file, "output.fields",
                       "expected an output directory to write the fields into (--out)");
    r = m.solve_with_fields(scene, *options.out);
  } else {
    r = m.solve(scene);
  }
  if (options.out) write_outputs(scene, r, *options.out);
  return r;
}

SimulationResult run(const std::filesystem::path& scene_file, std::string_view method_name,
                     const RunOptions& options) {
  const Scene scene = load_scene(scene_file, options.set);
  return run(scene, method_name, RunOptions{{}, options.out});
}

}  // namespace beamimpact
