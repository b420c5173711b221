// How many contact periods two coaxial rods have, by hand from the characteristics, against
// CoaxialRods.
//
// Notation (references.md section 1): striker A at v0 onto target B at rest, first touch at t0,
// tau = t - t0, Z = rho c A, T = 2 L / c, P0 = v0 Z_A Z_B / (Z_A + Z_B) (the force of the first
// wave pair), r = (Z_A - Z_B) / (Z_A + Z_B) (the reflection coefficient at the contact for a wave
// in A). While closed, P = (v0 - 2 S_A / Z_A - 2 eps S_B / Z_B) / (1/Z_A + 1/Z_B); the ends move at
// v_A = v0 - (P + 2 S_A) / Z_A and v_B = (P + 2 eps S_B) / Z_B, with S_X the reflections coming
// back (CoaxialRods.cc) and eps = +1 for a free far end of B, -1 for a fixed one.
//
// 1. Two free rods touch once, whatever their ratios. Say T_A < T_B (the problem is symmetric in
//    A and B: P and the gap rate are). Until T_B nothing returns from B (S_B = 0).
//    - Z_A <= Z_B: at tau = T_A the release wave returns through A (S_A = P0) and the trial force
//      is r P0 <= 0: the force ends at T_A. A is then rigid and stress-free at v_A = r v0 <= 0
//      (its pulse lasted exactly one round trip), while B's end only ever moves away from A
//      (v_B = 2 S_B / Z_B >= 0): the gap never closes again.
//    - Z_A > Z_B: each return through A steps P down by r > 0 (P_n = P0 r^n on
//      [n T_A, (n + 1) T_A)) until T_B, when B's reflection arrives (S_B = P0) and the trial force
//      is -r P0 - (1 - r) S_A < 0: the force ends at T_B. B's pulse then lasted one round trip of B,
//      so its end moves at v_B = 2 P(tau mod T_B) / Z_B >= 2 P0 r^N / Z_B = (1 + r) r^N v0 (the
//      smallest step, N = floor(T_B / T_A)), while A's echoes sum at least the steps
//      P0 .. P0 r^(N-1): v_A <= v0 - 2 P0 (1 - r^N) / ((1 - r) Z_A) = r^N v0 < v_B. The gap only
//      grows.
//    So the second contact period needs a reflection that comes back as compression.
// 2. A target clamped at its far end (eps = -1), Z_B / 3 < Z_A < Z_B, T_A < T_B:
//    - [0, T_A): P = P0, both ends at v0 Z_A / (Z_A + Z_B).
//    - T_A: A's release returns, trial r P0 < 0: they part. A is rigid at r v0 < 0 (moving back);
//      B's end is at rest (its pulse is still on the way to the clamp). The gap opens at -r v0.
//    - T_B: the pulse comes back from the clamp as compression, S_B = P0 on [T_B, T_B + T_A):
//      B's end moves towards A at 2 P0 / Z_B = (1 + r) v0, faster than A recedes (1 + 2 r > 0).
//      The gap -r v0 (T_B - T_A) closes at (1 + 2 r) v0: second touch at
//      tau2 = T_B + (T_B - T_A) (-r) / (1 + 2 r) = T_B + (T_B - T_A) (Z_B - Z_A) / (3 Z_A - Z_B),
//      which is a contact period when tau2 < T_B + T_A.
//    - [tau2, T_B + T_A): S_A = P0, S_B = P0, so P = P0 (1 + 2 r) > 0.
//    - T_B + T_A: B's returning pulse ends (S_B = 0), the trial is r P0 < 0 again: they part.
//    With Z_B = 2 Z_A (r = -1/3): tau2 = 2 T_B - T_A, P = P0 / 3 (the benchmark scene's data).

