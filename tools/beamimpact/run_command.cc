#include "beamimpact/run_command.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "beamimpact/methods.hpp"
#include "io/run_output.hpp"
#include "scene/SceneError.hpp"
#include "scene/scene_io.hpp"

namespace beamimpact {
namespace {

struct RunArgs {
  std::string scene, out, method = "paper";
  std::vector<std::string> sets;
  bool quiet = false;
};

void print_result(const RunResult& r, const std::string& out) {
  fmt::print("{} run: {} steps, dt = {:.6g} s (critical {:.6g} s), {:.3f} s wall\n", r.method,
             r.steps, r.dt, r.critical_dt, r.wall_seconds);
  fmt::print("  effects: {}\n", fmt::join(r.effects, ", "));
  for (const ContactSummary& c : r.contacts) {
    fmt::print("  contact {} -> {} ({}): {} impact(s), impulse {:.6g} N s", c.striker, c.target,
               c.kind, c.intervals.size(), c.impulse_normal);
    if (!c.intervals.empty())
      fmt::print(", first [{:.6g}, {:.6g}] s", c.intervals[0][0], c.intervals[0][1]);
    fmt::print("\n");
  }
  fmt::print("  energy {:.6g} -> {:.6g} J\n", r.energy_initial, r.energy_final);
  fmt::print("  wrote {}/history.csv and {}/summary.json\n", out, out);
}

void run(const RunArgs& a) {
  const Scene scene = load_scene(a.scene, a.sets);
  const auto& table = methods();
  const auto it = table.find(a.method);
  if (it == table.end()) {
    std::string names;
    for (const auto& [n, f] : table) names += (names.empty() ? "" : ", ") + n;
    std::string hint = a.method == "fenicsx"
                           ? " (the FEniCSx reference runs as: /usr/bin/python3 references/fenicsx/run.py SCENE --out DIR)"
                           : "";
    throw SceneError(a.scene, "--method", "expected one of " + names + ", got '" + a.method + "'" + hint);
  }
  std::filesystem::remove(std::filesystem::path(a.out) / "summary.json");
  const RunResult r = it->second(scene);
  write_run(scene, r, a.out);
  if (!a.quiet) print_result(r, a.out);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* sub = app.add_subcommand("run", "Run one scene with one method; writes DIR/history.csv and DIR/summary.json");
  sub->add_option("scene", args->scene, "Scene file (TOML, see shared/spec/interface.md)")->required();
  sub->add_option("--out", args->out, "Output directory")->required();
  sub->add_option("--method", args->method, "paper (Pu & Chi 2011 explicit integrator), exact, ida")
      ->capture_default_str();
  sub->add_option("--set", args->sets, "Override a scene key, e.g. --set time.dt=0.005 (repeatable)");
  sub->add_flag("--quiet", args->quiet, "Print nothing on success");
  sub->callback([args] { run(*args); });
}

}  // namespace beamimpact
