// M_A(t) of a rotating body against an independent construction: the mass of a model whose body
// is drawn already rotated.
#include <solver/integrator/CorotationalMass.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>

namespace beamimpact::paper {
namespace {

using testing::soft_body;

Scene with_striker_at(double angle) {
  Scene s;
  s.file = "test";
  s.model.mass = MassKind::kConsistent;
  const Vec2 d{std::cos(angle), std::sin(angle)};
  s.bodies = {soft_body("A", {1, 2}, {1 + 3 * d[0], 2 + 3 * d[1]}, 3), soft_body("B", {50, 50}, {60, 50}, 2)};
  return s;
}

TEST(CorotationalMass, RigidlyRotatedBodyHasTheMassOfTheRotatedModel) {
  const double a0 = 0.3;
  for (double phi : {0.4, 1.9, -2.6}) {
    const Model m(with_striker_at(a0), true);
    const InternalForce fint(m, {true, false});
    CorotationalMass cm(m, fint);
    // Rigid rotation of A by phi about its first node.
    Eigen::VectorXd U = Eigen::VectorXd::Zero(m.size());
    const Vec2 o = m.node_position(0);
    for (int n = 0; n < 4; ++n) {
      const Vec2 x = m.node_position(n);
      const double dx = x[0] - o[0], dy = x[1] - o[1];
      U(m.equation(n, 0)) = (std::cos(phi) - 1) * dx - std::sin(phi) * dy;
      U(m.equation(n, 1)) = std::sin(phi) * dx + (std::cos(phi) - 1) * dy;
      U(m.equation(n, 2)) = phi;
    }
    cm.update(U);
    const Model rotated(with_striker_at(a0 + phi), true);
    const Eigen::MatrixXd diff = Eigen::MatrixXd(cm.M()) - Eigen::MatrixXd(rotated.M());
    EXPECT_LT(diff.cwiseAbs().maxCoeff(), 1e-12 * Eigen::MatrixXd(rotated.M()).cwiseAbs().maxCoeff()) << phi;
    // The rotated mass differs from the reference one (the rebuild matters).
    EXPECT_GT((Eigen::MatrixXd(m.M()) - Eigen::MatrixXd(rotated.M())).cwiseAbs().maxCoeff(), 1e-3);
  }
}

}  // namespace
}  // namespace beamimpact::paper
