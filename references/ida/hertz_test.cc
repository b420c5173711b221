// The Hertz law in the IDA reference: the rigid rod dropped on a Hertz spring
// (verification/scenes/extra/hertz_drop.toml) is a mass on that spring, with the closed form
// delta_max = (5 m v0^2 / (4 k))^(2/5), R_max = k delta_max^(3/2), contact time
// (4/5) B(2/5, 1/2) delta_max / v0 = 2.9432 delta_max / v0 (Johnson 1985, section 11.4), and an
// elastic rebound at v0.
#include <references/ida/solve.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact::ida {
namespace {

constexpr double kK = 1e9, kM = 1.0, kV0 = 1.0;  // N/m^1.5, kg, m/s

TEST(IdaHertz, RigidMassOnAHertzSpringMatchesTheClosedForm) {
  const Scene s = load_scene((testing::source_dir() / "verification/scenes/extra/hertz_drop.toml").string(),
                             {"ida.rtol=1e-10"});
  const SimulationResult r = solve(s);
  const double dmax = std::pow(5.0 * kM * kV0 * kV0 / (4.0 * kK), 0.4);
  const double T = 0.8 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9) * dmax / kV0;
  ASSERT_EQ(r.contacts.at(0).intervals.size(), 1u);
  const auto iv = r.contacts[0].intervals[0];
  // Onset and release are located roots (rtol 1e-10): 1e-8 relative covers the root tolerance.
  EXPECT_NEAR(iv[0], 1e-3, 1e-11);
  EXPECT_NEAR(iv[1] - iv[0], T, 1e-8 * T);
  // Impulse 2 m v0 (elastic) to the integration tolerance; the peak is sampled at IDA's steps
  // (some 1e2 in the contact, the force flat at its top to second order): 1e-4.
  EXPECT_NEAR(r.contacts[0].impulse_normal, 2 * kM * kV0, 1e-7);
  const double Rmax = kK * std::pow(dmax, 1.5);
  EXPECT_NEAR(r.contacts[0].peak_R, Rmax, 1e-4 * Rmax);
  EXPECT_NEAR(r.energy_final, 0.5 * kM * kV0 * kV0, 1e-7);  // no dashpot: the energy returns
}

}  // namespace
}  // namespace beamimpact::ida
