// The rod-on-beam cost estimate against the solution it describes and against S2 by hand, and
// the exact method refusing an extraordinary mode count before it starts.
#include <references/exact/RodOnBeamCost.hpp>

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include <references/exact/rod_on_beam_testing.hpp>
#include <references/exact/solve.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::exact {
namespace {

TEST(RodOnBeamCost, S2At4096ModesByHand) {
  // Omega_4096 = (4096 pi / 10)^2 a = 1.9120e6 rad/s; samples a quarter radian apart:
  // 1.3075e-7 s, over 3 - 0.1 = 2.9 s: 2.2180e7 stops of 2 x 4096 + 3 = 8195 states each.
  const double a = std::sqrt(100.0 * (0.4 * 0.4 * 0.4 / 12.0) / 0.4);
  const double omega = std::pow(4096.0 * std::numbers::pi / 10.0, 2) * a;
  const double samples = 2.9 / (0.25 / omega);
  const RodOnBeamCost c = estimate_rod_on_beam_cost(s2_rod_on_beam(), {4096});
  EXPECT_NEAR(omega, 1.9120e6, 1e2);  // the hand value above, to its 5 digits
  EXPECT_NEAR(c.samples, samples, 1e-9 * samples);
  EXPECT_NEAR(c.state_steps, samples * 8195.0, 1e-9 * samples * 8195.0);
  EXPECT_EQ(c.rows, 301.0);  // 0, 0.01, ..., 3 s
  // rod_field(): panels of 4 c delta = 5.23e-6 m over 5 m: 956003 panels x 10 reads per row.
  EXPECT_NEAR(c.field_points, 301.0 * 956003.0 * 10.0, 301.0 * 10.0);
  EXPECT_GT(c.seconds(), 10 * kOrdinaryExactSeconds) << "hours: the case the check exists for";
}

TEST(RodOnBeamCost, PredictsTheIntegratorStopsOfARun) {
  // Every memory sample is a stop of the rk8pd driver, a quarter radian of the top mode apart,
  // where one rk8pd step at rtol 1e-10 suffices; the extra steps (piece ends, output rows,
  // rejected steps, root finding at the re-contact) stay below 10 %.
  RodOnBeamSetup s = s2_rod_on_beam();
  s.modes = 64;
  s.rod_fields = false;
  const RodOnBeam run(s);
  const RodOnBeamCost c = estimate_rod_on_beam_cost(s, {64});
  EXPECT_DOUBLE_EQ(c.sample_dt, run.solution().sample_dt);
  EXPECT_NEAR(static_cast<double>(run.solution().steps), c.samples, 0.1 * c.samples);
}

TEST(RodOnBeamCost, ExactRefusesAnExtraordinaryModeCountBeforeStarting) {
  // S2 with 4096 modes: hours of integration (above). Refused at once, naming the key, the
  // estimate and the setting that allows it; the default mode study (16..512 modes, worst case
  // about 2 min) is not.
  const Scene scene = testing::load_paper_scene("s2_transverse", {"exact.modes=4096"});
  try {
    (void)solve(scene);
    FAIL() << "ran 4096 modes";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(e.key(), "exact.modes") << m;
    EXPECT_NE(m.find("4096 modes: 2.22e+07 integrator stops"), std::string::npos) << m;
    EXPECT_NE(m.find("time.allow_long_run = true"), std::string::npos) << m;
  }
  std::vector<int> study;
  for (int n = 16; n <= 512; n *= 2) study.push_back(n);
  EXPECT_LT(estimate_rod_on_beam_cost(s2_rod_on_beam(), study).seconds(), kOrdinaryExactSeconds);
}

}  // namespace
}  // namespace beamimpact::exact
