// The semi-analytic ball on a beam against independent computations: the Hertz mass-spring
// answer on a beam too stiff to move (the half-space limit, Johnson 1985 section 11.4), a
// fixed-step RK4 of the same modal equations without located events, the energy balance, and
// convergence with the number of modes on the shipped scene.
#include <references/exact/BallOnBeam.hpp>

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include <references/exact/recognise_scene.hpp>
#include <references/exact/solve_ball_on_beam.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact::exact {
namespace {

// verification/scenes/extra/ball_on_beam.toml as the exact method reads it.
BallOnBeamSetup scene_setup(int modes) {
  const ExactProblem p = recognise_scene(
      load_scene((testing::source_dir() / "verification/scenes/extra/ball_on_beam.toml").string()));
  BallOnBeamSetup s = ball_on_beam_setup(p);
  s.modes = modes;
  s.t_end = 1.2e-3;
  s.dt_out = 1e-5;
  return s;
}

// A 1 kg mass at 1 m/s on k = 1e9 N/m^1.5 (as verification/scenes/extra/hertz_drop.toml),
// struck at the midspan of a beam so stiff that it hardly moves: EI = 3.5e9 N m^2 on 1 m gives
// L^3 / (48 EI) = 6e-12 m/N, 1e-4 of the spring's compliance delta_max / R_max at the peak, and
// a first mode omega_1 = 5.8e5 rad/s, 470 times faster than the contact (0.81 ms): the beam
// follows quasi-statically. The mass on the spring alone: delta_max = (5 m v0^2 / (4 k))^(2/5),
// R_max = k delta_max^(3/2), contact time (4/5) B(2/5, 1/2) delta_max / v0, rebound at -v0.
TEST(BallOnBeam, StiffBeamGivesTheHertzMassOnASpring) {
  BallOnBeamSetup s;
  s.mass = 1.0;
  s.stiffness = 1e9;
  s.beam = SimpleBeam{1.0, 3.5e9, 1.0, 1.0, 1.0};
  s.x_c = 0.5;
  s.v0 = 1.0;
  s.gap = 1e-5;
  s.modes = 8;
  s.t_end = 1e-3;
  s.dt_out = 1e-5;
  const BallOnBeamSolution r = solve_ball_on_beam(s);
  const double delta_max = std::pow(1.25 * s.mass * s.v0 * s.v0 / s.stiffness, 0.4);
  const double beta = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);  // B(2/5, 1/2)
  const double contact_time = 0.8 * beta * delta_max / s.v0;
  EXPECT_NEAR(contact_time / delta_max, 2.9432, 1e-4);  // the constant of the hertz tests
  ASSERT_EQ(r.intervals.size(), 1u);
  // The beam's compliance (1e-4 of the spring's) and its quasi-static following (1 / (omega_1 t)^2
  // ~ 5e-6) move every quantity by ~1e-4: 3e-4 relative (the rebound and impulse: 1e-3).
  EXPECT_NEAR(r.delta_max, delta_max, 3e-4 * delta_max);
  EXPECT_NEAR(r.peak_R, s.stiffness * std::pow(delta_max, 1.5),
              3e-4 * s.stiffness * std::pow(delta_max, 1.5));
  EXPECT_NEAR(r.intervals[0][0], s.gap / s.v0, 1e-15);
  EXPECT_NEAR(r.intervals[0][1] - r.intervals[0][0], contact_time, 3e-4 * contact_time);
  EXPECT_NEAR(r.final_velocity, -s.v0, 1e-3 * s.v0);
  EXPECT_NEAR(r.impulse, 2.0 * s.mass * s.v0, 1e-3 * 2.0 * s.mass * s.v0);
}

// The same truncated system (32 modes of the shipped scene) stepped by classical RK4 at a fixed
// step, with no event location: contacts are the runs of steps with delta > 0, their ends
// interpolated linearly between steps, the impulse by the trapezoid rule.
struct BruteForce {
  std::vector<std::array<double, 2>> intervals;
  double impulse = 0.0, peak = 0.0;
};

