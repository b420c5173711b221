#include <references/ida/PenaltyIda.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace beamimpact::ida {
namespace {

/// Two point masses on a line, m1 at rest position 0 moving at v0 toward m2 at gap g0.
struct TwoMasses {
  double m1 = 1.0, m2 = 3.0, v0 = 2.0, g0 = 0.5, k = 1e4;
  SparseMatrix M, K, C;
  std::unique_ptr<FixedContact> contact;
  TwoMasses() {
    M.resize(2, 2);
    M.insert(0, 0) = m1;
    M.insert(1, 1) = m2;
    K.resize(2, 2);
    ContactFrame f;
    f.g0 = g0;  // gap = g0 + u2 - u1
    f.n_terms = {{1, 1.0}, {0, -1.0}};
    contact = std::make_unique<FixedContact>(f);
  }
  double m_red() const { return 1.0 / (1.0 / m1 + 1.0 / m2); }
  /// Runs to t_end; returns the integrator for inspection.
  std::unique_ptr<PenaltyIda> run(double cn, IdaSettings s, double t_end) {
    auto ida = std::make_unique<PenaltyIda>(M, K, C, std::vector<const ContactKinematics*>{contact.get()},
                                            std::vector<PenaltyLaw>{{k, cn, 0.0, 1.0}}, s);
    ida->start(0.0, Eigen::Vector2d::Zero(), Eigen::Vector2d(v0, 0.0));
    ida->advance_to(t_end);
    return ida;
  }
};

TEST(PenaltyIda, TwoMassesElasticDurationAndVelocityExchange) {
  TwoMasses tm;
  IdaSettings s;
  s.rtol = 1e-10;
  s.atol = 1e-13;
  const double duration = M_PI / std::sqrt(tm.k * (1 / tm.m1 + 1 / tm.m2));
  auto ida = tm.run(0.0, s, 1.0);
  const auto& ev = ida->events();
  ASSERT_EQ(ev.size(), 2u);
  // Theory: touch at g0/v0, release after half a period of the spring on the reduced mass,
  // velocities exchanged as in an elastic collision. Tolerance 1e-8 (relative): 100 x rtol,
  // the usual global-error factor of BDF over ~1e3 steps; the measured error is printed.
  EXPECT_NEAR(ev[0].t, tm.g0 / tm.v0, 1e-8 * tm.g0 / tm.v0);
  EXPECT_NEAR(ev[1].t - ev[0].t, duration, 1e-8 * duration);
  const double v1 = (tm.m1 - tm.m2) / (tm.m1 + tm.m2) * tm.v0, v2 = 2 * tm.m1 / (tm.m1 + tm.m2) * tm.v0;
  EXPECT_NEAR(ida->V()(0), v1, 1e-8 * tm.v0);
  EXPECT_NEAR(ida->V()(1), v2, 1e-8 * tm.v0);
  // The impulse quadrature equals m1's momentum change.
  EXPECT_NEAR(ida->impulse_normal(0), tm.m1 * (tm.v0 - v1), 1e-8 * tm.m1 * tm.v0);
  EXPECT_NEAR(ida->dissipated(), 0.0, 1e-12);
  RecordProperty("duration_error", std::to_string(ev[1].t - ev[0].t - duration));
  std::printf(
      "two masses: duration error %.3e s (of %.6f), v1 error %.3e, v2 error %.3e m/s, "
      "steps %ld\n",
      ev[1].t - ev[0].t - duration, duration, ida->V()(0) - v1, ida->V()(1) - v2, ida->counters().steps);
}

TEST(PenaltyIda, TwoMassesDampedRestitution) {
  // A dashpot set for restitution e: separation velocity e v0 (closed form of penalty_law,
  // independently checked there) and energy loss (1 - e^2) m_red v0^2 / 2 in the quadrature.
  TwoMasses tm;
  IdaSettings s;
  s.rtol = 1e-10;
  s.atol = 1e-13;
  for (double e : {0.8, 0.3, 0.01}) {
    const double zeta = damping_ratio_for_restitution(e);
    auto ida = tm.run(2 * zeta * std::sqrt(tm.k * tm.m_red()), s, 1.0);
    const double vrel = ida->V()(1) - ida->V()(0);
    EXPECT_NEAR(vrel, e * tm.v0, 1e-7 * tm.v0) << e;
    EXPECT_NEAR(ida->dissipated(), 0.5 * (1 - e * e) * tm.m_red() * tm.v0 * tm.v0, 1e-7) << e;
    // Momentum is exchanged through the contact only.
    EXPECT_NEAR(tm.m1 * ida->V()(0) + tm.m2 * ida->V()(1), tm.m1 * tm.v0, 1e-9);
  }
}

TEST(PenaltyIda, KluMatchesDense) {
  // Same problem, two linear solvers: the Newton solve differs only in roundoff, so the
  // results agree to far below the tolerance (1e-9 relative).
  TwoMasses tm;
  IdaSettings s;
  s.rtol = 1e-9;
  s.atol = 1e-12;
  auto a = tm.run(0.0, s, 1.0);
  s.linear_solver = IdaLinearSolver::kKlu;
  auto b = tm.run(0.0, s, 1.0);
  EXPECT_NEAR(a->V()(0), b->V()(0), 1e-9);
  EXPECT_NEAR(a->events()[1].t, b->events()[1].t, 1e-9);
}

}  // namespace
}  // namespace beamimpact::ida
