#include "command_study.hpp"

#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include <verification/study/run_study.hpp>

#include "methods_option.hpp"
#include "output_lock.hpp"

namespace beamimpact {
namespace {

void study_command(const study::StudyOptions& o) {
  const OutputLock lock = lock_output(o.out);
  const auto r = study::run_study(o);
  if (!r) return;  // an MPI worker rank: rank 0 writes the table
  const study::StudyCounts n = study::write_study_reports(o, *r);
  fmt::print("study {}: {} case(s) in {:.1f} s on {} rank(s) ({:.2f} cases/s), {} where the method broke\n",
             r->study.name, n.cases, r->wall_seconds, r->ranks, n.cases_per_second, n.broken);
  fmt::print("table: {} {}\nreport: {}\ntiming: {}\n", (o.out / "study.csv").string(),
             (o.out / "study.json").string(), (o.out / "study.md").string(),
             (o.out / "timing.json").string());
}

}  // namespace

void add_command_study(CLI::App& app) {
  auto a = std::make_shared<study::StudyOptions>();
  CLI::App* c = app.add_subcommand(
      "study",
      "Parameter study: a scene over a grid or Latin hypercube of parameters, each point compared with its "
      "reference (mpirun -n N spreads the points over N ranks)");
  c->add_option("STUDY", a->file, "Study file (TOML, verification/studies/)")->required();
  c->add_option("--out", a->out, "Output directory (study.csv, study.json, study.md, timing.*)")->required();
  c->add_flag("--keep-runs", a->keep_runs, "Keep every run's history.csv and summary.json under OUT/runs");
  c->add_flag("--fresh", a->fresh,
              "Run every point again (default: the points an interrupted study finished, recorded in "
              "OUT/points with the same version, study and scene files, are taken as they are)");
  add_methods_option(c);
  c->callback([a] { study_command(*a); });
}

}  // namespace beamimpact
