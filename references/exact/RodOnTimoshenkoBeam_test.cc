// The rod-on-beam solution with a Timoshenko target (RodOnBeam.hpp with BeamShear set) against
// an independent computation: a staggered finite-difference (velocity-stress leapfrog) solution of
// the Timoshenko beam equations on the half span, coupled to the rod through its impedance, over
// the first rod round trip (before the rod's echo returns the contact force is Z (v0 - w')
// exactly); the rod impedance at first touch; the energy balance; and the Euler-Bernoulli limit
// as the section's radius of gyration shrinks with E I and rho A held.
#include <references/exact/RodOnBeam.hpp>
#include <references/exact/rod_on_beam_testing.hpp>

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace beamimpact::exact {
namespace {

/// S2 made stocky (verification/scenes/extra/s2_stocky.toml) with a Timoshenko target: sections
/// 1 m x 1 m (A = 1 m^2, I = 1/12 m^4, L/h = 10; Z_A = 10 N s/m), kappa 5/6, nu 0.3 (G = 38.46 Pa).
RodOnBeamSetup stocky_rod_on_timoshenko_beam(int modes, double t_end) {
  RodOnBeamSetup s = s2_rod_on_beam(modes, t_end, 1.0);
  s.shear = BeamShear{5.0 / 6.0, 100.0 / 2.6};
  return s;
}

/// Contact force history P(k dt), k = 0..steps, of the rod striking the midspan of the simply
/// supported Timoshenko beam at t = 0, before the rod's echo (t < T_A): the beam's half span
/// [0, L/2] on `cells` cells, symmetry at midspan (psi = 0, shear force -P/2 on the half beam),
/// w = M = 0 at the support. Velocities v, phi at nodes and half steps; shear force Q and moment M
/// at cell centres and whole steps; P = Z (v0 - v_0) with v_0 the mean of its half-step values.
std::vector<double> finite_difference_force(const RodOnBeamSetup& s, int cells, double dt, int steps) {
  const SimpleBeam& b = s.beam;
  const double h = 0.5 * b.length / cells, rA = b.rho * b.area, rI = b.rho * b.inertia;
  const double EI = b.E * b.inertia, S = s.shear.kappa * s.shear.G * b.area, Z = s.rod.impedance();
  std::vector<double> v(cells + 1, 0.0), phi(cells + 1, 0.0), Q(cells, 0.0), M(cells, 0.0), P;
  for (int k = 0; k <= steps; ++k) {
    // Half step k - 1/2 -> k + 1/2 with the forces of step k; node 0 solves for P with v.
    const double a = 2.0 * dt / (rA * h), vm = v[0];
    v[0] = (vm + a * Q[0] + 0.5 * a * Z * (s.v0 - 0.5 * vm)) / (1.0 + 0.25 * a * Z);
    P.push_back(Z * (s.v0 - 0.5 * (vm + v[0])));
    for (int i = 1; i < cells; ++i) {
      v[i] += dt / (rA * h) * (Q[i] - Q[i - 1]);
      phi[i] += dt / (rI * h) * (M[i] - M[i - 1] + 0.5 * h * (Q[i - 1] + Q[i]));
    }
    phi[cells] += 2.0 * dt / (rI * h) * (-M[cells - 1] + 0.5 * h * Q[cells - 1]);
    for (int j = 0; j < cells; ++j) {
      Q[j] += dt * S * ((v[j + 1] - v[j]) / h - 0.5 * (phi[j] + phi[j + 1]));
      M[j] += dt * EI * (phi[j + 1] - phi[j]) / h;
    }
  }
  return P;
}

/// Impulse (N s) of the finite-difference force over [0, tau] after touch (trapezoid rule).
double finite_difference_impulse(const RodOnBeamSetup& s, int cells, double tau) {
  const double dt = 0.25 / cells;  // 0.5 h / c0: h = 5 m / cells, c0 = sqrt(E / rho) = 10 m/s
  const int steps = static_cast<int>(std::lround(tau / dt));
  const std::vector<double> P = finite_difference_force(s, cells, dt, steps);
  double J = 0.0;
  for (int k = 0; k < steps; ++k) J += 0.5 * dt * (P[k] + P[k + 1]);
  return J;
}

/// Impulse (N s) of the modal solution with `modes` modes from touch (t0 = 0.1 s) to t0 + tau.
double modal_impulse(int modes, double tau) {
  RodOnBeamSetup s = stocky_rod_on_timoshenko_beam(modes, 0.1 + tau);
  s.rod_fields = false;
  return RodOnBeam(s).solution().impulse;
}

TEST(RodOnTimoshenkoBeam, FiniteDifferenceReferenceStartsAtTheShearWaveImpedance) {
  // The reference itself: at touch the beam answers with two shear waves, impedance
  // Z_B = 2 rho A c_s (c_s = sqrt(kappa G / rho) = 5.661 m/s, Z_B = 11.32 N s/m), so the rod feels
  // P(0+) = Z_A Z_B / (Z_A + Z_B) v0 = 5.310 N. The grid rings for ~100 steps after the jump
  // (at any resolution); from 1 to 2 ms (steps 256-512 at 64000 cells) it has settled, and the
  // force's own change by then is at most its mean slope over the first 0.15 s (4 N/s, falling
  // to 4.7 N) x 2 ms = 1.5e-3 of P: 2e-3.
  const RodOnBeamSetup s = stocky_rod_on_timoshenko_beam(1, 1.0);
  const double cs = std::sqrt(s.shear.kappa * s.shear.G / s.beam.rho),
               ZB = 2.0 * s.beam.rho * s.beam.area * cs;
  const double ZA = s.rod.impedance(), expected = ZA * ZB / (ZA + ZB) * s.v0;
  const std::vector<double> P = finite_difference_force(s, 64000, 0.25 / 64000, 512);
  for (int k = 256; k <= 512; k += 32) EXPECT_NEAR(P[k], expected, 2e-3 * expected) << k;
}

TEST(RodOnTimoshenkoBeam, ImpulseOfTheFirstRoundTripMatchesFiniteDifferences) {
  // Over 0.95 s from touch (before the rod's echo at T_A = 1 s, so both sides see the rod as its
  // impedance; the supports' reflections are in both) the impulse of the modal sum converges as
  // 1 / modes (the Gibbs tail of the shear-wave front at the struck point) and the finite
  // differences' as h (the force's jump at touch): each doubling must halve the change (ratio
  // 2 within 0.3: higher-order terms), and the two Richardson limits (2 J_2n - J_n) agree. What
  // remains after the extrapolation is second order in 1 / modes and h, below a tenth of the
  // removed first-order term (1.9e-4 and 1.0e-4 of J here), hence 3e-5 relative.
  const double tau = 0.95;
  const RodOnBeamSetup s = stocky_rod_on_timoshenko_beam(1, 1.0);
  const double f500 = finite_difference_impulse(s, 500, tau), f1000 = finite_difference_impulse(s, 1000, tau),
               f2000 = finite_difference_impulse(s, 2000, tau);
  const double m128 = modal_impulse(128, tau), m256 = modal_impulse(256, tau), m512 = modal_impulse(512, tau);
  EXPECT_NEAR((f1000 - f500) / (f2000 - f1000), 2.0, 0.3);
  EXPECT_NEAR((m256 - m128) / (m512 - m256), 2.0, 0.3);
  const double fd = 2.0 * f2000 - f1000, modal = 2.0 * m512 - m256;
  EXPECT_NEAR(modal, fd, 3e-5 * fd);
}

TEST(RodOnTimoshenkoBeam, ForceJustAfterFirstTouchIsRodImpedanceTimesSpeedAndEnergyIsKept) {
  // At touch the beam is at rest and no wave has come back: P = Z_A v0 = 10 N exactly. The
  // rod's field momentum is m_A v0 - J (Newton) and rod field + beam modal energy is
  // m_A v0^2 / 2 (field from the interpolated memory: 1e-7 as for the Euler-Bernoulli beam); the
  // beam's modal energy equals the work of P on it to the rk8pd tolerance (1e-10 x scales).
  const RodOnBeam r(stocky_rod_on_timoshenko_beam(64, 3.0));
  const auto& sol = r.solution();
  EXPECT_NEAR(sol.first_P, 10.0, 1e-13);
  expect_momentum_and_energy_kept(sol, 5.0);  // rod mass rho A L = 5 kg
}

/// Largest |P_a - P_b| over the rows of two solutions with the same output times (N).
double largest_force_difference(const RodOnBeamSolution& a, const RodOnBeamSolution& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.rows.size() && i < b.rows.size(); ++i)
    d = std::max(d, std::abs(a.rows[i].P - b.rows[i].P));
  return d;
}

TEST(RodOnTimoshenkoBeam, ApproachesEulerBernoulliAsTheRadiusOfGyrationShrinks) {
  // Scaling E by s and I by 1/s (G with E) holds E I and rho A, so the Euler-Bernoulli solution
  // does not change, while the Timoshenko corrections of every kept mode, (k r)^2 (1 + E / (kappa
  // G)) in omega^2 and (k r)^2 in the modal mass (r^2 = I / A), fall as 1 / s: the difference
  // to Euler-Bernoulli is c / s + O(1 / s^2). S2's section (r^2 = 0.0133 m^2) at s = 32, 64, 128
  // keeps 16 modes, all on the bending branch (the cutoff sqrt(kappa G A / (rho I)), 1570 rad/s at s = 32, is
  // above Omega_16 = 29 rad/s); mode 16's correction (k r)^2 (1 + E / (kappa G)) is 4.4 % at s = 32, so each
  // doubling must halve the difference within 1 +- 0.1 (the O(1 / s^2) term's share, ~ that correction).
  auto setup = [](double scale) {
    RodOnBeamSetup s = stocky_rod_on_timoshenko_beam(16, 1.5);  // the first contact and its end
    s.rod = Rod{5.0, 100.0, 1.0, 0.4};
    s.beam = SimpleBeam{10.0, 100.0 * scale, 1.0, 0.4, 0.4 * 0.4 * 0.4 / 12.0 / scale};
    s.shear = BeamShear{5.0 / 6.0, 100.0 * scale / 2.6};
    s.rod_fields = false;
    return s;
  };
  RodOnBeamSetup eb = setup(1.0);
  eb.shear = BeamShear{};
  const RodOnBeamSolution ref = RodOnBeam(eb).solution();
  std::vector<double> dJ, dP;
  for (double scale : {32.0, 64.0, 128.0}) {
    const RodOnBeamSolution sol = RodOnBeam(setup(scale)).solution();
    dJ.push_back(std::abs(sol.impulse - ref.impulse) / ref.impulse);
    dP.push_back(largest_force_difference(sol, ref));
  }
  for (std::size_t i = 1; i < dJ.size(); ++i) {
    EXPECT_NEAR(dJ[i - 1] / dJ[i], 2.0, 0.2) << i;
    EXPECT_NEAR(dP[i - 1] / dP[i], 2.0, 0.2) << i;
  }
  EXPECT_GT(dP.back(), 0.0);
}

}  // namespace
}  // namespace beamimpact::exact
