// The run-cost estimate and its guard: counts from the scene (no model built).
#include <solver/scene/run_cost.hpp>

#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

using testing::load_paper_scene;

TEST(RunCost, CountsStepsAndDofsOfS1) {
  // S1: end 4 s, dt 0.01 s -> 400 steps; two bodies of 10 elements -> 2 x 11 nodes x 3 DOFs = 66.
  const RunCost c = estimate_run_cost(load_paper_scene("s1_central"), 0.01);
  EXPECT_EQ(c.steps, 400.0);
  EXPECT_EQ(c.dofs, 66.0);
  EXPECT_EQ(c.work, 400.0 * 66.0);
  EXPECT_NEAR(c.wave_steps, 40.0, 1e-12);  // 4 s / (1 m / 10 m/s)
  EXPECT_EQ(step_count(load_paper_scene("s1_central"), 0.01), 400);
}

TEST(RunCost, AutoStepIsTheAxialTransitTime) {
  // S1: le = 1 m, c = sqrt(E / rho) = 10 m/s -> le / c = 0.1 s (the critical step the solver
  // finds for S1, 0.1 s); dt = "auto" takes fraction 0.5 of it.
  const Scene s = load_paper_scene("s1_central", {"time.dt=\"auto\""});
  EXPECT_NEAR(estimate_auto_dt(s), 0.05, 1e-15);
}

TEST(RunCost, RefusesBeyondOrdinaryUnlessAllowed) {
  // 1e9 steps x 66 DOFs = 6.6e10 DOF-steps is ordinary work but 1e9 rows x 200 B = 200 GB of
  // history is not; end 4e9 s: 4e11 x 66 = 2.6e13 DOF-steps.
  const Scene big = load_paper_scene("s1_central", {"time.end=1e7"});
  EXPECT_THROW(check_run_cost(big, 0.01), InputError);
  EXPECT_NO_THROW(
      check_run_cost(load_paper_scene("s1_central", {"time.end=1e7", "time.allow_long_run=true"}), 0.01));
  EXPECT_NO_THROW(check_run_cost(load_paper_scene("s1_central"), 0.01));
  try {
    check_run_cost(load_paper_scene("s1_central", {"time.end=4e9"}), 0.01);
    FAIL() << "expected a refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "time.allow_long_run");
    EXPECT_NE(std::string(e.what()).find(
                  "4e+11 steps (the fastest wave needs 4e+10) x 66 DOFs = 2.64e+13 DOF-steps"),
              std::string::npos)
        << e.what();
  }
}

TEST(RunCost, StepCountBeyondTheTimeAxisIsAlwaysRefused) {
  // 1e3 s / 1e-13 s = 1e16 steps > 1e15: refused even with allow_long_run (it overflowed a long
  // at dt = 1e-300 and could not advance t in double precision).
  const Scene s = load_paper_scene("s1_central", {"time.end=1e3", "time.allow_long_run=true"});
  EXPECT_THROW(step_count(s, 1e-13), InputError);
  EXPECT_THROW(check_run_cost(s, 1e-13), InputError);
  EXPECT_THROW(check_run_cost(s, 0.0), InputError);
  EXPECT_EQ(step_count(s, 1e-12), 1'000'000'000'000'000);
}

TEST(RunCost, FieldFilesBeyondAGigabyteNeedFewerRowsOrTheOption) {
  // S1 with fields: 401 files of 22 nodes. The writer made 1 272 273 bytes in single precision
  // (the default; 3117-3120 B a file) and 1 802 395 in double (4439 B a file), measured with
  // `du -b` of the fields folder: the estimates are within 10 % of them.
  const RunCost s1 = estimate_run_cost(load_paper_scene("s1_central", {"output.fields=true"}), 0.01);
  EXPECT_NEAR(s1.field_bytes, 1272273.0, 0.1 * 1272273.0);
  const RunCost s1_double = estimate_run_cost(
      load_paper_scene("s1_central", {"output.fields=true", "output.field_precision=\"double\""}), 0.01);
  EXPECT_NEAR(s1_double.field_bytes, 1802395.0, 0.1 * 1802395.0);
  EXPECT_EQ(estimate_run_cost(load_paper_scene("s1_central"), 0.01).field_bytes, 0.0);
  // 4e4 s at 0.01 s: 4e6 files of about 3.1 kB = 12.4 GB (history 0.8 GB and 2.6e8 DOF-steps are
  // ordinary): refused naming output.fields, asking for every 13th row (under 1 GB); every 40th
  // row (0.3 GB) or allow_long_run passes.
  try {
    check_run_cost(load_paper_scene("s1_central", {"output.fields=true", "time.end=4e4"}), 0.01);
    FAIL() << "expected a refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "output.fields");
    EXPECT_NE(std::string(e.what()).find("time.output_every = 13 or more"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(check_run_cost(
      load_paper_scene("s1_central", {"output.fields=true", "time.end=4e4", "time.output_every=40"}), 0.01));
  EXPECT_NO_THROW(check_run_cost(
      load_paper_scene("s1_central", {"output.fields=true", "time.end=4e4", "time.allow_long_run=true"}),
      0.01));
}

}  // namespace
}  // namespace beamimpact
