// The critical step from the element and subdomain bounds, against closed forms and a dense solve.
#include <solver/model/critical_dt.hpp>

#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact {
namespace {

using testing::paper_scene;

double dense_omega_max(const Model& m) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(m.K()), Eigen::MatrixXd(m.M()),
                                                               Eigen::EigenvaluesOnly);
  return std::sqrt(es.eigenvalues().maxCoeff());
}

TEST(CriticalStep, LumpedRodsGiveTheCourantLimit) {
  // Free lumped rods: omega_max = 2 c / h exactly (the k = n mode), so dt_crit = h / c = 0.1 s.
  const Model m(load_scene(paper_scene("s1_central")), false);
  const CriticalStep c = critical_step(m);
  EXPECT_NEAR(c.dt, 0.1, 1e-12);
  EXPECT_NEAR(c.element_bound_dt, 0.1, 1e-12);  // the single bar element has the same limit
}

TEST(CriticalStep, PaperScenesGetTheDenseLimit) {
  // Tolerance 1e-10 relative: dense solves of the same matrices in other orders (roundoff).
  for (const char* mass : {"\"lumped\"", "\"consistent\""})
    for (const char* scene : {"s2_transverse", "s3_surface_20", "s4_oblique_60"}) {
      const Scene s =
          load_scene(paper_scene(scene), {std::string("model.mass=") + mass, "model.kinematics=\"linear\""});
      const Model m(s, true);
      const CriticalStep c = critical_step(m);
      EXPECT_NEAR(c.omega_max, dense_omega_max(m), 1e-10 * c.omega_max) << scene << " " << mass;
      // Irons' element bound: no assembled frequency exceeds the largest element frequency.
      EXPECT_LE(c.element_bound_dt, c.dt * (1 + 1e-12)) << scene << " " << mass;
      // Never above the true limit 2/omega_max of the dense solve beyond roundoff: the step's
      // bound is a sigma whose LDL^T pivots of sigma M - K are all positive (1e-13: the two
      // computations' roundoff, measured up to 17 eps on omega^2).
      EXPECT_LE(c.dt, 2 / dense_omega_max(m) * (1 + 1e-13)) << scene << " " << mass;
      EXPECT_EQ(c.bound, CriticalBound::kSubdomain) << scene << " " << mass;
      // Every body fits one subdomain and bodies are uncoupled in K: the subdomain bound is exact.
      EXPECT_NEAR(subdomain_bound(m, kSubdomainElements), std::pow(dense_omega_max(m), 2),
                  1e-10 * std::pow(dense_omega_max(m), 2))
          << scene << " " << mass;
      // One run per body: the lower bound is the Laguerre bracket's lower end, at the top
      // (1e-12: the bracket's width near the root is a few eps, plus the dense solve's roundoff).
      EXPECT_LE(c.omega_lower, dense_omega_max(m) * (1 + 1e-12)) << scene << " " << mass;
      EXPECT_GE(c.omega_lower, dense_omega_max(m) * (1 - 1e-12)) << scene << " " << mass;
    }
}

TEST(CriticalStep, BodiesOfSeveralRunsGetAProvenLowerBound) {
  // 100 elements per body: runs of 32, 32, 32 and 4, so the bound is no longer exact and the
  // lower bound comes from a run with the equations shared with its neighbours held at zero.
  // That is a Rayleigh quotient of the model: never above the dense omega_max (1e-12: the dense
  // solve's and the bracket's roundoff), and the bounds stay close to it.
  for (const char* mass : {"\"lumped\"", "\"consistent\""})
    for (const char* scene : {"s2_transverse", "s4_oblique_60"}) {
      const Scene s =
          load_scene(paper_scene(scene), {std::string("model.mass=") + mass, "model.kinematics=\"linear\"",
                                          "bodies.A.elements=100", "bodies.B.elements=100"});
      const Model m(s, true);
      const CriticalStep c = critical_step(m);
      const double w = dense_omega_max(m);
      EXPECT_LE(c.omega_lower, w * (1 + 1e-12)) << scene << " " << mass;
      EXPECT_GE(c.omega_max, w * (1 - 1e-12)) << scene << " " << mass;
      // The top mode sits at a body end, inside the run holding that end; holding the run's far
      // cut moves it by the mode's exponentially small amplitude there (measured 1e-10 lumped,
      // 9e-16 consistent): 1e-8.
      EXPECT_GE(c.omega_lower, w * (1 - 1e-8)) << scene << " " << mass;
    }
}

TEST(CriticalStep, SubdomainsShorterThanABodyStillBoundTheLimit) {
  // S3's 20-element target split into runs of 1, 3 and 7 elements: each bound is at or above the
  // dense omega_max^2 (the theorem), and longer runs are tighter here (one run: exact).
  const Model m(load_scene(paper_scene("s3_surface_20")), true);
  const double w2 = std::pow(dense_omega_max(m), 2);
  double last = INFINITY;
  for (int run : {1, 3, 7, 32}) {
    const double lam = subdomain_bound(m, run);
    EXPECT_GE(lam, w2 * (1 - 1e-12)) << run;
    EXPECT_LE(lam, last * (1 + 1e-12)) << run;
    last = lam;
  }
  EXPECT_NEAR(last, w2, 1e-10 * w2);
  EXPECT_NEAR(subdomain_bound(m, 1), element_bound(m), 1e-10 * element_bound(m));
}

TEST(CriticalStep, BendingAndRotaryInertiaSetTheLimitNotTheRodWaveSpeed) {
  // S2's elements are 1 m long: h/c = 0.1 s for the axial waves, yet the frame's limit is lower,
  // set by the HRZ rotary inertia (m h^2/78).
  const Model m(load_scene(paper_scene("s2_transverse")), true);
  EXPECT_LT(critical_step(m).dt, 0.1);
}

TEST(CriticalStep, RayleighDampingShortensTheStep) {
  // dt = 2/omega (sqrt(1 + xi^2) - xi), xi = a0/(2 omega) + a1 omega/2.
  const Scene s = load_scene(paper_scene("s1_central"), {"model.rayleigh_stiffness=0.002"});
  const Model m(s, false);
  const CriticalStep c = critical_step(m);
  const double w = 20.0, xi = 0.002 * w / 2;
  EXPECT_NEAR(c.dt, 2 / w * (std::sqrt(1 + xi * xi) - xi), 1e-12);
}

}  // namespace
}  // namespace beamimpact
