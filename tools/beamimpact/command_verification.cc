#include "command_verification.hpp"

#include "command_run.hpp"
#include "command_scenes.hpp"
#include "option_checks.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include <api/methods_file.hpp>
#include <api/registry.hpp>
#include <api/shipped_scenes.hpp>
#include <beamimpact/version.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/write_file_atomic.hpp>
#include <verification/compare/compare_runs.hpp>
#include <verification/jobs/execute_jobs.hpp>
#include <verification/jobs/interruption.hpp>
#include <verification/jobs/task_farm.hpp>
#include <verification/matrix/VerificationMatrix.hpp>
#include <verification/matrix/baseline.hpp>
#include <verification/matrix/evaluate.hpp>
#include <verification/matrix/reports.hpp>
#include <verification/matrix/sweep.hpp>
#include <verification/matrix/verify.hpp>
#include "CommandExit.hpp"
#include "methods_option.hpp"
#include "output_lock.hpp"

namespace beamimpact {
namespace {

namespace fs = std::filesystem;
using namespace verification;

struct CompareArgs {
  std::string a, b, json;
  CompareOptions options;
};

}  // namespace

void add_isolate_flag(CLI::App* sub, std::filesystem::path& exe) {
  sub->add_flag_callback(
      "--isolate", [&exe] { exe = program_path(); },
      "Run each case as its own `beamimpact run` process (a crash or a hang ends only that run); default: "
      "in this process (an outside method's program is its own process either way)");
}

namespace {

void compare(const CompareArgs& a) {
  fs::path json = a.json.empty() ? fs::path(a.a) / "compare.json" : fs::path(a.json);
  if (std::error_code ec; fs::is_directory(json, ec)) json /= "compare.json";  // --json DIR
  const OutputLock lock = lock_output(json.has_parent_path() ? json.parent_path() : fs::path("."));
  const StoredRun run = StoredRun::read(a.a), reference = StoredRun::read(a.b);
  const Comparison c = compare_runs(run.view(), reference.view(), a.options);
  fmt::print("{}", c.to_text());
  write_file_atomic(json, c.to_json().dump(1) + "\n");
  fmt::print("wrote {}\n", json.string());
}

/// The verdict lines of a result: failing gates, counts, where the reports are, the baseline.
void print_verify(const VerifyOptions& o, const VerifyResult& r, const fs::path& baseline_written) {
  for (const auto& i : r.items)
    for (const auto& g : i.gates)
      if (g.status == GateStatus::kFail) fmt::print("FAIL {}: {} ({})\n", i.name, g.gate.metric, g.message);
  const GateCounts n = count_gates(r.items);
  fmt::print("verify {}: {} gates, {} passed, {} failed, {} skipped, {:.1f} s\nreport: {}\n",
             r.gates_passed() ? "passed" : "FAILED", n.gates, n.pass, n.fail, n.skipped,
             r.context.wall_seconds, (o.out / "report.md").string());
  fmt::print("junit: {}\nnorms: {}\n", (o.out / "junit.xml").string(), (o.out / "norms.json").string());
  if (r.baseline) fmt::print("{}", r.baseline->to_text());
  if (r.baseline && !r.update_baseline && !r.baseline->passed())
    fmt::print("baseline FAILED: {} gate(s) worse than in {}\n", r.baseline->worse.size(),
               r.baseline_file.string());
  if (!baseline_written.empty()) fmt::print("baseline: wrote {}\n", baseline_written.string());
  if (r.update_baseline && !r.gates_passed())
    fmt::print(stderr, "baseline: {} not updated: this verification failed\n", r.baseline_file.string());
}

void verify_command(VerifyOptions o) {
  const OutputLock lock = lock_output(o.out);  // before the earlier reports are removed
  jobs::forward_interruptions();
  o.matrix = resolve_data_file(o.matrix.string());  // verification/matrix.toml from any folder
  o.quiet = jobs::World::rank() != 0;
  const auto result = verification::verify(o);
  if (!result) return;  // an MPI worker rank: rank 0 evaluates and writes the reports
  print_verify(o, *result, write_verify_reports(o, *result));
  if (jobs::interruption()) {
    fmt::print(stderr, "verify: interrupted (signal {}): the report is marked incomplete\n",
               jobs::interruption());
    throw CommandExit{jobs::interrupted_exit_code()};
  }
  if (!result->passed()) throw CommandExit{1};
}

void sweep_command(SweepOptions o) {
  const OutputLock lock = lock_output(o.out);  // before the earlier tables are removed
  jobs::forward_interruptions();
  const auto ran = verification::sweep(o);
  if (!ran) return;  // an MPI worker rank: rank 0 compares and writes the outputs
  const SweepResult& r = *ran;
  write_sweep(o, r);
  for (const auto& p : r.points) {
    const auto& s = p.outcome.spec;
    fmt::print("{:<28} {:>8} steps {:>9.4f} s", s.settings_label(), p.outcome.steps,
               p.outcome.solver_seconds);
    if (p.comparison) {
      for (const char* n : {"impulse", "I.rel_linf", "ua.rel_l2"}) {
        const Norm* x = p.comparison->find(n);
        fmt::print("  {} {}", n, x && x->value ? fmt::format("{:.3e}", *x->value) : "n/a");
      }
    } else {
      fmt::print("  {}: {}", to_string(p.outcome.status), p.outcome.message);
    }
    fmt::print("\n");
  }
  fmt::print("errors against {}\nreport: {}\n", r.reference_label, (o.out / "sweep.md").string());
  if (jobs::interruption()) {
    fmt::print(stderr, "sweep: interrupted (signal {}): the report is marked incomplete\n",
               jobs::interruption());
    throw CommandExit{jobs::interrupted_exit_code()};
  }
}

}  // namespace

namespace {

/// `verify`: its options, --baseline and --update-baseline among them.
void add_verify_command(CLI::App& app) {
  auto va = std::make_shared<VerifyOptions>();
  CLI::App* v = app.add_subcommand("verify", "Run the verification matrix; exit 1 if any gate fails");
  v->add_option("MATRIX", va->matrix,
                "VerificationMatrix file; a relative path missing here is looked for under the data root "
                "(the repository or the installed share/beamimpact)")
      ->capture_default_str();
  v->add_option("--out", va->out, "Output directory (runs/, junit.xml, norms.json, report.md)")->required();
  v->add_option("--tier", va->tier,
                "quick (CI), stability (health checks of the hard cases) or full (everything, plus fine "
                "meshes and small dt)")
      ->check(CLI::IsMember(VerificationMatrix::tier_names()))
      ->capture_default_str();
  v->add_option("--jobs", va->jobs, "Runs in parallel")->capture_default_str()->check(job_count());
  v->add_option("--only", va->only, "Only cases whose name contains this text (e.g. s1_central)");
  v->add_flag("--fresh", va->fresh,
              "Run everything again (default: the runs an interrupted verify finished in OUT/runs, with the "
              "same version, scene and settings, are taken as they are)");
  add_threads_option(v, va->threads,
                     "Threads of each run of the paper integrator (as run --threads; default: each run's)");
  add_isolate_flag(v, va->exe);
  CLI::Option* baseline = v->add_option(
      "--baseline", va->baseline,
      "A baseline (an earlier --update-baseline, or a norms.json): exit 1 when a gated value got worse "
      "than in it by more than max(1 % of it, 1e-9); better ones are listed (docs/ci.md)");
  v->add_flag("--update-baseline", va->update_baseline,
              "Write the --baseline file from this run (when it passes) instead of holding the run to it")
      ->needs(baseline);
  add_methods_option(v);
  v->callback([va] { verify_command(*va); });
}

}  // namespace

void add_verification_commands(CLI::App& app) {
  auto ca = std::make_shared<CompareArgs>();
  CLI::App* c = app.add_subcommand(
      "compare", "Error norms of run DIR_1 against reference run DIR_2 (each norm's definition is printed)");
  c->add_option("DIR_1", ca->a, "Run directory (history.csv, summary.json)")->required();
  c->add_option("DIR_2", ca->b, "Reference run directory")->required();
  c->add_option("--json", ca->json,
                "Write the norms as JSON to this file, or to compare.json in this directory (default "
                "DIR_1/compare.json)");
  const CLI::Validator positive_time(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end != text.c_str() && *end == '\0' && v > 0.0 && std::isfinite(v)) return {};
        return "expected a positive finite time (s), got '" + text.substr(0, 80) + "'";
      },
      "TIME>0");
  c->add_option("--window", ca->options.window, "s, force averaging window (default 10 coarser output steps)")
      ->check(positive_time);
  c->add_option("--grid", ca->options.grid_step, "s, common grid step (default the finer output step)")
      ->check(positive_time);
  c->add_option("--merge", ca->options.merge_gap,
                "s, contact samples closer than this are one impact (default 3.5 coarser output steps)")
      ->check(positive_time);
  c->add_option("--threshold", ca->options.threshold,
                "fraction of the reference's largest R above which a sample counts as contact (default 1e-6)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end != text.c_str() && *end == '\0' && v >= 0.0 && v < 1.0) return {};
            return "expected a fraction of the reference's largest R in [0, 1), got '" + text.substr(0, 80) +
                   "'";
          },
          "FRACTION"));
  add_methods_option(c);
  c->callback([ca] { compare(*ca); });

  add_verify_command(app);

  auto sa = std::make_shared<SweepOptions>();
  CLI::App* s =
      app.add_subcommand("sweep", "Error norms and wall time of one scene at several dt (and meshes)");
  s->add_option("SCENE", sa->scene, "Scene file or a shipped scene's name (`beamimpact scenes`)")
      ->required()
      ->transform(scene_argument());
  auto* dt = s->add_option("--dt", sa->dts, "s, time steps, e.g. 0.01,0.005,0.0025")->delimiter(',');
  auto* fr = s->add_option("--fraction", sa->fractions,
                           "fractions of the critical step, for scenes with dt = \"auto\" (e.g. 0.5,0.25)")
                 ->delimiter(',');
  dt->excludes(fr);
  s->add_option("--mesh", sa->meshes, "Element multipliers (beam methods), e.g. 1,2,4")->delimiter(',');
  s->add_option("--method", sa->method, "Method under test")->capture_default_str();
  s->add_option("--reference", sa->reference,
                "self (the method at the finest dt/4 on the finest mesh), a method name (" + method_names() +
                    "), or a run directory")
      ->capture_default_str();
  s->add_option("--out", sa->out, "Output directory (runs/, sweep.md, sweep.csv, sweep.json)")->required();
  s->add_option("--jobs", sa->jobs, "Runs in parallel")->capture_default_str()->check(job_count());
  add_threads_option(s, sa->threads,
                     "Threads of each run of the paper integrator (as run --threads; default: each run's)");
  add_isolate_flag(s, sa->exe);
  add_methods_option(s);
  s->callback([sa] { sweep_command(*sa); });
}

}  // namespace beamimpact