#include <references/exact/CoaxialRods.hpp>

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace beamimpact::exact {
namespace {

// Every time and force below is a short sum of O(1) numbers, computed by the code through a few
// hundred pieces: 1e-12 relative is roundoff with a wide margin.
constexpr double kRound = 1e-12;

TEST(CoaxialRodsRecontact, FreeRodsTouchOnceAndPartAtTheClosedFormTime) {
  // Length ratios on both sides of 1 (T_A / T_B from 0.2 to 2) and impedance ratios from 1/4
  // to 4, speeds unequal; the contact ends at T_short when the short rod is the softer (or
  // equal), at T_long when it is the stiffer (case 1 above).
  const double v0 = 1.3, gap = 0.2, t0 = gap / v0;
  const Rod b{10.0, 100.0, 1.0, 0.4};  // T_B = 2 s, Z_B = 4 N s/m
  int cases = 0;
  for (double La : {2.0, 5.5, 13.0, 17.0, 20.0})
    for (double area : {0.1, 0.27, 0.4, 0.9, 1.6}) {
      const Rod a{La, 160.0, 0.9, area};  // c = 13.33 m/s
      const double Ta = a.round_trip(), Tb = b.round_trip(), Za = a.impedance(), Zb = b.impedance();
      const bool a_short = Ta < Tb;
      const double Zs = a_short ? Za : Zb, Zl = a_short ? Zb : Za;
      const double end = t0 + (Zs <= Zl ? std::min(Ta, Tb) : std::max(Ta, Tb));
      CoaxialRods s(a, b, v0, gap, t0 + 4.0 * std::max(Ta, Tb));
      const auto iv = s.force_intervals();
      ASSERT_EQ(iv.size(), 1u) << "L_A = " << La << ", A_A = " << area;
      EXPECT_NEAR(iv[0][0], t0, kRound);
      EXPECT_NEAR(iv[0][1], end, kRound * end) << "L_A = " << La << ", A_A = " << area;
      ++cases;
    }
  EXPECT_EQ(cases, 25);
}

TEST(CoaxialRodsRecontact, ClampedTargetTouchesTwiceAtTheCharacteristicTimes) {
  // The benchmark scene (two_rods_second_contact.toml): A 10 m, B 14 m, B twice as stiff and
  // as dense (c = 10 m/s in both), areas 0.4 m^2: Z_B = 2 Z_A = 8 N s/m, T_A = 2 s, T_B = 2.8 s,
  // v0 = 1 m/s across 0.5 m (t0 = 0.5 s), B clamped at its far end.
  const Rod a{10.0, 100.0, 1.0, 0.4}, b{14.0, 200.0, 2.0, 0.4};
  const double v0 = 1.0, t0 = 0.5, te = 60.0;
  CoaxialRods s(a, b, v0, 0.5, te, FarEnd::kFixed);
  const double La = a.length, Lb = b.length, ca = a.wave_speed(), cb = b.wave_speed();
  const double Za = a.impedance(), Zb = b.impedance();
  const double P0 = v0 * Za * Zb / (Za + Zb);  // 8/3 N
  const double P2 = P0 / 3.0;                  // P0 (1 + 2 r), r = -1/3
  // Contact periods: [t0, t0 + 2 L_A/c_A] and [t0 + 4 L_B/c_B - 2 L_A/c_A, t0 + 2 L_B/c_B + 2 L_A/c_A].
  const double s1 = t0, e1 = t0 + 2.0 * La / ca;         // 0.5, 2.5 s
  const double s2 = t0 + 4.0 * Lb / cb - 2.0 * La / ca;  // 4.1 s
  const double e2 = t0 + 2.0 * Lb / cb + 2.0 * La / ca;  // 5.3 s
  const auto iv = s.force_intervals();
  ASSERT_EQ(iv.size(), 2u);
  EXPECT_NEAR(iv[0][0], s1, kRound);
  EXPECT_NEAR(iv[0][1], e1, kRound);
  EXPECT_NEAR(iv[1][0], s2, kRound);
  EXPECT_NEAR(iv[1][1], e2, kRound);
  EXPECT_NEAR(s.state(0.5 * (s1 + e1)).P, P0, kRound * P0);
  EXPECT_NEAR(s.state(0.5 * (s2 + e2)).P, P2, kRound * P0);
  // Between them: A rigid at r v0 = -v0/3; B's end at rest, then at -(1 + r) v0 = -2/3 v0 (towards A)
  // once the clamp's echo is back (t0 + T_B = 3.3 s); the gap peaks there at (v0/3)(T_B - T_A).
  EXPECT_NEAR(s.state(3.0).va, -v0 / 3.0, kRound);
  EXPECT_NEAR(s.state(3.0).vb, 0.0, kRound);
  EXPECT_NEAR(s.state(3.7).vb, -2.0 * v0 / 3.0, kRound);
  EXPECT_NEAR(s.state(t0 + 2.0 * Lb / cb).gap, v0 / 3.0 * 0.8, kRound);
  EXPECT_GT(s.state(3.7).gap, 0.0);
  // Impulses: P0 T_A = 16/3 N s and P0/3 (2 T_A - T_B) = 16/15 N s.
  const double J1 = P0 * 2.0, J2 = P2 * 1.2;
  EXPECT_NEAR(s.impulse(e1) - s.impulse(s1), J1, kRound * J1);
  EXPECT_NEAR(s.impulse(e2) - s.impulse(s2), J2, kRound * J1);
  EXPECT_NEAR(s.impulse(te), J1 + J2, kRound * J1);
  // Only P acts on A: its momentum ends at m v0 - J1 - J2 = -2.4 N s, a mean velocity of -0.6 m/s;
  // its end then alternates between v0 - 2 P0/Z_A = -v0/3 and v0 - 2 (P0 + P2)/Z_A = -7/9 v0.
  const double mA = a.mass();
  for (double t : {5.6, 9.1, 33.3, 59.0}) {
    EXPECT_NEAR(s.striker_field(t).momentum, mA * v0 - J1 - J2, kRound * mA) << t;
    EXPECT_NEAR(s.striker_field(t).momentum / mA, -0.6 * v0, kRound) << t;
  }
  // A's end: -7/9 v0 while the echo of the second pulse is at it (t in [s2 + 2k, e2 + 2k), k >= 1),
  // -v0/3 otherwise.
  EXPECT_NEAR(s.state(8.5).va, -7.0 / 9.0 * v0, kRound);
  EXPECT_NEAR(s.state(7.7).va, -v0 / 3.0, kRound);
  // The clamp does no work: energy 1/2 m_A v0^2 = 2 J at every time (exact field integrals).
  const double E0 = 0.5 * mA * v0 * v0;
  for (double t : {1.0, 3.0, 4.5, 5.0, 7.7, 21.3, 59.0}) {
    const RodField fa = s.striker_field(t), fb = s.target_field(t);
    EXPECT_NEAR(fa.kinetic + fa.strain + fb.kinetic + fb.strain, E0, kRound * E0) << t;
  }
  // No third contact: after e2 the gap grows at the mean 0.6 m/s plus a part periodic in
  // lcm(T_A, 2 T_B) = 28 s (A's end velocity is periodic in T_A, the clamped B's in 2 T_B), so a
  // window longer than one such period (te - e2 = 54.7 s) settles it for all time.
  EXPECT_GT(te - e2, 28.0);
}

TEST(CoaxialRodsRecontact, ClampedTargetGeneralRatiosFollowTheClosedForm) {
  // Unequal materials and Z_B / Z_A = 1.5 (r = -1/5): second touch at
  // tau2 = T_B + (T_B - T_A) (Z_B - Z_A) / (3 Z_A - Z_B) = T_B + (T_B - T_A) / 3, force 3/5 P0,
  // release at T_A + T_B (T_B = 1.6 T_A < 4 T_A, so tau2 < T_A + T_B).
  const Rod a{3.0, 210.0, 2.0, 0.5};  // c = 10.247 m/s, Z = 10.247 N s/m
  const double ca = a.wave_speed(), Za = a.impedance(), Ta = a.round_trip();
  // B: c_B = 0.8 c_A so L_B = 0.8 x 1.6 L_A gives T_B = 1.6 T_A; area for Z_B = 1.5 Z_A.
  const double cb = 0.8 * ca, rhob = 1.3, Eb = rhob * cb * cb;
  const Rod b{0.8 * 1.6 * a.length, Eb, rhob, 1.5 * Za / (rhob * cb)};
  const double Tb = b.round_trip(), Zb = b.impedance();
  ASSERT_NEAR(Tb / Ta, 1.6, kRound);
  ASSERT_NEAR(Zb / Za, 1.5, kRound);
  const double v0 = 2.1, gap = 0.3, t0 = gap / v0;
  CoaxialRods s(a, b, v0, gap, t0 + Ta + Tb + 0.5 * Ta, FarEnd::kFixed);
  const double tau2 = Tb + (Tb - Ta) * (Zb - Za) / (3.0 * Za - Zb);
  const auto iv = s.force_intervals();
  ASSERT_GE(iv.size(), 2u);
  EXPECT_NEAR(iv[0][1], t0 + Ta, kRound * Tb);
  EXPECT_NEAR(iv[1][0], t0 + tau2, kRound * Tb);
  EXPECT_NEAR(iv[1][1], t0 + Ta + Tb, kRound * Tb);
  const double P0 = v0 * Za * Zb / (Za + Zb);
  EXPECT_NEAR(s.state(t0 + 0.5 * (tau2 + Ta + Tb)).P, 0.6 * P0, kRound * P0);
  EXPECT_NEAR(s.impulse(iv[1][1]) - s.impulse(iv[1][0]), 0.6 * P0 * (Ta + Tb - tau2), kRound * P0 * Ta);
}

}  // namespace
}  // namespace beamimpact::exact
