// Tests of the exact coaxial-rod solution against the closed forms of references.md section 1.
#include <references/exact/CoaxialRods.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace beamimpact::exact {
namespace {

// Roundoff: every value below is a few sums of O(1) numbers, so 1e-12 relative is generous.
constexpr double kRound = 1e-12;

Rod rod(double L, double E, double rho, double A) { return Rod{L, E, rho, A}; }

TEST(CoaxialRods, EqualRodsExchangeVelocities) {
  // S1 data: L = 10 m, c = 10 m/s, Z = 4 N s/m, gap 0.5 m, v0 = 1 m/s.
  const Rod r = rod(10.0, 100.0, 1.0, 0.4);
  CoaxialRods s(r, r, 1.0, 0.5, 4.0);
  const double Z = r.impedance(), T = r.round_trip();
  ASSERT_NEAR(T, 2.0, kRound);
  EXPECT_NEAR(s.first_touch(), 0.5, kRound);
  for (double t : {0.5, 0.9, 1.5, 2.4999}) EXPECT_NEAR(s.state(t).P, Z * 1.0 / 2.0, kRound) << t;
  EXPECT_EQ(s.state(2.6).P, 0.0);
  const auto iv = s.force_intervals();
  ASSERT_EQ(iv.size(), 1u);
  EXPECT_NEAR(iv[0][0], 0.5, kRound);
  EXPECT_NEAR(iv[0][1], 2.5, kRound);
  EXPECT_NEAR(s.impulse(4.0), Z / 2.0 * T, kRound);  // 4 N s
  // Afterwards A at rest and B rigid at v0: the field momenta and energies show it.
  const RodField fa = s.striker_field(3.7), fb = s.target_field(3.7);
  EXPECT_NEAR(fa.momentum, 0.0, kRound);
  EXPECT_NEAR(fa.kinetic + fa.strain, 0.0, kRound);
  EXPECT_NEAR(fb.momentum, r.mass(), kRound);
  EXPECT_NEAR(fb.kinetic, 0.5 * r.mass(), kRound);
  EXPECT_NEAR(fb.strain, 0.0, kRound);
  EXPECT_NEAR(s.state(3.7).va, 0.0, kRound);
  EXPECT_NEAR(s.state(3.7).vb, 1.0, kRound);
  EXPECT_GT(s.state(3.7).gap, 0.0);
}

TEST(CoaxialRods, MidContactFieldSplitsEnergyExactly) {
  // At t0 + T/4 the pulse has run L/2 into each rod: each compressed half holds strain
  // (Z v0/2)^2 / (2 E A) * L/2 and the energy balance is exact.
  const Rod r = rod(10.0, 100.0, 1.0, 0.4);
  CoaxialRods s(r, r, 1.0, 0.5, 4.0);
  const double P = r.impedance() / 2.0, L = r.length;
  const RodField fa = s.striker_field(1.0), fb = s.target_field(1.0);
  EXPECT_NEAR(fa.strain, P * P / (2.0 * r.E * r.area) * L / 2.0, kRound);
  EXPECT_NEAR(fb.strain, fa.strain, kRound);
  EXPECT_NEAR(fa.kinetic + fa.strain + fb.kinetic + fb.strain, 0.5 * r.mass(), kRound);
  EXPECT_NEAR(fa.momentum + fb.momentum, r.mass(), kRound);
  EXPECT_NEAR(fa.momentum, r.mass() - s.impulse(1.0), kRound);
}

TEST(CoaxialRods, ShortStrikerSameMaterialLeavesAPulseInB) {
  // L_A = 5 m, L_B = 10 m: force Z v0/2 for T_A = 1 s, then A at rest, stress-free; the ends
  // stay together with zero force until T_B, which must not count as a second impact.
  const Rod a = rod(5.0, 100.0, 1.0, 0.4), b = rod(10.0, 100.0, 1.0, 0.4);
  CoaxialRods s(a, b, 1.0, 0.0, 6.0);
  const auto iv = s.force_intervals();
  ASSERT_EQ(iv.size(), 1u);
  EXPECT_NEAR(iv[0][0], 0.0, kRound);
  EXPECT_NEAR(iv[0][1], a.round_trip(), kRound);
  EXPECT_NEAR(s.impulse(6.0), a.impedance() / 2.0 * a.round_trip(), kRound);
  // Zero-force, zero-gap phase between T_A and T_B.
  EXPECT_EQ(s.state(1.5).P, 0.0);
  EXPECT_TRUE(s.state(1.5).closed);
  EXPECT_EQ(s.state(1.5).gap, 0.0);
  EXPECT_GT(s.state(2.5).gap, 0.0);
  const RodField fa = s.striker_field(5.5);
  EXPECT_NEAR(fa.momentum, 0.0, kRound);
  EXPECT_NEAR(fa.kinetic + fa.strain, 0.0, kRound);
  // B carries all the energy, but never moves rigidly: its energy exceeds that of its
  // centre-of-mass motion, p^2 / (2 m_B) = 0.5 J, by the 0.5 J of the pulse, at every time.
  for (double t : {2.1, 2.9, 3.6, 4.4, 5.5}) {
    const RodField f = s.target_field(t);
    EXPECT_NEAR(f.kinetic + f.strain, 0.5 * a.mass(), kRound) << t;
    EXPECT_NEAR(f.kinetic + f.strain - f.momentum * f.momentum / (2.0 * b.mass()), 0.5, kRound) << t;
  }
  // Its far half moves at v0 and its near half is at rest (or vice versa): the end alternates.
  EXPECT_NEAR(s.state(2.5).vb, 1.0, kRound);
  EXPECT_NEAR(s.state(3.5).vb, 0.0, kRound);
}

TEST(CoaxialRods, EqualTransitTimesGiveRigidExchange) {
  // Same round trip (T = 2 s), impedances 8 and 4 N s/m: A is twice as stiff and dense per length.
  const Rod a = rod(10.0, 100.0, 1.0, 0.8), b = rod(10.0, 100.0, 1.0, 0.4);
  CoaxialRods s(a, b, 1.0, 0.0, 5.0);
  const double ZA = a.impedance(), ZB = b.impedance();
  const double vA = (ZA - ZB) / (ZA + ZB), vB = 2.0 * ZA / (ZA + ZB);
  const auto iv = s.force_intervals();
  ASSERT_EQ(iv.size(), 1u);
  EXPECT_NEAR(iv[0][1], 2.0, kRound);
  EXPECT_NEAR(s.striker_field(4.5).momentum / a.mass(), vA, kRound);
  EXPECT_NEAR(s.target_field(4.5).momentum / b.mass(), vB, kRound);
  // Rigid: no strain left, kinetic energy of rigid motion.
  EXPECT_NEAR(s.striker_field(4.5).strain + s.target_field(4.5).strain, 0.0, kRound);
  EXPECT_NEAR(s.state(4.5).va, vA, kRound);
  EXPECT_NEAR(s.state(4.5).vb, vB, kRound);
}

TEST(CoaxialRods, ShortStiffStrikerGivesGeometricStaircase) {
  // Short striker of higher impedance (Z_s = 12, L = 2 m, T_s = 0.4 s) on a long rod
  // (Z_l = 4, L = 10 m, T_l = 2 s): P steps down by r = (Z_s - Z_l)/(Z_s + Z_l) = 1/2 every T_s
  // until separation at T_l (while P stays positive).
  const Rod a = rod(2.0, 100.0, 1.0, 1.2), b = rod(10.0, 100.0, 1.0, 0.4);
  CoaxialRods s(a, b, 1.0, 0.0, 3.0);
  const double Zs = a.impedance(), Zl = b.impedance(), Ts = a.round_trip();
  const double r = (Zs - Zl) / (Zs + Zl);
  double P = Zs * Zl / (Zs + Zl) * 1.0;
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(s.state((k + 0.5) * Ts).P, P, kRound * Zs) << "step " << k;
    P *= r;
  }
  const auto iv = s.force_intervals();
  ASSERT_EQ(iv.size(), 1u);
  EXPECT_NEAR(iv[0][1], b.round_trip(), kRound);
  // Momentum: A loses exactly the impulse; the total is conserved; the energy too.
  const RodField fa = s.striker_field(2.9), fb = s.target_field(2.9);
  EXPECT_NEAR(fa.momentum, a.mass() - s.impulse(2.9), kRound);
  EXPECT_NEAR(fa.momentum + fb.momentum, a.mass(), kRound);
  EXPECT_NEAR(fa.kinetic + fa.strain + fb.kinetic + fb.strain, 0.5 * a.mass(), kRound);
}

TEST(CoaxialRods, UnequalEverythingConservesAndReContacts) {
  // Arbitrary data: no closed form, but momentum and energy balances are exact identities of
  // the field integrals, independent of how P was found.
  const Rod a = rod(3.0, 210.0, 2.0, 0.5), b = rod(7.3, 70.0, 0.9, 0.3);
  CoaxialRods s(a, b, 1.7, 0.2, 12.0);
  const double E0 = 0.5 * a.mass() * 1.7 * 1.7;
  for (double t : {0.05, 0.5, 1.3, 3.3, 7.7, 11.9}) {
    const RodField fa = s.striker_field(t), fb = s.target_field(t);
    EXPECT_NEAR(fa.momentum + fb.momentum, a.mass() * 1.7, 1e-11) << t;
    EXPECT_NEAR(fa.momentum, a.mass() * 1.7 - s.impulse(t), 1e-11) << t;
    EXPECT_NEAR(fa.kinetic + fa.strain + fb.kinetic + fb.strain, E0, 1e-11 * E0) << t;
    EXPECT_GE(s.state(t).gap, 0.0);
    EXPECT_GE(s.state(t).P, 0.0);
  }
}

}  // namespace
}  // namespace beamimpact::exact
