/// @file step_loop_benchmark.cc
/// @brief The paper integrator's step loop against the hand-written kernel, in one run:
/// ns per DOF-step of ExplicitContactIntegrator (S2 refined: two lumped frame bodies, one
/// contact, linear kinematics) as a ratio to beamimpact::bench::StepKernel (a lumped frame chain
/// of about the same DOFs), from 1e2 to 1e6 DOFs, and the set-up (model assembly, critical step,
/// integrator construction) in units of the integrator's steps.
/// Run: build/benchmarks/step_loop_benchmark [max_dofs]  (prints a Markdown table)
/// Each step timing is the best of 3 interleaved rounds of at least 0.2 s (this machine is
/// shared); each part of the set-up is its best over repeated set-ups (at least 3, and until
/// 0.2 s have passed, at most 100: at 1e2 DOFs a set-up takes 30 us and the first few in a
/// process still pay for cold caches and page faults). The first set-up is reported too. The
/// set-up in steps counts the model, the critical step and the integrator; reading the scene
/// file (TOML parse, the same at every size) is reported beside it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

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

}  // namespace

int main(int argc, char** argv) {
  const double max_dofs = argc > 1 ? std::atof(argv[1]) : 1e6;
  std::printf(
      "step_loop_benchmark, beamimpact %s; scene s2_transverse refined (lumped frame, one "
      "contact), kernel: StepKernel frame chain\n\n",
      kVersion);
  std::printf(
      "| DOFs | kernel ns/DOF-step | integrator ns/DOF-step | ratio | set-up (s) | set-up (steps) | "
      "model / critical step / integrator (steps) | first set-up (steps) | scene file read (steps) |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (double target = 1e2; target <= max_dofs * 1.0001; target *= 10) {
    // Two bodies of n elements each: about 6 n DOFs.
    const int n = std::max(2, static_cast<int>(target / 6));
    // The set-up, repeated (the first in a process also pays for cold caches and page faults):
    // the best time of each part. The last objects are the ones stepped.
    double t_scene = 1e300, t_model = 1e300, t_crit = 1e300, t_integ = 1e300, t_first = 0.0;
    std::unique_ptr<Scene> s;
    std::unique_ptr<Model> m;
    std::unique_ptr<paper::ExplicitContactIntegrator> integ_ptr;
    const Clock::time_point rounds_start = Clock::now();
    for (int round = 0; round < 100 && (round < 3 || seconds_since(rounds_start) < 0.2); ++round) {
      integ_ptr.reset();
      Clock::time_point t0 = Clock::now();
      s = std::make_unique<Scene>(
          load_scene(std::string(BEAMIMPACT_SOURCE_DIR) + "/verification/scenes/paper/s2_transverse.toml",
                     {"bodies.A.elements=" + std::to_string(n), "bodies.B.elements=" + std::to_string(n),
                      "time.dt=\"auto\""}));
      t_scene = std::min(t_scene, seconds_since(t0));
      t0 = Clock::now();
      const Effects fx = derive_effects(*s);
      m = std::make_unique<Model>(*s, fx.bending);
      t_model = std::min(t_model, seconds_since(t0));
      t0 = Clock::now();
      const double dt = 0.5 * critical_step(*m).dt;
      t_crit = std::min(t_crit, seconds_since(t0));
      t0 = Clock::now();
      integ_ptr = std::make_unique<paper::ExplicitContactIntegrator>(*m, *s, fx, dt);
      t_integ = std::min(t_integ, seconds_since(t0));
      if (round == 0) t_first = t_model + t_crit + t_integ;  // the minima are the first times yet
    }
    paper::ExplicitContactIntegrator& integ = *integ_ptr;
    const double setup = t_model + t_crit + t_integ;
    bench::StepKernel kernel(static_cast<std::size_t>(m->size() / 3), true);
    const double dofs = m->size(), kdofs = static_cast<double>(kernel.dofs());
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
    std::printf("| %.0f | %.2f | %.2f | %.2f | %.4f | %.0f | %.0f / %.0f / %.0f | %.0f | %.0f |\n", dofs,
                ns_ker, ns_int, ns_int / ns_ker, setup, setup / t_int, t_model / t_int, t_crit / t_int,
                t_integ / t_int, t_first / t_int, t_scene / t_int);
    std::fflush(stdout);
  }
  return 0;
}
