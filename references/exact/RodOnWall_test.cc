// The rod on a rigid wall against hand calculations: d'Alembert without gravity, and the
// bouncing bar of Doyen, Ern and Piperno (2011) with the closed form of its first impact, its
// period, and the energy and momentum balances (integrated field against impulse bookkeeping).
#include <references/exact/RodOnWall.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace beamimpact::exact {
namespace {

// S1's rod (L = 10 m, E = 100 Pa, rho = 1, A = 0.4: c = 10 m/s, Z = 4 N s/m, m = 4 kg) at
// v0 = 1 m/s, 0.5 m from the wall. d'Alembert by hand: touch at 0.5 s; the end stops, a
// compression wave of force Z v0 = 4 N runs up the rod and back (2 L / c = 2 s); at 2.5 s it
// has reversed the whole rod, which leaves stress-free at -v0; impulse 2 m v0 = 8 N s.
TEST(RodOnWall, RodStrikingAWallRebounds) {
  const Rod rod{10.0, 100.0, 1.0, 0.4};
  const RodOnWall sol({rod, 1.0, 0.0, 0.5, 4.0});
  ASSERT_EQ(sol.intervals().size(), 1u);
  EXPECT_NEAR(sol.intervals()[0][0], 0.5, 1e-14);
  EXPECT_NEAR(sol.intervals()[0][1], 2.5, 1e-14);
  for (double t : {0.5, 1.0, 2.0, 2.49}) EXPECT_NEAR(sol.state(t).R, 4.0, 1e-13) << t;
  EXPECT_EQ(sol.state(2.5).R, 0.0);
  EXPECT_NEAR(sol.impulse(4.0), 8.0, 1e-13);
  EXPECT_NEAR(sol.peak_force(), 4.0, 1e-13);
  EXPECT_NEAR(sol.state(3.0).v, -1.0, 1e-14);   // contact end moves away at v0
  EXPECT_NEAR(sol.state(4.0).gap, 1.5, 1e-13);  // 1.5 s at 1 m/s after release
  // Halfway through the contact (t = 1.5 s) the wave front is at the free end: the whole rod is
  // at rest and compressed to R / (E A) = 0.1: strain energy E A e^2 L / 2 = 2 J = m v0^2 / 2.
  const RodField mid = sol.field(1.5);
  EXPECT_NEAR(mid.kinetic, 0.0, 1e-13);
  EXPECT_NEAR(mid.strain, 2.0, 1e-13);
  const RodField after = sol.field(3.0);
  EXPECT_NEAR(after.kinetic, 2.0, 1e-13);
  EXPECT_NEAR(after.strain, 0.0, 1e-13);
  EXPECT_NEAR(after.momentum, -4.0, 1e-13);
}

// The bouncing bar: L = 10, E = 900, rho = 1 (c = 30, T2 = 2 L / c = 2/3 s), A = 1 (Z = 30,
// m = 10), g = 10, released from rest with its lower end 5 m above the ground. By hand: free
// fall (stress-free) for sqrt(2 h / g) = 1 s, touching at 10 m/s. While no wave has come back
// from the top (T2), R = Z w(t) with w = g t the ground's speed in the falling frame: 300 N
// rising to 500 N; at 1 + T2 the reflected wave q = w(1) = 10 arrives and R = Z (w - 2 q)
// = 30 (50/3 - 20) < 0: the bar leaves at exactly 5/3 s. Impulse Z g (25/9 - 1) / 2 = 800/3
// N s, so the mean velocity is g t - I / m = 50/3 - 80/3 = -10 m/s (upwards): the centre
// rises and falls back in 2 v / g = 2 s, and the next contact starts at 1 + 2/3 + 2 = 11/3 s.
// Each impact lasts 2/3 s and the bar leaves each time with its centre at 10 m/s upwards, so
// contacts start every 8/3 s (the force rises 300 -> 500 N in odd impacts and falls 500 -> 300
// N in even ones: the motion's period is 16/3 s).
TEST(RodOnWall, BouncingBarFirstImpactAndPeriod) {
  const Rod rod{10.0, 900.0, 1.0, 1.0};
  const double t_end = 30.0;
  const RodOnWall sol({rod, 0.0, 10.0, 5.0, t_end});
  const auto& iv = sol.intervals();
  ASSERT_EQ(iv.size(), 11u);  // starts 1 + 8k/3 <= 30: k = 0..10
  for (std::size_t k = 0; k < iv.size(); ++k) {
    // Roundoff of the event times grows with the number of pieces (~1e-15 s each).
    EXPECT_NEAR(iv[k][0], 1.0 + 8.0 * static_cast<double>(k) / 3.0, 1e-11) << "impact " << k;
    EXPECT_NEAR(iv[k][1] - iv[k][0], 2.0 / 3.0, 1e-11) << "impact " << k;
  }
  EXPECT_NEAR(sol.state(1.0).R, 300.0, 1e-10);
  EXPECT_NEAR(sol.state(1.5).R, 450.0, 1e-10);
  EXPECT_NEAR(sol.impulse(2.0), 800.0 / 3.0, 1e-10);
  EXPECT_NEAR(sol.state(1.0 - 1e-9).v, 10.0, 1e-7);  // touching at sqrt(2 g h)
  EXPECT_NEAR(sol.state(1.0).v, 0.0, 1e-12);         // and held by the ground from then on
  EXPECT_NEAR(sol.state(0.5).u, 1.25, 1e-13);        // free fall g t^2 / 2
  EXPECT_NEAR(sol.state(2.0 + 2.0 / 3.0).R, 0.0, 0.0);
  // Every impact carries the same impulse: the mean velocity goes from -10 m/s (down, in the
  // direction towards the ground +10) to 10 m/s upwards with gravity acting 2/3 s: m (20 + g 2/3).
  for (std::size_t k = 0; k + 1 < iv.size(); ++k) {
    const double ik = sol.impulse(iv[k][1] + 0.5) - sol.impulse(iv[k][0] - 0.5);
    EXPECT_NEAR(ik, 10.0 * (20.0 + 20.0 / 3.0), 1e-9) << "impact " << k;
  }
  // The energy account K + S - W = E0 = 0 (released from rest, no strain) and the momentum
  // m g t - I: the field integrals against the impulse bookkeeping, at times inside and between
  // impacts. Tolerance: roundoff of ~1e3 J quantities summed over a few hundred pieces.
  for (double t : {0.3, 1.0, 1.2, 1.6, 2.5, 3.9, 7.77, 12.0, 19.0, 29.9}) {
    const RodField f = sol.field(t);
    EXPECT_NEAR(f.kinetic + f.strain - sol.load_work(t), 0.0, 1e-9 * (1.0 + f.kinetic)) << t;
    EXPECT_NEAR(f.momentum, 10.0 * 10.0 * t - sol.impulse(t), 1e-10 * 10.0 * 10.0 * t) << t;
  }
  // p grows as g t (300 m/s at 30 s): the last impact's 500 N carries a few 1e-12 of it.
  EXPECT_NEAR(sol.peak_force(), 500.0, 1e-8);
}

// Invalid data is refused, not solved.
TEST(RodOnWall, RefusesNonPositiveGap) {
  EXPECT_THROW(RodOnWall({Rod{1.0, 1.0, 1.0, 1.0}, 1.0, 0.0, 0.0, 1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace beamimpact::exact
