// What each effect costs per step: the paper's integrator on a target beam of n elements, with one
// effect switched on at a time, timed in the same run as the hand-written lumped-mass kernel
// (beamimpact::bench::StepKernel) at the same element count. Ratios, not absolute times, are the
// result (reports/plot_effects_benchmark.py divides them; the machine is shared and noisy).
//
// Scenes (written here, one TOML per variant): targets along x, 10 m, E = 100, rho = 1, A = 0.4,
// I = 0.00533 (the paper's S2 beam), n elements in all; strikers are rigid 1 m bodies (3 DOFs each).
// Effect rows: one simply supported target and one striker 1 m above it at rest (the contact is
// checked every step but never closes), one effect switched on at a time.
// Contact rows: 8 targets of n/8 elements (frames), each with a rigid striker in line with it; k of
// them start 1e-7 m from their target's free end and push it along its axis at 1 m/s, the others
// stay 1 m away. The pushed targets are pinned at the far end and the strikers are heavy (rho = 1e6:
// half a mass-on-rod period is ~1000 s), so a closed contact stays closed for the whole timing (a
// transverse strike chatters); each benchmark reports `closed`: the fraction of timed steps in which
// the k pushed contacts all carried R > 0. contact_0 (all open) is their baseline.
// Thread rows (name_threads_2): the same variant with the step on 2 threads (set_threads), timed
// in wall time (the plot compares them with their one-thread variant's wall time); every row
// reports `threads`, the count used.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>

#include <fmt/format.h>
#include <unistd.h>

#include <solver/integrator/ExplicitContactIntegrator.hpp>
#include <solver/model/critical_dt.hpp>
#include <solver/scene/scene_io.hpp>

#include "step_kernel.hpp"

