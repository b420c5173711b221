#include <references/ida/penalty_law.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace beamimpact::ida {
namespace {

/// Independent check: integrate d'' = -(d + 2 zeta d') (unit frequency, force clipped at zero)
/// with classical RK4 at h = 1e-5 until the force vanishes; returns -d'(release).
double restitution_rk4(double zeta) {
  double d = 0.0, v = 1.0;
  const double h = 1e-5;
  auto acc = [&](double x, double y) { return -(x + 2.0 * zeta * y); };
  for (int i = 0; i < 100000000; ++i) {
    const double k1x = v, k1v = acc(d, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(d + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(d + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = acc(d + h * k3x, v + h * k3v);
    const double dn = d + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vn = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (dn + 2.0 * zeta * vn < 0.0 && i > 0) {
      // Linear interpolation of v to the force zero: error O(h) = 1e-5 at most.
      const double f0 = d + 2.0 * zeta * v, f1 = dn + 2.0 * zeta * vn;
      const double w = f0 / (f0 - f1);
      return -((1 - w) * v + w * vn);
    }
    d = dn;
    v = vn;
  }
  return NAN;
}

TEST(PenaltyLaw, RestitutionClosedFormMatchesDirectIntegration) {
  // Tolerance 2e-5: the RK4 reference locates the release by linear interpolation over one
  // step of 1e-5 (in units of 1/omega); its truncation error is far smaller.
  for (double zeta : {0.0, 0.05, 0.3, 0.7, 0.999, 1.0, 1.001, 2.0, 5.0, 20.0})
    EXPECT_NEAR(restitution_for_damping_ratio(zeta), restitution_rk4(zeta), 2e-5) << zeta;
}

TEST(PenaltyLaw, RestitutionLimits) {
  EXPECT_DOUBLE_EQ(restitution_for_damping_ratio(0.0), 1.0);               // undamped: elastic
  EXPECT_NEAR(restitution_for_damping_ratio(1.0), std::exp(-2.0), 1e-12);  // critical
  // Large zeta: q ~ 1/(4 zeta^2), e ~ q: falls like 1/(4 zeta^2).
  EXPECT_NEAR(restitution_for_damping_ratio(100.0) * 4e4, 1.0, 1e-3);
}

TEST(PenaltyLaw, InverseRoundTrips) {
  for (double e : {1.0, 0.9, 0.5, 0.2, 0.14, 0.13, 0.01, 1e-3, 1e-5})
    EXPECT_NEAR(restitution_for_damping_ratio(damping_ratio_for_restitution(e)), e, 1e-10 * (1 + e));
  EXPECT_THROW(damping_ratio_for_restitution(0.0), std::invalid_argument);
}

TEST(PenaltyLaw, FrictionBoundedAndDissipative) {
  PenaltyLaw law{1e3, 0.0, 0.3, 1e-3};
  for (double vt : {-1.0, -1e-3, -1e-6, 0.0, 1e-6, 1e-3, 1.0}) {
    const double tau = law.friction_force(2.0, vt);
    EXPECT_LE(std::abs(tau), 0.3 * 2.0);  // |tau| <= mu R
    EXPECT_LE(tau * vt, 0.0);             // friction power <= 0
  }
  // Far above v_reg the law is Coulomb's to (v_reg/v)^2 / 2.
  EXPECT_NEAR(law.friction_force(2.0, 1.0), -0.6, 0.6 * 1e-6);
}

}  // namespace
}  // namespace beamimpact::ida
