// The Hertz step equation a + b R + (R / k)^(2/3) = 0: its root satisfies the equation to
// roundoff over 30 decades of stiffness, and meets the two limits it joins (a rigid step b -> 0:
// R = k (-a)^(3/2), the spring alone; a stiff spring k -> inf: R = -a / b, the hard law).
#include <solver/contact/hertz_law.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace beamimpact::paper {
namespace {

TEST(HertzLaw, RootSatisfiesTheStepEquation) {
  // Residual relative to |a|: 1e-13 (Newton stops at 1e-15 relative change in the indentation).
  for (double a : {-1e-9, -1e-6, -1e-3, -0.1})
    for (double b : {1e-12, 1e-9, 1e-6, 1e-3})
      for (double k : {1e3, 1e6, 1e9, 1e12, 1e15}) {
        const double R = hertz_force(a, b, k);
        ASSERT_GT(R, 0.0);
        const double residual = a + b * R + std::cbrt((R / k) * (R / k));
        EXPECT_LT(std::abs(residual), 1e-13 * std::abs(a)) << a << " " << b << " " << k;
      }
}

TEST(HertzLaw, OpenWhenTheStepDoesNotPenetrate) {
  EXPECT_EQ(hertz_force(0.0, 1e-6, 1e9), 0.0);
  EXPECT_EQ(hertz_force(1e-3, 1e-6, 1e9), 0.0);
}

TEST(HertzLaw, JoinsTheSpringAndTheHardLaw) {
  // b k^(2/3) |a|^(1/2) measures the step's compliance against the spring's: 1e-8 and 1e8 leave
  // relative corrections of that order (the next term of each expansion).
  const double a = -1e-4, k = 1e9;
  const double spring = k * std::pow(-a, 1.5);
  EXPECT_NEAR(hertz_force(a, 1e-8 / (k * std::sqrt(-a)), k), spring, 1e-7 * spring);
  const double b = 1e-6;
  const double kstiff = 1e8 / (b * std::sqrt(-a));  // spring indentation (R/k)^(2/3) ~ 1e-5 of |a|
  EXPECT_NEAR(hertz_force(a, b, kstiff), -a / b, 1e-4 * (-a / b));
}

TEST(HertzLaw, StoredEnergyIsTheIntegralOfTheForce) {
  // int_0^d k x^(3/2) dx = 2/5 k d^(5/2), checked by Simpson's rule on 2000 panels (1e-9).
  const double k = 3e9, d = 2e-4, R = k * std::pow(d, 1.5);
  double s = 0.0;
  const int n = 2000;
  for (int i = 0; i <= n; ++i) {
    const double x = d * i / n, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    s += w * k * std::pow(x, 1.5);
  }
  s *= d / (3.0 * n);
  EXPECT_NEAR(hertz_energy(R, k), s, 1e-9 * s);
}

}  // namespace
}  // namespace beamimpact::paper
