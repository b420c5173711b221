/// @file setup_benchmark.cc
/// @brief The set-up on the user's path in steps of the same run: everything beamimpact::run does
/// from the scene in memory to the first step (model, critical step, integrator, contact pairs,
/// deformed-surface trackers, recorder, first history row), on rods (S1 meshed: two free rods,
/// axial only) and frames (S2 meshed: a striker frame on a simply supported frame), 1e3-1e6 DOFs.
///   step     (T(2N steps) - T(N steps)) / N, whole runs through beamimpact::run in this process
///   warm     T(1 step) - step, best of repeated 1-step runs in this process
///   cold     the same in a fresh process (this program as a child: its first run, the scene
///            loaded before the clock starts), best of 3 children
///   CLI      a fresh `beamimpact run --quiet --out DIR` of 1 step, the whole process (start,
///            scene file read, set-up, one step, outputs written) minus one step
/// All runs keep a history row every 100 steps (the step is the stepping, not a row's energy
/// sweeps; a row every step would halve the set-up in steps) and write no files, except the CLI's.
/// Run: build/benchmarks/setup_benchmark [max_dofs]   (prints a Markdown table)
/// One case: build/benchmarks/setup_benchmark --child rods|frames ELEMENTS END [REPEATS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <api/run.hpp>
#include <beamimpact/version.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/Progress.hpp>

