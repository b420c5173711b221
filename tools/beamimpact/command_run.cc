#include "command_run.hpp"

#include <filesystem>

#include <fmt/format.h>

#include <api/registry.hpp>
#include <api/run.hpp>
#include <solver/record/FieldWriter.hpp>
#include <solver/schema/output_schema.hpp>
#include <solver/util/Progress.hpp>

namespace beamimpact {
namespace {

struct RunArgs {
  std::string scene, out, method = "paper";
  std::vector<std::string> sets;
  bool quiet = false;
  bool allow_long = false;
  bool fields = false;
};

void print_result(const SimulationResult& r, const std::string& out) {
  fmt::print("{} run: {} steps, dt = {:.6g} s (critical {:.6g} s), {:.3f} s wall\n", r.method, r.steps, r.dt,
             r.critical_dt, r.wall_seconds);
  fmt::print("  effects: {}\n", fmt::join(r.effects, ", "));
  for (const ContactSummary& c : r.contacts) {
    fmt::print("  contact {} -> {} ({}): {} impact(s), impulse {:.6g} N s", c.striker, c.target,
               to_string(c.kind), c.intervals.size(), c.impulse_normal);
    if (!c.intervals.empty()) fmt::print(", first [{:.6g}, {:.6g}] s", c.intervals[0][0], c.intervals[0][1]);
    fmt::print("\n");
  }
  fmt::print("  energy {:.6g} -> {:.6g} J\n", r.energy_initial, r.energy_final);
  if (std::filesystem::exists(std::filesystem::path(out) / "history.csv"))
    fmt::print("  wrote {}/history.csv and {}/summary.json\n", out, out);
  else
    fmt::print("  wrote {}/summary.json (no history.csv: [output] history = false)\n", out);
  if (std::filesystem::exists(FieldWriter::collection(out)))
    fmt::print("  wrote {}/fields.pvd and {}/fields/\n", out, out);
}

void simulate(const RunArgs& a) {
  Progress::set_enabled(!a.quiet);
  std::vector<std::string> sets = a.sets;
  if (a.allow_long) sets.push_back("time.allow_long_run=true");
  if (a.fields) sets.push_back("output.fields=true");
  const SimulationResult r = beamimpact::run(a.scene, a.method, RunOptions{sets, a.out});
  if (!a.quiet) print_result(r, a.out);
}

void print_methods() {
  fmt::print("{:<9} {:<10} {:<8} {:<8} {:<8} {}\n", "method", "kind", "dt", "friction", "rotation",
             "summary");
  for (const Method& m : methods())
    fmt::print("{:<9} {:<10} {:<8} {:<8} {:<8} {}\n", m.name, m.in_process() ? "in-process" : "program",
               m.accepts.dt ? "yes" : "own", m.accepts.friction ? "yes" : "no",
               m.accepts.rotation ? "yes" : "no", m.summary);
}

}  // namespace

void add_command_run(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* sub =
      app.add_subcommand("run", "Run one scene with one method; writes DIR/history.csv and DIR/summary.json");
  sub->add_option("scene", args->scene, "Scene file (TOML, see shared/spec/interface.md)")->required();
  sub->add_option("--out", args->out, "Output directory")->required();
  sub->add_option("--method", args->method,
                  "A method of the registry (`beamimpact methods`): " + method_names())
      ->capture_default_str();
  sub->add_option("--set", args->sets, "Override a scene key, e.g. --set time.dt=0.005 (repeatable)");
  sub->add_flag("--quiet", args->quiet, "Print nothing on success (no progress either)");
  sub->add_flag("--allow-long", args->allow_long,
                "Run even when the cost estimate is far beyond the ordinary (as time.allow_long_run = true)");
  sub->add_flag("--fields", args->fields,
                "Also write VTK fields for ParaView: DIR/fields.pvd and DIR/fields/*.vtu (as output.fields = true)");
  sub->callback([args] { simulate(*args); });
}

void add_command_methods(CLI::App& app) {
  app.add_subcommand("methods", "List the methods of the registry and what each accepts")
      ->callback(print_methods);
  app.add_subcommand("schema", "Print the output schema (history.csv columns, enums, units) as JSON")
      ->callback([] { fmt::print("{}\n", schema_json().dump(2)); });
}

}  // namespace beamimpact
