// The critical step from Lanczos on the sparse operator, against closed forms and a dense solve.
#include <beamimpact/model/critical_dt.hpp>

#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include <beamimpact/scene/scene_io.hpp>
#include <beamimpact/testing/test_scenes.hpp>

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

TEST(CriticalStep, LanczosMatchesADenseEigenSolve) {
  // Tolerance 1e-10 relative: Lanczos stops when the top Ritz value is stable to 1e-12.
  for (const char* mass : {"\"lumped\"", "\"consistent\""})
    for (const char* scene : {"s2_transverse", "s3_surface_20", "s4_oblique_60"}) {
      const Scene s =
          load_scene(paper_scene(scene), {std::string("model.mass=") + mass, "model.kinematics=\"linear\""});
      const Model m(s, true);
      const CriticalStep c = critical_step(m);
      EXPECT_NEAR(c.omega_max, dense_omega_max(m), 1e-10 * c.omega_max) << scene << " " << mass;
      // Irons' element bound: no assembled frequency exceeds the largest element frequency.
      EXPECT_LE(c.element_bound_dt, c.dt * (1 + 1e-12)) << scene << " " << mass;
    }
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
