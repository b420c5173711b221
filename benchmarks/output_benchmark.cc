/// @file output_benchmark.cc
/// @brief What output costs on the user's path: whole in-process runs of the paper integrator
/// (beamimpact::run, the path of `beamimpact run`) on S2's geometry meshed to 1e4-1e6 DOFs, with
/// and without history rows and field files, in one run of this program. Each cost is a
/// difference of whole runs, in units of the run's own step:
///   step          (T(10N steps) - T(N steps)) / 9N, a history row every 100 steps, no fields (the
///                 10N-step time the best of the interleaved runs below: short runs alone gave a
///                 step up to 3x too long, their set-up and first touches not amortized)
///   history row   (T(history, a row every step) - T(no rows)) / N
///   field row     (T(fields every k-th step) - T(history every k-th step)) / rows, in ms and in
///                 steps: binary in single precision (the default) and in double, ASCII in single
///   fields/100    the run writing binary fields every 100 steps (single, then double precision)
///                 against the same run without them, as a fraction of the run (the runs
///                 interleaved, each the best of 9: on a shared machine a difference of a few
///                 per cent between runs of a second needs many).
/// Each other T is the best of 3 runs (the machine is shared). Each run writes into an empty
/// temporary folder, the files of the runs before it removed and written back to disk (sync)
/// before its clock starts.
/// Run: build/benchmarks/output_benchmark [max_dofs]   (prints a Markdown table)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>

#include <api/run.hpp>
#include <beamimpact/version.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/Progress.hpp>

