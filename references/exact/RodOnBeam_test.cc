// The semi-analytic rod-on-beam solution against theory (references.md section 2): the
// contact force at first touch, the infinite-beam erfcx asymptotic, the rigid-wall limit,
// momentum and energy balances, and convergence with the number of modes.
#include <references/exact/RodOnBeam.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include <references/exact/erfcx.hpp>
#include <references/exact/rod_on_beam_testing.hpp>

namespace beamimpact::exact {
namespace {

TEST(RodOnBeam, ForceJustAfterFirstTouchIsRodImpedanceTimesSpeed) {
  // At touch the beam is at rest and no wave has come back: P = Z_A v0 exactly.
  const RodOnBeam r(s2_rod_on_beam(16, 0.5));
  EXPECT_NEAR(r.solution().first_P, 4.0, 1e-14);
  ASSERT_FALSE(r.solution().intervals.empty());
  EXPECT_NEAR(r.solution().intervals[0][0], 0.1, 1e-14);  // g0 / v0
}

TEST(RodOnBeam, EarlyForceFollowsInfiniteBeamErfcx) {
  // P = Z_A v0 erfcx(b sqrt(tau)) holds for an infinite beam. A 40 m span struck at midspan
  // keeps the support images 40 m away: their share of the response is ~2 a tau / x^2 < 5e-4
  // for tau <= 0.35 s (a = sqrt(EI/rhoA) = 1.15 m^2/s). 512 modes reach 1.9e3 rad/s, so
  // Omega_N tau > 90 and the truncation ripple measured at this N is below 1e-3; 3e-3 bounds both.
  RodOnBeamSetup s = s2_rod_on_beam(512, 0.35);
  s.beam.length = 40.0;
  s.x_c = 20.0;
  s.gap = 0.0;
  s.dt_out = 0.05;
  s.rod_fields = false;
  const RodOnBeam r(s);
  const double b =
      s.rod.impedance() / (2.0 * s.beam.rho * s.beam.area * std::sqrt(2.0 * s.beam.dispersion()));
  int checked = 0;
  for (const RodOnBeamRow& row : r.solution().rows) {
    if (row.t < 0.1) continue;
    const double expected = s.rod.impedance() * s.v0 * erfcx(b * std::sqrt(row.t));
    EXPECT_NEAR(row.P, expected, 3e-3 * expected) << "tau = " << row.t;
    ++checked;
  }
  EXPECT_EQ(checked, 6);
}

TEST(RodOnBeam, HeavyStiffBeamActsAsRigidWall) {
  // Beam 1e4 times denser and 1e8 times stiffer: b sqrt(T_A) ~ 2e-4, so the rod sees a wall:
  // P = Z_A v0 for one round trip, impulse 2 m_A v0, rebound at -v0 (to ~1e-3).
  RodOnBeamSetup s = s2_rod_on_beam(16, 2.0);
  s.beam.rho = 1e4;
  s.beam.E = 1e10;
  const RodOnBeam r(s);
  const auto& sol = r.solution();
  ASSERT_EQ(sol.intervals.size(), 1u);
  EXPECT_NEAR(sol.intervals[0][0], 0.1, 1e-12);
  EXPECT_NEAR(sol.intervals[0][1], 1.1, 1e-9);  // the unloading wave arrives at t0 + T_A
  EXPECT_NEAR(sol.impulse, 2.0 * s.rod.mass() * s.v0, 1e-3 * sol.impulse);
  const RodOnBeamRow& last = sol.rows.back();
  EXPECT_NEAR(last.rod.momentum / s.rod.mass(), -s.v0, 1e-3);
}

TEST(RodOnBeam, MomentumAndEnergyBalance) {
  // Newton and energy on every row (tolerances in rod_on_beam_testing.hpp); rod mass 2 kg.
  const RodOnBeam r(s2_rod_on_beam(32, 3.0));
  const auto& sol = r.solution();
  expect_momentum_and_energy_kept(sol, 2.0);
  EXPECT_GE(sol.intervals.size(), 2u);  // it separates at t0 + T_A and strikes again
}

TEST(RodOnBeam, ImpulseAndContactTimesConvergeWithModes) {
  // Each doubling must shrink the change of impulse and contact times; by 128 modes the
  // change is below 1e-3 of the impulse and of the first contact's duration.
  const ModeStudy st = converge_modes(s2_rod_on_beam(16, 2.3), 16, 128, 1e-3);
  ASSERT_GE(st.table.size(), 3u);
  std::vector<double> dJ;
  for (std::size_t i = 1; i < st.table.size(); ++i)
    dJ.push_back(std::abs(st.table[i].impulse - st.table[i - 1].impulse));
  for (std::size_t i = 2; i < dJ.size(); ++i) EXPECT_LT(dJ[i], dJ[i - 1]) << i;
  EXPECT_TRUE(st.converged);
  EXPECT_LT(st.impulse_change, 1e-3);
}

}  // namespace
}  // namespace beamimpact::exact
