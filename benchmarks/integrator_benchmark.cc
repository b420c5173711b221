// Cost of the paper's integrator: one step per iteration, on models from 10^2 to 10^5 DOFs.
// Read the ratios within one run (this machine is noisy): time per step / DOFs should stay flat
// (O(n) per step), consistent mass costs a sparse solve, friction and corotation cost little.
#include <benchmark/benchmark.h>

#include <solver/integrator/ExplicitContactIntegrator.hpp>
#include <solver/model/critical_dt.hpp>
#include <solver/scene/scene_io.hpp>

namespace {

using namespace beamimpact;
using namespace beamimpact::paper;

std::string scene_path(const char* name) {
  return std::string(BEAMIMPACT_SOURCE_DIR) + "/verification/scenes/paper/" + name + ".toml";
}

/// S2 (transverse) or S1 (axial) refined to n elements per body, stepped at half the critical step.
void run_steps(benchmark::State& state, const char* scene, std::vector<std::string> sets) {
  const std::string n = std::to_string(state.range(0));
  sets.push_back("bodies.A.elements=" + n);
  sets.push_back("bodies.B.elements=" + n);
  sets.push_back("time.dt=\"auto\"");
  const Scene s = load_scene(scene_path(scene), sets);
  const Effects fx = derive_effects(s);
  const Model m(s, fx.bending);
  const double dt = 0.5 * critical_step(m).dt;
  ExplicitContactIntegrator in(m, s, fx, dt);
  for (auto _ : state) in.step();
  state.SetItemsProcessed(state.iterations() * m.size());  // DOF-steps per second
  state.counters["dofs"] = m.size();
}

void BM_StepAxialRods(benchmark::State& s) { run_steps(s, "s1_central", {}); }
void BM_StepFrameLumped(benchmark::State& s) { run_steps(s, "s2_transverse", {}); }
void BM_StepFrameConsistent(benchmark::State& s) { run_steps(s, "s2_transverse", {"model.mass=consistent"}); }
void BM_StepFrictionCorotational(benchmark::State& s) { run_steps(s, "s4_oblique_60", {}); }
void BM_StepFrictionLinear(benchmark::State& s) {
  run_steps(s, "s4_oblique_60", {"model.kinematics=linear"});
}

BENCHMARK(BM_StepAxialRods)->RangeMultiplier(10)->Range(100, 100000);
BENCHMARK(BM_StepFrameLumped)->RangeMultiplier(10)->Range(100, 30000);
BENCHMARK(BM_StepFrameConsistent)->RangeMultiplier(10)->Range(100, 30000);
BENCHMARK(BM_StepFrictionLinear)->Arg(1000);
BENCHMARK(BM_StepFrictionCorotational)->Arg(1000);

/// The critical step (element bound, subdomain bound by inertia, lower bound): cost per model size.
void BM_CriticalStep(benchmark::State& state) {
  const std::string n = std::to_string(state.range(0));
  const Scene s =
      load_scene(scene_path("s2_transverse"), {"bodies.A.elements=" + n, "bodies.B.elements=" + n});
  const Model m(s, true);
  for (auto _ : state) benchmark::DoNotOptimize(critical_step(m));
  state.counters["dofs"] = m.size();
}
BENCHMARK(BM_CriticalStep)->RangeMultiplier(10)->Range(100, 10000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
