#include "command_model.hpp"
#include "command_scenes.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <api/model_export.hpp>
#include <solver/scene/run_cost.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/OutputLock.hpp>
#include <verification/jobs/JobSpec.hpp>

namespace beamimpact {
namespace {

struct ModelArgs {
  std::string scene, out;
  std::vector<std::string> sets;
  int mesh_factor = 1;
  bool quiet = false;
};

void export_scene(const ModelArgs& a) {
  {  // a refused export leaves no earlier one's model.json to vouch for it
    const OutputLock lock(a.out);
    std::filesystem::remove(std::filesystem::path(a.out) / "model.json");
  }
  if (a.mesh_factor < 1 || a.mesh_factor > 1000)
    throw InputError(a.scene, "--mesh-factor",
                     "expected an element multiplier 1..1000, got " + std::to_string(a.mesh_factor));
  std::vector<std::string> sets;
  if (a.mesh_factor != 1) sets = jobs::mesh_overrides(a.scene, a.mesh_factor);
  sets.insert(sets.end(), a.sets.begin(), a.sets.end());  // an explicit --set wins
  const Scene scene = load_scene(a.scene, sets);
  check_model_cost(scene);  // as `run` refuses it, before anything is allocated
  const nlohmann::json doc = export_model(scene, a.out);
  if (a.quiet) return;
  fmt::print("model of {}: {} layout, {} equations, {} contact(s), dt {:.6g} s, end {:.6g} s\n",
             doc["scene"].get<std::string>(), doc["layout"].get<std::string>(), doc["equations"].get<int>(),
             doc["contacts"].size(), doc["time"]["dt"].get<double>(), doc["time"]["end"].get<double>());
  fmt::print(
      "  wrote {}/model.json (describes M.mtx, K.mtx, C.mtx, dofs.csv, initial_state.csv, load.csv, "
      "momentum.csv)\n",
      a.out);
}

}  // namespace

void add_command_model(CLI::App& app) {
  auto args = std::make_shared<ModelArgs>();
  CLI::App* sub = app.add_subcommand(
      "model",
      "Export the scene's semi-discrete model (M, K, C, DOF map, initial state, contact rows) to DIR");
  sub->add_option("scene", args->scene, "Scene file (TOML) or a shipped scene's name (`beamimpact scenes`)")
      ->required()
      ->transform(scene_argument());
  sub->add_option("--out", args->out, "Output directory (model.json is written last)")->required();
  sub->add_option("--set", args->sets, "Override a scene key, e.g. --set bodies.A.elements=100 (repeatable)");
  sub->add_option("--mesh-factor", args->mesh_factor,
                  "Multiply every body's elements by this (1..1000), as the matrix's mesh factor does")
      ->capture_default_str();
  sub->add_flag("--quiet", args->quiet, "Print nothing on success");
  sub->callback([args] { export_scene(*args); });
}

}  // namespace beamimpact
