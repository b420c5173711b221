// The simply supported Timoshenko beam's modes (TimoshenkoBeam.hpp, BeamModes.hpp) against an
// independent computation: each frequency by bisection on the determinant of the 2x2 system of
// the equations of motion (not the quadratic's formula), the amplitude ratio against the other
// equation of the system, the branches' orthogonality in the kinetic energy, the modal mass by
// quadrature of the kinetic energy, the slender limit (Euler-Bernoulli with the Rayleigh-Timoshenko
// correction), and the second branch's cutoff sqrt(kappa G A / (rho I)) as k -> 0.
#include <references/exact/TimoshenkoBeam.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include <references/exact/BeamModes.hpp>

namespace beamimpact::exact {
namespace {

/// S2 made stocky (verification/scenes/extra/s2_stocky.toml): 10 m span, 1 m x 1 m section, E 100 Pa,
/// rho 1 kg/m^3, nu 0.3, kappa 5/6: L/h = 10.
SimpleBeam stocky() { return SimpleBeam{10.0, 100.0, 1.0, 1.0, 1.0 / 12.0}; }
BeamShear shear_of(const SimpleBeam& b) { return BeamShear{5.0 / 6.0, b.E / (2.0 * 1.3)}; }

/// Determinant of the system (rho A w^2 - S k^2) W + S k Psi = 0, S k W + (rho I w^2 - E I k^2 - S) Psi = 0.
double det(const SimpleBeam& b, const BeamShear& sh, double k, double w) {
  const double S = sh.kappa * sh.G * b.area, w2 = w * w;
  return (b.rho * b.area * w2 - S * k * k) * (b.rho * b.inertia * w2 - b.E * b.inertia * k * k - S) -
         S * S * k * k;
}

/// Root of det in (lo, hi) by bisection (det changes sign there).
double bisect(const SimpleBeam& b, const BeamShear& sh, double k, double lo, double hi) {
  const double flo = det(b, sh, k, lo);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((det(b, sh, k, mid) > 0.0) == (flo > 0.0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// Both roots by bisection: det(0) = S E I k^4 > 0 and det < 0 where rho A w^2 = S k^2 (the first
/// factor vanishes), so one root lies on each side of that point.
std::array<double, 2> roots_by_bisection(const SimpleBeam& b, const BeamShear& sh, long n) {
  const double k = static_cast<double>(n) * std::numbers::pi / b.length, S = sh.kappa * sh.G * b.area;
  const double mid = std::sqrt(S * k * k / (b.rho * b.area));
  double hi = 2.0 * mid + std::sqrt(S / (b.rho * b.inertia));
  while (det(b, sh, k, hi) < 0.0) hi *= 2.0;
  return {bisect(b, sh, k, 0.0, mid), bisect(b, sh, k, mid, hi)};
}

TEST(TimoshenkoBeam, BothRootsMatchBisectionOfTheDeterminant) {
  // Bisection to 200 halvings is exact to roundoff; the formula loses nothing but roundoff: 1e-12.
  const SimpleBeam b = stocky();
  for (long n : {1L, 2L, 5L, 20L, 100L}) {
    const auto r = timoshenko_roots(b, shear_of(b), n);
    const auto ref = roots_by_bisection(b, shear_of(b), n);
    EXPECT_NEAR(r[0].omega, ref[0], 1e-12 * ref[0]) << n;
    EXPECT_NEAR(r[1].omega, ref[1], 1e-12 * ref[1]) << n;
  }
}

TEST(TimoshenkoBeam, AmplitudeRatioSolvesTheSecondEquationAndBranchesAreOrthogonal) {
  // The ratio Psi/W satisfies the system's second row (roundoff of its terms, S k ~ 30 N/m: 1e-10
  // relative), and the two modes of one wavenumber are orthogonal in the kinetic energy,
  // rho A W1 W2 + rho I Psi1 Psi2 = 0 (eigenvectors of a symmetric pencil): what lets each mode be
  // integrated on its own.
  const SimpleBeam b = stocky();
  const BeamShear sh = shear_of(b);
  const double S = sh.kappa * sh.G * b.area;
  for (long n : {1L, 3L, 17L}) {
    const double k = static_cast<double>(n) * std::numbers::pi / b.length;
    const auto r = timoshenko_roots(b, sh, n);
    for (const TimoshenkoRoot& x : r) {
      const double row2 =
          S * k + (b.rho * b.inertia * x.omega * x.omega - b.E * b.inertia * k * k - S) * x.ratio;
      EXPECT_NEAR(row2, 0.0, 1e-10 * (S * k + S * std::abs(x.ratio))) << n;
    }
    const double cross = b.rho * b.area + b.rho * b.inertia * r[0].ratio * r[1].ratio;
    const double norm = std::sqrt((b.rho * b.area + b.rho * b.inertia * r[0].ratio * r[0].ratio) *
                                  (b.rho * b.area + b.rho * b.inertia * r[1].ratio * r[1].ratio));
    EXPECT_NEAR(cross / norm, 0.0, 1e-12) << n;
  }
}

TEST(TimoshenkoBeam, SlenderLimitIsEulerBernoulliWithTheRayleighTimoshenkoCorrection) {
  // omega_1 = omega_EB (1 - (k r)^2 (1 + E / (kappa G)) / 2 + O((k r)^4)), r^2 = I / A: with
  // (k r)^2 = 1e-6 the neglected term is ~1e-12, so the correction holds to 1e-5 of itself.
  SimpleBeam b = stocky();
  b.length = 1000.0 * std::numbers::pi / std::sqrt(12.0);  // k r = 1e-3 for n = 1
  const BeamShear sh = shear_of(b);
  const double kr2 = 1e-6, predicted = 0.5 * kr2 * (1.0 + b.E / (sh.kappa * sh.G));
  const double w1 = timoshenko_roots(b, sh, 1)[0].omega;
  EXPECT_NEAR(1.0 - w1 / b.omega(1), predicted, 1e-5 * predicted);
}

TEST(TimoshenkoBeam, SecondBranchStartsAtTheShearCutoff) {
  // As k -> 0 the second root tends to sqrt(kappa G A / (rho I)); its relative excess is
  // (k r)^2 (1 + E / (kappa G)) / 2 to first order: 1.8e-8 at k r = 1e-4, hence 1e-7.
  SimpleBeam b = stocky();
  b.length = 1e4 * std::numbers::pi / std::sqrt(12.0);
  const BeamShear sh = shear_of(b);
  const double cutoff = std::sqrt(sh.kappa * sh.G * b.area / (b.rho * b.inertia));
  EXPECT_NEAR(timoshenko_roots(b, sh, 1)[1].omega, cutoff, 1e-7 * cutoff);
}

TEST(BeamModes, TimoshenkoTableHoldsTheLowestModesOfBothBranchesWithTheirEnergyMass) {
  // The table of `count` modes is the count lowest of both branches (bisection roots, sorted);
  // each modal mass is the kinetic energy of the unit mode at unit q' times 2, by 2000-panel
  // Simpson quadrature of rho A w^2 + rho I psi^2 over the span (exact to roundoff: the integrands
  // are constants plus cosines of whole periods); the shape and momentum are the transverse sine's.
  const SimpleBeam b = stocky();
  const BeamShear sh = shear_of(b);
  const int count = 40;
  std::vector<double> all;
  for (long n = 1; n <= count; ++n)
    for (double w : roots_by_bisection(b, sh, n)) all.push_back(w);
  std::sort(all.begin(), all.end());
  const double x_c = 3.7;
  const std::vector<BeamMode> modes = beam_modes(b, sh, x_c, count);
  ASSERT_EQ(modes.size(), static_cast<std::size_t>(count));
  int second = 0;
  for (int i = 0; i < count; ++i) {
    const BeamMode& m = modes[static_cast<std::size_t>(i)];
    EXPECT_NEAR(m.omega, all[static_cast<std::size_t>(i)], 1e-12 * m.omega) << i;
    second += m.branch == 2;
    const double k = m.n * std::numbers::pi / b.length;
    const double ratio = timoshenko_roots(b, sh, m.n)[m.branch - 1].ratio;
    const int panels = 2000;
    double T2 = 0.0;
    for (int j = 0; j <= panels; ++j) {
      const double x = b.length * j / panels, wt = (j == 0 || j == panels) ? 1.0 : (j % 2 ? 4.0 : 2.0);
      const double w = std::sin(k * x), psi = ratio * std::cos(k * x);
      T2 += wt * (b.rho * b.area * w * w + b.rho * b.inertia * psi * psi);
    }
    T2 *= b.length / panels / 3.0;
    EXPECT_NEAR(m.mass, T2, 1e-10 * T2) << i;
    EXPECT_NEAR(m.shape, std::sin(k * x_c), 1e-14);  // roundoff of the argument k x_c
    EXPECT_NEAR(m.momentum, b.rho * b.area * (1.0 - std::cos(k * b.length)) / k,
                1e-12 * b.rho * b.area * b.length);
    EXPECT_DOUBLE_EQ(top_frequency(b, sh, i + 1), m.omega) << i;
  }
  // At L/h = 10 the cutoff sqrt(kappa G A / (rho I)) = 19.6 rad/s lies below omega_1 of mode 40
  // (about sqrt(kappa G / rho) k = 71 rad/s): the second branch is in the table.
  EXPECT_GT(second, 0);
}

}  // namespace
}  // namespace beamimpact::exact