namespace {

using namespace beamimpact;
using namespace beamimpact::paper;

/// @brief One variant of the benchmark scene.
struct Variant {
  bool rods = false;            ///< one target, collinear striker: the scene runs as axial rods
  int targets = 1;              ///< > 1: the contact layout (targets in parallel, in-line strikers)
  int closed = 0;               ///< strikers that start 1e-7 m from their target, moving onto it
  double mu = 0.0;              ///< Coulomb coefficient of every contact
  bool free_target = false;     ///< the effect layout's target without supports (it can rotate)
  std::string mass = "lumped";  ///< "lumped" | "consistent"
  std::string kinematics = "linear";
  double rayleigh_mass = 0.0;  ///< a0 (1/s)
  int threads = 1;             ///< threads of the step (ExplicitContactIntegrator::set_threads)
};

constexpr const char* kBeam =
    "E = 100.0\nrho = 1.0\narea = 0.4\ninertia = 0.0053333333333333\nvelocity = [0.0, 0.0]\n";

std::string rigid_striker(int k, double x0, double x1, double y0, double y1, double vx, double vy,
                          double rho) {
  return fmt::format(
      "[[bodies]]\nname = \"A{}\"\nstart = [{}, {}]\nend = [{}, {}]\nelements = 1\nE = 100.0\nrho = {}\n"
      "area = 0.4\ninertia = 0.0053333333333333\nvelocity = [{}, {}]\nsupports = []\nrigid = true\n",
      k, x0, y0, x1, y1, rho, vx, vy);
}

std::string scene_text(const Variant& v, long elements) {
  std::string s = fmt::format(
      "name = \"effects_benchmark\"\n[time]\ndt = \"auto\"\nfraction = 0.5\nend = 0.01\n"
      "[model]\nmass = \"{}\"\nrotary_inertia = \"hrz\"\nkinematics = \"{}\"\nrayleigh_mass = {}\n",
      v.mass, v.kinematics, v.rayleigh_mass);
  if (v.targets == 1) {  // the effect layout
    s += fmt::format(
        "[[bodies]]\nname = \"B0\"\nstart = [0.0, 0.0]\nend = [10.0, 0.0]\nelements = {}\n{}supports = {}\n",
        elements, kBeam,
        v.free_target || v.rods
            ? "[]"
            : "[{ at = \"start\", fix = [\"x\", \"y\"] }, { at = \"end\", fix = [\"y\"] }]");
    s += v.rods ? rigid_striker(0, -2.0, -1.0, 0.0, 0.0, 0.0, 0.0, 100.0)
                : rigid_striker(0, 5.37, 5.37, 2.0, 1.0, 0.0, 0.0, 100.0);
  } else {  // the contact layout: targets 2 m apart in y, strikers in line, the first `closed` pushing
    for (int k = 0; k < v.targets; ++k) {
      const double y = 2.0 * k;
      s += fmt::format(
          "[[bodies]]\nname = \"B{}\"\nstart = [0.0, {}]\nend = [10.0, {}]\nelements = {}\n{}"
          "supports = [{{ at = \"start\", fix = [\"y\"] }}, {{ at = \"end\", fix = [\"x\", \"y\"] }}]\n",
          k, y, y, elements / v.targets, kBeam);
      const double gap = k < v.closed ? 1e-7 : 1.0;
      s += rigid_striker(k, -1.0 - gap, -gap, y, y, k < v.closed ? 1.0 : 0.0, 0.0, 1e6);
    }
  }
  for (int k = 0; k < v.targets; ++k)
    s += fmt::format("[[contacts]]\nstriker = \"A{}\"\nnode = \"end\"\ntarget = \"B{}\"\nfriction = {}\n", k,
                     k, v.mu);
  return s;
}

/// True when the first k contacts all carry a compressive force.
bool closed(const ExplicitContactIntegrator& in, int k) {
  for (int i = 0; i < k; ++i)
    if (!(in.forces()[static_cast<std::size_t>(i)].R > 0.0)) return false;
  return true;
}

/// Elements of B for a target of about `dofs` DOFs (3 per node for frames, 1 for rods).
long elements_for(long dofs, bool rods) { return rods ? dofs - 1 : dofs / 3 - 1; }

void run_variant(benchmark::State& state, const Variant& v) {
  const long n = elements_for(state.range(0), v.rods);
  const auto file = std::filesystem::temp_directory_path() /
                    fmt::format("beamimpact_effects_benchmark_{}.toml", static_cast<long>(::getpid()));
  std::ofstream(file) << scene_text(v, n);
  const Scene s = load_scene(file);
  std::filesystem::remove(file);
  const Effects fx = derive_effects(s);
  const Model m(effective_scene(s, fx), fx.bending);
  const double dt = 0.5 * critical_step(m).dt;
  auto in = std::make_unique<ExplicitContactIntegrator>(m, s, fx, dt);
  const int threads = in->set_threads(v.threads);
  if (v.closed > 0) {  // 1e-7 m at 1 m/s: the pushed contacts close within a few steps
    for (int k = 0; k < 1000 && !closed(*in, v.closed); ++k) in->step();
    if (!closed(*in, v.closed)) {
      state.SkipWithError("the contacts did not close during warm-up");
      return;
    }
  }
  long n_closed = 0;
  for (auto _ : state) {
    in->step();
    n_closed += closed(*in, v.closed);
  }
  state.SetItemsProcessed(state.iterations() * m.size());  // DOF-steps per second
  state.counters["dofs"] = static_cast<double>(m.size());
  state.counters["elements"] = static_cast<double>(n);
  state.counters["threads"] = threads;
  state.counters["closed"] = static_cast<double>(n_closed) / static_cast<double>(state.iterations());
}

/// The yardstick at the same element count (rods: 1 DOF per node; frames: 3).
void kernel(benchmark::State& state, bool rods) {
  bench::StepKernel k(static_cast<std::size_t>(elements_for(state.range(0), rods)), !rods);
  for (auto _ : state) {
    k.step();
    benchmark::DoNotOptimize(k.displacement().data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(k.dofs()));
  state.counters["dofs"] = static_cast<double>(k.dofs());
}

void sizes(benchmark::internal::Benchmark* b) {
  for (long d : {1000L, 10000L, 100000L}) b->Arg(d);
}

/// A variant: the defaults (frames, one open frictionless contact) changed by `edit`.
Variant variant(const std::function<void(Variant&)>& edit) {
  Variant v;
  edit(v);
  return v;
}

// Name: the effect (what is switched on relative to "frames"); the plot script divides the ratios.
#define EFFECT(name, edit) \
  BENCHMARK_CAPTURE(run_variant, name, variant([](Variant& v) { edit; }))->Apply(sizes);

// A variant on 2 threads, timed in wall time: NAME_threads_2.
#define EFFECT_THREADS(name, edit)                                          \
  BENCHMARK_CAPTURE(run_variant, name##_threads_2, variant([](Variant& v) { \
                      edit;                                                 \
                      v.threads = 2;                                        \
                    }))                                                     \
      ->Apply(sizes)                                                        \
      ->UseRealTime();

BENCHMARK_CAPTURE(kernel, frame_kernel, false)->Apply(sizes);
BENCHMARK_CAPTURE(kernel, rod_kernel, true)->Apply(sizes);
// Baselines: the contact is checked every step but stays open.
EFFECT(rods, v.rods = true)
EFFECT(frames, (void)v)
// Effects a scene calls for (each alone on top of frames).
EFFECT(consistent_mass, v.mass = "consistent")
EFFECT(damping, v.rayleigh_mass = 0.1)
EFFECT(corotational, v.free_target = true; v.kinematics = "corotational")
// Effects declared but not called for: must cost what frames cost (within noise).
EFFECT(friction_declared_contact_open, v.mu = 0.3)
EFFECT(corotational_declared_target_held, v.kinematics = "corotational")
// Contact layout (8 targets): 0 (baseline), 1, 2 and 8 closed pairs, then one closed pair with friction.
EFFECT(contact_0, v.targets = 8)
EFFECT(contact_1, v.targets = 8; v.closed = 1)
EFFECT(contact_2, v.targets = 8; v.closed = 2)
EFFECT(contact_8, v.targets = 8; v.closed = 8)
EFFECT(contact_1_friction, v.targets = 8; v.closed = 1; v.mu = 0.3)
// The step on 2 threads (the same bits as on 1): rods, frames, 8 closed contacts.
EFFECT_THREADS(rods, v.rods = true)
EFFECT_THREADS(frames, (void)v)
EFFECT_THREADS(contact_8, v.targets = 8; v.closed = 8)

}  // namespace

BENCHMARK_MAIN();
