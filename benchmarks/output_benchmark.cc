/// @file output_benchmark.cc
/// @brief What output costs on the user's path: whole in-process runs of the paper integrator
/// (beamimpact::run, the path of `beamimpact run`) on S2's geometry meshed to 1e4-1e6 DOFs, with
/// and without history rows and field files, in one run of this program. Each cost is a
/// difference of whole runs, in units of the run's own step:
///   step          (T(2N steps) - T(N steps)) / N, no rows kept (output.history = false)
///   history row   (T(history, a row every step) - T(no rows)) / N
///   field row     (T(fields every k-th step) - T(history every k-th step)) / rows, binary and ASCII
///   fields/100    the run writing binary fields every 100 steps against the same run without
///                 them, as a fraction of the run (the two runs interleaved, each the best of 5).
/// Each other T is the best of 3 runs (the machine is shared). Field files go to a temporary folder.
/// Run: build/benchmarks/output_benchmark [max_dofs]   (prints a Markdown table)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>

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
std::string scene_text(long elements, double end, int every, bool history, bool fields, const char* format) {
  const long a = std::max(1L, elements / 3), b = std::max(2L, elements - a);
  return fmt::format(
      "name = \"output_benchmark\"\n[time]\ndt = \"auto\"\nfraction = 0.9\nend = {}\noutput_every = {}\n"
      "[output]\nhistory = {}\nfields = {}\nfield_format = \"{}\"\n"
      "[[bodies]]\nname = \"A\"\nstart = [5.0, 5.1]\nend = [5.0, 0.1]\nelements = {}\nE = 100.0\nrho = 1.0\n"
      "area = 0.4\ninertia = 0.0053333333333333\nvelocity = [0.0, -1.0]\nsupports = []\n"
      "[[bodies]]\nname = \"B\"\nstart = [0.0, 0.0]\nend = [10.0, 0.0]\nelements = {}\nE = 100.0\nrho = 1.0\n"
      "area = 0.4\ninertia = 0.0053333333333333\nvelocity = [0.0, 0.5]\n"
      "supports = [{{ at = \"start\", fix = [\"x\", \"y\"] }}, {{ at = \"end\", fix = [\"y\"] }}]\n"
      "[[contacts]]\nstriker = \"A\"\nnode = \"end\"\ntarget = \"B\"\n",
      end, every, history, fields, format, a, b);
}

/// Wall time of one whole run of the scene text (seconds), and the run's result.
double timed_run(const std::string& text, const std::filesystem::path& out,
                 SimulationResult* last = nullptr) {
  const Clock::time_point t0 = Clock::now();
  const Scene scene = load_scene_text(text, "output_benchmark.toml");
  SimulationResult res = run(scene, "paper", RunOptions{{}, out});
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

/// Best wall times of `rounds` runs of each of two scene texts, interleaved (a, b, a, b, ...):
/// both see the same spells of load on a shared machine.
std::pair<double, double> best_pair(const std::string& a, const std::string& b,
                                    const std::filesystem::path& out, int rounds) {
  std::pair<double, double> best{1e300, 1e300};
  for (int r = 0; r < rounds; ++r) {
    best.first = std::min(best.first, timed_run(a, out));
    best.second = std::min(best.second, timed_run(b, out));
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const double max_dofs = argc > 1 ? std::atof(argv[1]) : 1e6;
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "beamimpact_output_benchmark";
  std::printf(
      "output_benchmark, beamimpact %s; S2 geometry meshed finely (lumped frames, linear), paper integrator "
      "through beamimpact::run; each time the best of 3 whole runs; costs in steps of the same run\n\n",
      kVersion);
  std::printf(
      "| DOFs | steps N | step (us) | history row (steps) | binary field row (steps) | ASCII field row "
      "(steps) "
      "| binary / ASCII bytes per row | fields every 100 steps (extra run time) |\n"
      "|---|---|---|---|---|---|---|---|\n");
  Progress::Silence quiet;
  for (double dofs = 1e4; dofs <= max_dofs * 1.0001; dofs *= 10) {
    const long elements = static_cast<long>(dofs / 3);
    SimulationResult probe;
    best_run(scene_text(elements, 1e-9, 1, false, false, "binary"), out, &probe);  // dt of this mesh
    const long N = dofs >= 1e6 ? 100 : 400;
    const int every = 10;
    const double end = static_cast<double>(N) * probe.dt;
    const double t_n = best_run(scene_text(elements, end, 1, false, false, "binary"), out);
    const double t_2n = best_run(scene_text(elements, 2 * end, 1, false, false, "binary"), out);
    const double step = (t_2n - t_n) / static_cast<double>(N);
    const double t_hist = best_run(scene_text(elements, end, 1, true, false, "binary"), out);
    const double t_every = best_run(scene_text(elements, end, every, true, false, "binary"), out);
    const double rows = static_cast<double>(N / every + 1);
    const double t_bin = best_run(scene_text(elements, end, every, true, true, "binary"), out);
    const auto bytes = [&] {
      return std::filesystem::file_size(out / "fields" / fmt::format("step_{:06d}.vtu", N / every));
    };
    const double bin_bytes = static_cast<double>(bytes());
    const double t_ascii = best_run(scene_text(elements, end, every, true, true, "ascii"), out);
    const double ascii_bytes = static_cast<double>(bytes());
    const auto [t_100, t_100f] = best_pair(scene_text(elements, 10 * end, 100, true, false, "binary"),
                                           scene_text(elements, 10 * end, 100, true, true, "binary"), out, 5);
    std::printf("| %.0e | %ld | %.3g | %.3g | %.3g | %.3g | %.0f / %.0f kB | %+.1f %% |\n", dofs, N,
                step * 1e6, (t_hist - t_n) / static_cast<double>(N) / step, (t_bin - t_every) / rows / step,
                (t_ascii - t_every) / rows / step, bin_bytes / 1e3, ascii_bytes / 1e3,
                100.0 * (t_100f - t_100) / t_100);
    std::fflush(stdout);
  }
  std::filesystem::remove_all(out);
  return 0;
}
