/// @file step_loop_benchmark.cc
/// @brief The paper integrator's step loop against the hand-written kernel, in one run:
/// ns per DOF-step of ExplicitContactIntegrator (S2 refined: two lumped frame bodies, one
/// contact, linear kinematics) as a ratio to beamimpact::bench::StepKernel (a lumped frame chain
/// of about the same DOFs), from 1e2 to 1e6 DOFs. The set-up before the first step is measured
/// on the user's whole path by setup_benchmark.cc, not here.
/// Run: build/benchmarks/step_loop_benchmark [max_dofs]  (prints a Markdown table)
/// Each step timing is the best of 3 interleaved rounds of at least 0.2 s (this machine is
/// shared).
/// A second table times the step on 1 thread and on 2 (and on the machine's hardware threads
/// when more) from 1e3 DOFs up, interleaved, with the machine's load average at each row, and
/// checks in the same run that every thread count gives the bits of one thread (U and Vbar after
/// the same number of steps); a difference is an error (exit 1).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "step_kernel.hpp"

#include <beamimpact/version.hpp>
#include <solver/integrator/ExplicitContactIntegrator.hpp>
#include <solver/model/critical_dt.hpp>
#include <solver/scene/scene_io.hpp>

namespace {

using namespace beamimpact;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Seconds per call of f, best of `rounds` rounds of at least min_seconds each.
template <class F>
double per_call(F&& f, int rounds = 3, double min_seconds = 0.2) {
  double best = 1e300;
  for (int r = 0; r < rounds; ++r) {
    long calls = 0;
    const Clock::time_point t0 = Clock::now();
    double t = 0.0;
    do {
      for (int i = 0; i < 16; ++i) f();
      calls += 16;
      t = seconds_since(t0);
    } while (t < min_seconds);
    best = std::min(best, t / static_cast<double>(calls));
  }
  return best;
}

/// The 1-minute load average (/proc/loadavg), -1 when unknown.
double load_average() {
  std::FILE* f = std::fopen("/proc/loadavg", "r");
  double l = -1.0;
  if (f) {
    if (std::fscanf(f, "%lf", &l) != 1) l = -1.0;
    std::fclose(f);
  }
  return l;
}

/// True when a and b hold the same bits.
bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

/// S2 with two bodies of n elements each, about 6 n = `target` DOFs, dt = "auto".
Scene refined_s2(double target) {
  const int n = std::max(2, static_cast<int>(target / 6));
  return load_scene(std::string(BEAMIMPACT_SOURCE_DIR) + "/verification/scenes/paper/s2_transverse.toml",
                    {"bodies.A.elements=" + std::to_string(n), "bodies.B.elements=" + std::to_string(n),
                     "time.dt=\"auto\""});
}

/// The threads table at about `target` DOFs (S2 refined, dt = 0.5 x critical): the step on each
/// thread count, best of 3 interleaved rounds, and the bits of each against one thread after the
/// same number of steps. False when some count gives other bits.
bool thread_rows(double target) {
  const Scene s = refined_s2(target);
  const Effects fx = derive_effects(s);
  const Model m(s, fx.bending);
  const double dt = 0.5 * critical_step(m).dt;
  std::vector<int> counts = {1, 2};
  if (const int hw = static_cast<int>(std::thread::hardware_concurrency()); hw > 2) counts.push_back(hw);
  std::vector<std::unique_ptr<paper::ExplicitContactIntegrator>> in;
  std::vector<int> used;
  for (int c : counts) {
    in.push_back(std::make_unique<paper::ExplicitContactIntegrator>(m, s, fx, dt));
    used.push_back(in.back()->set_threads(c));
  }
  std::vector<double> best(counts.size(), 1e300);
  const double load = load_average();
  for (int round = 0; round < 3; ++round)
    for (std::size_t k = 0; k < counts.size(); ++k)
      best[k] = std::min(best[k], per_call([&] { in[k]->step(); }, 1));
  long steps = 0;
  for (const auto& p : in) steps = std::max(steps, p->step_index());
  for (const auto& p : in)
    while (p->step_index() < steps) p->step();
  bool all_same = true;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    const bool same = same_bits(in[k]->U(), in[0]->U()) && same_bits(in[k]->Vbar(), in[0]->Vbar());
    all_same = all_same && same;
    std::printf("| %d | %d | %d | %.2f | %.2f | %ld | %s | %.2f |\n", m.size(), counts[k], used[k],
                best[k] / m.size() * 1e9, best[0] / best[k], steps, same ? "yes" : "NO", load);
  }
  std::fflush(stdout);
  return all_same;
}

}  // namespace

int main(int argc, char** argv) {
  const double max_dofs = argc > 1 ? std::atof(argv[1]) : 1e6;
  std::printf(
      "step_loop_benchmark, beamimpact %s; scene s2_transverse refined (lumped frame, one "
      "contact), kernel: StepKernel frame chain\n\n",
      kVersion);
  std::printf("| DOFs | kernel ns/DOF-step | integrator ns/DOF-step | ratio |\n");
  std::printf("|---:|---:|---:|---:|\n");
  for (double target = 1e2; target <= max_dofs * 1.0001; target *= 10) {
    const Scene s = refined_s2(target);
    const Effects fx = derive_effects(s);
    const Model m(s, fx.bending);
    paper::ExplicitContactIntegrator integ(m, s, fx, 0.5 * critical_step(m).dt);
    bench::StepKernel kernel(static_cast<std::size_t>(m.size() / 3), true);
    const double dofs = m.size(), kdofs = static_cast<double>(kernel.dofs());
    double t_int = 1e300, t_ker = 1e300;
    for (int round = 0; round < 3; ++round) {  // interleaved: both see the same machine load
      t_ker = std::min(t_ker, per_call([&] { kernel.step(); }, 1));
      t_int = std::min(t_int, per_call([&] { integ.step(); }, 1));
    }
    if (!std::isfinite(integ.U().norm()) || !std::isfinite(kernel.displacement()[0])) {
      std::fprintf(stderr, "step_loop_benchmark: a run went unstable at %g DOFs\n", dofs);
      return 1;
    }
    const double ns_int = t_int / dofs * 1e9, ns_ker = t_ker / kdofs * 1e9;
    std::printf("| %.0f | %.2f | %.2f | %.2f |\n", dofs, ns_ker, ns_int, ns_int / ns_ker);
    std::fflush(stdout);
  }
  std::printf(
      "\nThe step on threads (the same scene; best of 3 interleaved rounds of at least 0.2 s; same "
      "bits: U and Vbar against 1 thread after the same steps; load: 1-minute load average)\n\n");
  std::printf(
      "| DOFs | threads asked | threads used | ns/DOF-step | speed-up | steps | same bits | load |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|:---:|---:|\n");
  bool same = true;
  for (double target = 1e3; target <= max_dofs * 1.0001; target *= std::sqrt(10.0))  // 1e3, 3.2e3, 1e4, ...
    same = thread_rows(target) && same;
  if (!same) {
    std::fprintf(stderr, "step_loop_benchmark: some thread count changed the bits of one thread\n");
    return 1;
  }
  return 0;
}