namespace {

using namespace beamimpact;
using Clock = std::chrono::steady_clock;

/// S2's bodies (A: 5 m striker 0.1 m above B's midspan, B: 10 m simply supported beam), meshed
/// with `elements` in all (A a third), dt at 0.9 of the proven critical step. B starts moving up
/// at 0.5 m/s between its supports, so that every node carries non-zero values from the first
/// step (field files of zeros would flatter ASCII).
std::string scene_text(long elements, double end, int every, bool history, bool fields, const char* format,
                       const char* precision = "single") {
  const long a = std::max(1L, elements / 3), b = std::max(2L, elements - a);
  return fmt::format(
      "name = \"output_benchmark\"\n[time]\ndt = \"auto\"\nfraction = 0.9\nend = {}\noutput_every = {}\n"
      "[output]\nhistory = {}\nfields = {}\nfield_format = \"{}\"\nfield_precision = \"{}\"\n"
      "[[bodies]]\nname = \"A\"\nstart = [5.0, 5.1]\nend = [5.0, 0.1]\nelements = {}\nE = 100.0\nrho = 1.0\n"
      "area = 0.4\ninertia = 0.0053333333333333\nvelocity = [0.0, -1.0]\nsupports = []\n"
      "[[bodies]]\nname = \"B\"\nstart = [0.0, 0.0]\nend = [10.0, 0.0]\nelements = {}\nE = 100.0\nrho = 1.0\n"
      "area = 0.4\ninertia = 0.0053333333333333\nvelocity = [0.0, 0.5]\n"
      "supports = [{{ at = \"start\", fix = [\"x\", \"y\"] }}, {{ at = \"end\", fix = [\"y\"] }}]\n"
      "[[contacts]]\nstriker = \"A\"\nnode = \"end\"\ntarget = \"B\"\n",
      end, every, history, fields, format, precision, a, b);
}

/// Wall time of one whole run of the scene text (seconds), and the run's result.
double timed_run(const std::string& text, const std::filesystem::path& out,
                 SimulationResult* last = nullptr) {
  // Into an empty folder, the earlier runs' files on disk: their removal and the kernel writing
  // them back would otherwise fall into this run's time (a user's run meets neither).
  std::filesystem::remove_all(out);
  ::sync();
  const Clock::time_point t0 = Clock::now();
  const Scene scene = load_scene_text(text, "output_benchmark.toml");
  RunOptions options{{}, out};
  options.tune_heap = true;  // as `beamimpact run`
  SimulationResult res = run(scene, "paper", options);
  const double t = std::chrono::duration<double>(Clock::now() - t0).count();
  if (last) *last = std::move(res);
  return t;
}

/// Best wall time of 3 whole runs of the scene text (seconds), and the run's result.
double best_run(const std::string& text, const std::filesystem::path& out, SimulationResult* last = nullptr) {
  double best = 1e300;
  for (int r = 0; r < 3; ++r) best = std::min(best, timed_run(text, out, last));
  return best;
}

/// Best wall time of `rounds` runs of each scene text, interleaved (a, b, c, a, b, c, ...): all
/// see the same spells of load on a shared machine.
std::vector<double> best_interleaved(const std::vector<std::string>& texts, const std::filesystem::path& out,
                                     int rounds) {
  std::vector<double> best(texts.size(), 1e300);
  for (int r = 0; r < rounds; ++r)
    for (std::size_t k = 0; k < texts.size(); ++k) best[k] = std::min(best[k], timed_run(texts[k], out));
  return best;
}

/// Size in bytes of the field file of row `row` of the last run into `out`.
double row_bytes(const std::filesystem::path& out, long row) {
  return static_cast<double>(
      std::filesystem::file_size(out / "fields" / fmt::format("step_{:06d}.vtu", row)));
}

/// Measures one size and prints its table row (see the file comment).
void measure(double dofs, const std::filesystem::path& out) {
  const long elements = static_cast<long>(dofs / 3);
  SimulationResult probe;
  best_run(scene_text(elements, 1e-9, 1, false, false, "binary"), out, &probe);  // dt of this mesh
  const long N = dofs >= 1e6 ? 100 : 400;
  const int every = 10;
  const double end = static_cast<double>(N) * probe.dt;
  const std::vector<double> t_100 =
      best_interleaved({scene_text(elements, 10 * end, 100, true, false, "binary"),
                        scene_text(elements, 10 * end, 100, true, true, "binary", "single"),
                        scene_text(elements, 10 * end, 100, true, true, "binary", "double")},
                       out, 9);
  const double t_n100 = best_run(scene_text(elements, end, 100, true, false, "binary"), out);
  const double step = (t_100[0] - t_n100) / (9.0 * static_cast<double>(N));
  const double t_n = best_run(scene_text(elements, end, 1, false, false, "binary"), out);
  const double t_hist = best_run(scene_text(elements, end, 1, true, false, "binary"), out);
  const double t_every = best_run(scene_text(elements, end, every, true, false, "binary"), out);
  const double rows = static_cast<double>(N / every + 1);
  // Per field row: ms and steps, and the bytes of the last row's file.
  std::string cost, bytes;
  for (const auto& [format, precision] :
       {std::pair{"binary", "single"}, {"binary", "double"}, {"ascii", "single"}}) {
    const double row =
        (best_run(scene_text(elements, end, every, true, true, format, precision), out) - t_every) / rows;
    cost += fmt::format(" {:.3g} ms ({:.3g}) |", row * 1e3, row / step);
    bytes += fmt::format("{}{:.0f}", bytes.empty() ? "" : " / ", row_bytes(out, N / every) / 1e3);
  }
  std::printf("| %.0e | %ld | %.3g | %.3g |%s %s kB | %+.1f %% | %+.1f %% |\n", dofs, N, step * 1e6,
              (t_hist - t_n) / static_cast<double>(N) / step, cost.c_str(), bytes.c_str(),
              100.0 * (t_100[1] - t_100[0]) / t_100[0], 100.0 * (t_100[2] - t_100[0]) / t_100[0]);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const double max_dofs = argc > 1 ? std::atof(argv[1]) : 1e6;
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "beamimpact_output_benchmark";
  std::printf(
      "output_benchmark, beamimpact %s; S2 geometry meshed finely (lumped frames, linear), paper integrator "
      "through beamimpact::run; each time the best of 3 whole runs; field rows in ms and (in brackets) in "
      "steps of the same run\n\n",
      kVersion);
  std::printf(
      "| DOFs | steps N | step (us) | history row (steps) | binary field row, single | binary field row, "
      "double "
      "| ASCII field row, single | bytes per row: binary single / double / ASCII | fields every 100 steps, "
      "single (extra run time) | the same, double |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n");
  Progress::Silence quiet;
  for (double dofs = 1e4; dofs <= max_dofs * 1.0001; dofs *= 10) measure(dofs, out);
  std::filesystem::remove_all(out);
  return 0;
}