BruteForce rk4(const BallOnBeamSetup& s, double h) {
  const int N = s.modes;
  std::vector<double> phi(N), w2(N);
  for (int n = 0; n < N; ++n) {
    phi[n] = std::sin((n + 1) * std::numbers::pi * s.x_c / s.beam.length);
    const double kn = (n + 1) * std::numbers::pi / s.beam.length;
    w2[n] = std::pow(kn, 4) * s.beam.E * s.beam.inertia / (s.beam.rho * s.beam.area);
  }
  const double M = 0.5 * s.beam.rho * s.beam.area * s.beam.length;
  const auto delta = [&](const std::vector<double>& y) {
    double w = 0.0;
    for (int n = 0; n < N; ++n) w += phi[n] * y[n];
    return y[2 * N] - s.gap - w;
  };
  const auto force = [&](const std::vector<double>& y) {
    const double d = delta(y);
    return d > 0.0 ? s.stiffness * std::pow(d, 1.5) : 0.0;
  };
  const auto f = [&](const std::vector<double>& y) {
    std::vector<double> d(y.size());
    const double R = force(y);
    for (int n = 0; n < N; ++n) d[n] = y[N + n], d[N + n] = -w2[n] * y[n] + phi[n] * R / M;
    d[2 * N] = y[2 * N + 1];
    d[2 * N + 1] = -R / s.mass;
    return d;
  };
  std::vector<double> y(2 * N + 2, 0.0);
  y[2 * N] = s.gap;  // start at the first touch, t = gap / v0
  y[2 * N + 1] = s.v0;
  BruteForce b;
  double t = s.gap / s.v0, d_prev = 0.0, R_prev = 0.0;
  bool closed = true;  // delta = 0 and rising at v0
  b.intervals.push_back({t, t});
  const auto axpy = [](const std::vector<double>& a, double c, const std::vector<double>& x) {
    std::vector<double> r(a);
    for (std::size_t i = 0; i < r.size(); ++i) r[i] += c * x[i];
    return r;
  };
  while (t < s.t_end - 0.5 * h) {
    const auto k1 = f(y), k2 = f(axpy(y, 0.5 * h, k1)), k3 = f(axpy(y, 0.5 * h, k2)), k4 = f(axpy(y, h, k3));
    for (std::size_t i = 0; i < y.size(); ++i) y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    t += h;
    const double d = delta(y), R = force(y);
    b.impulse += 0.5 * h * (R + R_prev);
    b.peak = std::max(b.peak, R);
    const double tc = t - h * d / (d - d_prev);  // where delta crosses 0, linearly
    if (!closed && d > 0.0) b.intervals.push_back({tc, tc});
    if (closed && d <= 0.0) b.intervals.back()[1] = tc;
    closed = d > 0.0;
    d_prev = d;
    R_prev = R;
  }
  return b;
}

TEST(BallOnBeam, AgreesWithAFixedStepRungeKuttaOfTheSameModes) {
  const BallOnBeamSetup s = scene_setup(32);
  const BallOnBeamSolution r = solve_ball_on_beam(s);
  const BruteForce b = rk4(s, 2e-9);
  ASSERT_EQ(r.intervals.size(), 5u);  // an impact and four sub-impacts
  ASSERT_EQ(b.intervals.size(), r.intervals.size());
  // RK4 at h = 2e-9 s (omega_32 h = 3e-4): its error is the kink of R at delta = 0 (a local
  // O(h^2.5) error at each contact end) and the linear interpolation of the crossing, O(h^2)
  // against the contact's curvature: far below 1e-10 s; the impulse's trapezoid rule, O(h^2)
  // on a 0.13 ms pulse: ~1e-9 relative. 1e-10 s and 1e-7 leave room for the kink's error.
  for (std::size_t i = 0; i < r.intervals.size(); ++i)
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(b.intervals[i][k], r.intervals[i][k], 1e-10) << i << " " << k;
  EXPECT_NEAR(b.impulse, r.impulse, 1e-7 * r.impulse);
  // The step's peak is sampled every h = 2e-9 s: (pi h / 0.13 ms)^2 / 2 ~ 1e-9 below the located one.
  EXPECT_NEAR(b.peak, r.peak_R, 1e-7 * r.peak_R);
  // No dissipation: kinetic + modal strain + spring energy stays m v0^2 / 2 to the tolerance.
  EXPECT_LT(r.energy_error, 1e-9 * 0.5 * s.mass * s.v0 * s.v0);
}

// Converged in the number of modes: the point receptance's terms fall as 1 / n^4 and the Hertz
// spring bounds the force's bandwidth, so each doubling changes the answer less (measured orders
// of about 3); from 128 to 256 modes the impulse, the peak and the contact times move by less
// than 2e-3 (relative, times relative to the first contact's duration: 0.26 us of 131 us; the
// later contacts start on reflected bending waves, the slowest to converge), with the same five
// contacts, and by less than a quarter of the previous doubling's change.
TEST(BallOnBeam, ConvergesWithTheNumberOfModes) {
  const BallModeStudy study = converge_ball_modes(scene_setup(0), 64, 256, 1e-12);
  ASSERT_EQ(study.table.size(), 3u);  // 64, 128, 256: the tolerance is never met
  EXPECT_FALSE(study.converged);
  const auto change = [&](std::size_t i) {
    const BallModeEntry &a = study.table[i - 1], &b = study.table[i];
    EXPECT_EQ(a.intervals.size(), b.intervals.size());
    double c =
        std::max(std::abs(b.impulse - a.impulse) / b.impulse, std::abs(b.peak_R - a.peak_R) / b.peak_R);
    for (std::size_t j = 0; j < std::min(a.intervals.size(), b.intervals.size()); ++j)
      for (int k = 0; k < 2; ++k)
        c = std::max(
            c, std::abs(b.intervals[j][k] - a.intervals[j][k]) / (b.intervals[0][1] - b.intervals[0][0]));
    return c;
  };
  EXPECT_EQ(study.table.back().intervals.size(), 5u);
  EXPECT_LT(change(2), 2e-3);
  EXPECT_LT(change(2), 0.25 * change(1));
  EXPECT_DOUBLE_EQ(study.change, change(2));
}

}  // namespace
}  // namespace beamimpact::exact