namespace {

using namespace beamimpact;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// The scene file and the elements per body for about `dofs` DOFs: rods carry 1 DOF a node,
/// frames 3.
struct Kind {
  const char* name;
  const char* file;
  int dofs_per_node;
};
constexpr Kind kKinds[] = {{"rods", "s1_central.toml", 1}, {"frames", "s2_transverse.toml", 3}};

std::string scene_path(const Kind& k) {
  return std::string(BEAMIMPACT_SOURCE_DIR) + "/verification/scenes/paper/" + k.file;
}

/// Overrides of the meshed scene: `elements` per body, dt at the scene's fraction of the critical
/// step, a history row every 100 steps, `end` s (0: the scene's).
std::vector<std::string> overrides(long elements, double end) {
  std::vector<std::string> set = {fmt::format("bodies.A.elements={}", elements),
                                  fmt::format("bodies.B.elements={}", elements), "time.dt=\"auto\"",
                                  "time.output_every=100", "time.allow_long_run=true"};
  if (end > 0.0) set.push_back(fmt::format("time.end={:.17g}", end));
  return set;
}

/// Seconds of one whole run of the loaded scene (beamimpact::run, no output directory), with
/// the heap policy `beamimpact run` turns on (RunOptions::tune_heap).
double timed_run(const Scene& scene, SimulationResult* result = nullptr) {
  RunOptions options;
  options.tune_heap = true;
  const Clock::time_point t0 = Clock::now();
  SimulationResult r = run(scene, "paper", options);
  const double t = seconds_since(t0);
  if (result) *result = std::move(r);
  return t;
}

/// Best of `rounds` runs of the scene file with these overrides.
double best_run(const Kind& k, long elements, double end, int rounds) {
  const Scene scene = load_scene(scene_path(k), overrides(elements, end));
  double best = 1e300;
  for (int r = 0; r < rounds; ++r) best = std::min(best, timed_run(scene));
  return best;
}

/// Best of 3 fresh processes running `command`, each printing its own seconds (child mode) or
/// timed here from start to exit (the CLI).
double best_process(const std::string& command, bool child_prints) {
  double best = 1e300;
  for (int r = 0; r < 3; ++r) {
    const Clock::time_point t0 = Clock::now();
    FILE* p = popen(command.c_str(), "r");
    if (!p) return 0.0;
    double t = 0.0;
    const bool read = std::fscanf(p, "%lf", &t) == 1;
    const int status = pclose(p);
    const double wall = seconds_since(t0);
    if (status != 0 || (child_prints && !read)) {
      std::fprintf(stderr, "setup_benchmark: '%s' failed\n", command.c_str());
      std::exit(1);
    }
    best = std::min(best, child_prints ? t : wall);
  }
  return best;
}

/// Child mode: the first run in this process (1 step), its seconds on stdout; with `repeats` > 1
/// the best of that many runs (warm after the first: for a profiler, e.g. perf record).
int child(const Kind& k, long elements, double end, int repeats) {
  const Scene scene = load_scene(scene_path(k), overrides(elements, end));
  double best = 1e300;
  for (int r = 0; r < std::max(repeats, 1); ++r) best = std::min(best, timed_run(scene));
  std::printf("%.9g\n", best);
  return 0;
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

/// One table row: the step and the set-up (warm, cold, CLI) of `k` meshed to about `dofs`.
void row(const Kind& k, double dofs, const std::string& self) {
  const long elements = std::max(2L, std::lround(dofs / 2.0 / k.dofs_per_node) - 1);
  SimulationResult probe;
  timed_run(load_scene(scene_path(k), overrides(elements, 1e-20)), &probe);  // this mesh's dt
  const double dt = probe.dt;
  // N steps of about 1 s, at least 16 (the step estimated from 1- and 65-step runs): the spread
  // of the set-up in the two runs (page faults, tens of ms at 1e6 DOFs) is then a few per cent
  // of N steps.
  const int rounds = probe.dofs >= 500000 ? 3 : 10;
  const double t1 = best_run(k, elements, dt, rounds);
  const double t65 = best_run(k, elements, 65 * dt, 3);
  const long N = std::clamp(static_cast<long>(1.0 / std::max((t65 - t1) / 64.0, 1e-9)), 16L, 400000L);
  const double t_n = best_run(k, elements, static_cast<double>(N) * dt, 3);
  const double t_2n = best_run(k, elements, static_cast<double>(2 * N) * dt, 3);
  const double step = (t_2n - t_n) / static_cast<double>(N);
  const double warm = t1 - step;
  const double cold =
      best_process(fmt::format("{} --child {} {} {:.17g}", quoted(self), k.name, elements, dt), true) - step;
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "beamimpact_setup_benchmark";
  std::string cli = quoted(std::string(BEAMIMPACT_BINARY_DIR) + "/beamimpact") + " run --quiet --out " +
                    quoted(out.string()) + " " + quoted(scene_path(k));
  for (const std::string& s : overrides(elements, dt)) cli += " --set " + quoted(s);
  const double whole = best_process(cli, false) - step;
  std::filesystem::remove_all(out);
  std::printf("| %s | %ld | %.3g | %.3g | %.0f | %.0f | %.3g | %.0f | %.3g | %.0f |\n", k.name, probe.dofs,
              step * 1e6, warm, warm / step, cold / step, cold, whole / step, whole, static_cast<double>(N));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  Progress::Silence quiet;
  if ((argc == 5 || argc == 6) && std::string(argv[1]) == "--child") {
    const int repeats = argc == 6 ? std::atoi(argv[5]) : 1;
    for (const Kind& k : kKinds)
      if (k.name == std::string(argv[2])) return child(k, std::atol(argv[3]), std::atof(argv[4]), repeats);
    return 2;
  }
  const double max_dofs = argc > 1 ? std::atof(argv[1]) : 1e6;
  const std::string self = std::filesystem::canonical("/proc/self/exe").string();
  std::printf(
      "setup_benchmark, beamimpact %s; the paper integrator through beamimpact::run, dt = 0.5 x critical "
      "(auto); "
      "set-up = a 1-step run minus one step, in steps of the same run\n\n",
      kVersion);
  std::printf(
      "| scene | DOFs | step (us) | warm set-up (s) | warm (steps) | cold (steps) | cold (s) | CLI process "
      "(steps) | CLI process (s) | N |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const Kind& k : kKinds)
    for (double dofs = 1e3; dofs <= max_dofs * 1.0001; dofs *= 10) row(k, dofs, self);
  return 0;
}
