// The Hertz step equation R = D(a + b R) with D the secant of the spring's energy from the gap
// gp at U^{p-1}: its root meets the limits it joins (a rigid step b -> 0 with gp at the root:
// R = k (-a)^(3/2), the spring alone; a stiff spring k -> inf: R = -a / b, the hard law), the
// secant is the integral mean of the force k delta^(3/2) over the gap's move (checked by
// quadrature, not by its formula), and the root satisfies its equation over 30 decades.
#include <solver/contact/hertz_law.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace beamimpact::paper {
namespace {

/// The mean of k max(-g, 0)^(3/2) over [lo, hi] by Simpson's rule on n panels (an independent
/// evaluation of the secant force: int F dg / (hi - lo)).
double mean_force(double lo, double hi, double k, int n = 20000) {
  double s = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double g = lo + (hi - lo) * i / n, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    s += w * k * std::pow(std::max(-g, 0.0), 1.5);
  }
  return s / (3.0 * n);
}

TEST(HertzLaw, SecantIsTheMeanForceOverTheMove) {
  // Simpson's rule on a d^(3/2) kink at g = 0 (one gap open): 1e-6 relative at 20000 panels.
  const double k = 3e9;
  for (auto [x, gp] :
       {std::pair{-2e-4, -1e-4}, {-1e-4, -2e-4}, {-2e-4, 5e-5}, {3e-5, -1e-4}, {-1e-4, -1e-4 * (1 + 1e-9)}}) {
    const double D = hertz_secant_force(x, gp, k), mean = mean_force(std::min(x, gp), std::max(x, gp), k);
    EXPECT_NEAR(D, mean, 1e-6 * mean) << x << " " << gp;
  }
  // Equal gaps: the force itself, k delta^(3/2).
  EXPECT_NEAR(hertz_secant_force(-1e-4, -1e-4, k), k * 1e-6, 1e-12 * k * 1e-6);
  EXPECT_EQ(hertz_secant_force(1e-4, 0.0, k), 0.0);
}

TEST(HertzLaw, PotentialIsTheIntegralOfTheForce) {
  // int_0^d k x^(3/2) dx = 2/5 k d^(5/2), by Simpson's rule (1e-6).
  const double k = 3e9, d = 2e-4;
  EXPECT_NEAR(hertz_potential(-d, k), mean_force(-d, 0.0, k) * d, 1e-6 * hertz_potential(-d, k));
  EXPECT_EQ(hertz_potential(1e-3, k), 0.0);
}

TEST(HertzLaw, RootSatisfiesTheStepEquation) {
  // h(y) = y - b D(a + y) increases through its root y = b R: the returned R is the root to 1e-12
  // relative when h changes sign within R (1 -+ 1e-12). (A residual R - D(a + b R) would measure
  // D's steepness in the hard limit, where an ulp of the gap moves D by 1e-9 of R, not the root.)
  for (double a : {-1e-9, -1e-6, -1e-3, -0.1})
    for (double b : {1e-12, 1e-9, 1e-6, 1e-3})
      for (double k : {1e3, 1e6, 1e9, 1e12, 1e15})
        for (double gp : {1e-3, 0.0, 0.5 * a}) {
          const double R = hertz_step_force(a, b, gp, k);
          ASSERT_GT(R, 0.0);
          auto h = [&](double f) { return b * f - b * hertz_secant_force(a + b * f, gp, k); };
          EXPECT_LE(h(R * (1 - 1e-12)), 0.0) << a << " " << b << " " << k << " " << gp;
          EXPECT_GE(h(R * (1 + 1e-12)), 0.0) << a << " " << b << " " << k << " " << gp;
        }
}

TEST(HertzLaw, OpenWhenTheStepDoesNotPenetrate) {
  EXPECT_EQ(hertz_step_force(0.0, 1e-6, 1e-3, 1e9), 0.0);
  EXPECT_EQ(hertz_step_force(1e-3, 1e-6, 0.0, 1e9), 0.0);
  // A spring that indented at U^{p-1} still pushes as it opens: its release's secant force.
  EXPECT_GT(hertz_step_force(1e-3, 1e-6, -1e-4, 1e9), 0.0);
}

TEST(HertzLaw, JoinsTheSpringAndTheHardLaw) {
  // b k^(2/3) |a|^(1/2) measures the step's compliance against the spring's: 1e-8 and 1e8 leave
  // relative corrections of that order (the next term of each expansion). gp = a: the step is
  // at rest in the spring (the secant is then the force at a).
  const double a = -1e-4, k = 1e9;
  const double spring = k * std::pow(-a, 1.5);
  EXPECT_NEAR(hertz_step_force(a, 1e-8 / (k * std::sqrt(-a)), a, k), spring, 1e-7 * spring);
  const double b = 1e-6;
  const double kstiff = 1e8 / (b * std::sqrt(-a));  // spring indentation ~ 1e-5 of |a|
  EXPECT_NEAR(hertz_step_force(a, b, 0.0, kstiff), -a / b, 1e-4 * (-a / b));
}

}  // namespace
}  // namespace beamimpact::paper
