#include "command_run.hpp"
#include "command_scenes.hpp"
#include "methods_option.hpp"

#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <api/registry.hpp>
#include <api/run.hpp>
#include <solver/record/FieldWriter.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/Progress.hpp>
#include <solver/util/write_file_atomic.hpp>

namespace beamimpact {
namespace {

struct RunArgs {
  std::string scene, out, method = "paper", mesh;
  double dt = 0.0;  // s, 0: the scene's
  int threads = 0;  // 0: the default (RunOptions::threads)
  std::vector<std::string> sets;
  bool quiet = false;
  bool allow_long = false;
  bool fields = false;
  std::string refusal;  // "" none
};

/// Writes a refusal (the InputError) to `file` as JSON {file, key, message}, for the job
/// executor that started this run (verification/jobs/run_job.hpp); a file that cannot be written
/// leaves the exit code 2 to say it.
void write_refusal(const std::string& file, const InputError& e) {
  try {
    write_file_atomic(
        file, nlohmann::json{{"file", e.file()}, {"key", e.key()}, {"message", e.what()}}.dump() + "\n");
  } catch (const std::exception&) {
  }
}

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
  if (r.extra.contains("loads") && r.extra["loads"].contains("work_final"))  // the loads' work fed it
    fmt::print("  energy {:.6g} -> {:.6g} J, the loads' work {:.6g} J\n", r.energy_initial, r.energy_final,
               r.extra["loads"]["work_final"].get<double>());
  else
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
  RunOptions o{sets, a.out, std::nullopt, a.mesh};
  if (a.dt != 0.0) o.dt = a.dt;
  if (a.threads != 0) o.threads = a.threads;
  o.tune_heap = true;  // this process runs one scene: the heap policy pays (docs/performance.md)
  SimulationResult r;
  try {
    r = beamimpact::run(a.scene, a.method, o);
  } catch (const InputError& e) {
    if (!a.refusal.empty()) write_refusal(a.refusal, e);
    throw;
  }
  if (!a.quiet) print_result(r, a.out);
  if (const auto w = r.extra.find("warnings"); w != r.extra.end())  // also when quiet: on stderr
    for (const auto& text : *w) fmt::print(stderr, "warning: {}\n", text.get<std::string>());
}

/// --threads: a whole number 1..thread_limit() (the registry's), checked before conversion so
/// that every bad value gets the same message naming the option (exit 2).
CLI::Validator threads_validator() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        char* end = nullptr;
        const long n = std::strtol(v.c_str(), &end, 10);
        if (v.empty() || *end != '\0' || n < 1 || n > thread_limit())
          return fmt::format("expected a whole number of threads 1..{}, got '{}'", thread_limit(), v);
        return {};
      },
      fmt::format("1..{}", thread_limit()));
}

}  // namespace

void add_command_run(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* sub =
      app.add_subcommand("run", "Run one scene with one method; writes DIR/history.csv and DIR/summary.json");
  sub->add_option(
         "scene", args->scene,
         "Scene file (TOML, see docs/scene-format.md), or a shipped scene's name (`beamimpact scenes`)")
      ->required()
      ->transform(scene_argument());
  sub->add_option("--out", args->out, "Output directory")->required();
  sub->add_option("--method", args->method,
                  "A method of the registry (`beamimpact methods`): " + method_names())
      ->capture_default_str();
  sub->add_option("--dt", args->dt,
                  "s, the time step (as --set time.dt=...; refused by a method that picks its own)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--mesh", args->mesh,
                  "Mesh: an element multiplier (1..64) for the beam methods, or an external method's preset");
  add_threads_option(
      sub, args->threads,
      fmt::format("Threads of the paper integrator's step (1..{}; as --set paper.threads=N); default: the "
                  "machine's, 1 for small models. The results are the same bits at any count",
                  thread_limit()));
  add_methods_option(sub);
  sub->add_option("--set", args->sets, "Override a scene key, e.g. --set time.dt=0.005 (repeatable)");
  sub->add_flag("--quiet", args->quiet, "Print nothing on success (no progress either)");
  sub->add_option("--refusal", args->refusal,
                  "When the run is refused (exit 2), also write the refusal to this file as JSON {file, key, "
                  "message} (for programs that start runs)");
  sub->add_flag("--allow-long", args->allow_long,
                "Run even when the cost estimate is far beyond the ordinary (as time.allow_long_run = true)");
  sub->add_flag(
      "--fields", args->fields,
      "Also write VTK fields for ParaView: DIR/fields.pvd and DIR/fields/*.vtu (as output.fields = true)");
  sub->callback([args] { simulate(*args); });
}

void add_threads_option(CLI::App* sub, int& threads, const std::string& help) {
  sub->add_option("--threads", threads, help)->check(threads_validator());
}

}  // namespace beamimpact
