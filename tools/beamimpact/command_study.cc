#include "command_study.hpp"

#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include <beamimpact/version.hpp>
#include <solver/util/write_file_atomic.hpp>
#include <verification/study/run_study.hpp>

#include "methods_option.hpp"
#include "output_lock.hpp"

namespace beamimpact {
namespace {

struct StudyArgs {
  std::string file, out;
  bool keep_runs = false;
  bool fresh = false;
};

void study_command(const StudyArgs& a) {
  const OutputLock lock = lock_output(a.out);
  remove_stale_outputs(a.out, {"study.csv", "study.json", "study.md", "timing.csv", "timing.json"});
  study::Study s = study::Study::load(a.file);
  s.keep_runs = s.keep_runs || a.keep_runs;
  const auto r = study::execute_study(s, a.out, a.fresh);
  if (!r) return;  // an MPI worker rank: rank 0 writes the table
  const std::string command =
      fmt::format("beamimpact study {} --out {}{}", a.file, a.out, a.keep_runs ? " --keep-runs" : "");
  const study::StudyCounts n = study::write_study(s, *r, a.out, command, kVersion);
  const auto out = std::filesystem::path(a.out);
  fmt::print("study {}: {} case(s) in {:.1f} s on {} rank(s) ({:.2f} cases/s), {} where the method broke\n",
             s.name, n.cases, r->wall_seconds, r->ranks, n.cases_per_second, n.broken);
  fmt::print("table: {} {}\nreport: {}\ntiming: {}\n", (out / "study.csv").string(),
             (out / "study.json").string(), (out / "study.md").string(), (out / "timing.json").string());
}

}  // namespace

void add_command_study(CLI::App& app) {
  auto a = std::make_shared<StudyArgs>();
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
