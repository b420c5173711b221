// The IDA reference's corotational internal force against what any corotational beam must do:
// no force and no energy under a rigid motion of any size, K U under a small motion, and the
// linear part untouched.
#include <references/ida/ElasticForce.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>

namespace beamimpact::ida {
namespace {

/// S4-45's model: the striker A (free, 5 elements at 45 deg) rotates, the target B is held.
struct S4 {
  Scene scene = testing::load_paper_scene("s4_oblique_45");
  Model model{scene, true};
  ElasticForce corot{model, {true, false}};
  ElasticForce linear{model, {false, false}};
};

/// U of striker A turned rigidly by `angle` (rad) about its first node and shifted by (dx, dy).
Eigen::VectorXd rigid_motion(const Model& model, double angle, double dx, double dy) {
  Eigen::VectorXd U = Eigen::VectorXd::Zero(model.size());
  const Vec2 o = model.node_position(model.node_id(0, 0));
  const double c = std::cos(angle), s = std::sin(angle);
  for (int node = 0; node < model.num_nodes(); ++node) {
    if (model.body_of_node(node) != 0) continue;
    const Vec2 p = model.node_position(node);
    const double rx = p[0] - o[0], ry = p[1] - o[1];
    U(model.equation(node, 0)) = c * rx - s * ry - rx + dx;
    U(model.equation(node, 1)) = s * rx + c * ry - ry + dy;
    U(model.equation(node, 2)) = angle;
  }
  return U;
}

// A rigid motion stores no energy and needs no force, whatever the angle (past pi too: the
// rotation is counted on the branch of the nodes' own rotation). Roundoff: the force is K_local
// (about EA/L = 7.2e10 N/m) times a deformation computed to ~1e-16 m on metre-long elements, so
// ~1e-5 N; bound 1e-3 N against the 7e7 N a 0.1 % stretch would give.
TEST(ElasticForce, RigidMotionOfAnyAngleHasNoForceAndNoEnergy) {
  const S4 s;
  Eigen::VectorXd f;
  for (double angle : {0.3, 1.5, 3.0, 4.0, -2.5, 7.0, 12.0}) {
    const Eigen::VectorXd U = rigid_motion(s.model, angle, 0.7, -0.2);
    s.corot.apply(U, f);
    EXPECT_LT(f.cwiseAbs().maxCoeff(), 1e-3) << angle << " rad";
    EXPECT_LT(s.corot.energy(U), 1e-12) << angle << " rad";
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(s.corot.rigid_rotation(k, U), angle, 1e-12) << angle << " rad";
    // The linear model reads the same motion as strain (why the corotation is needed).
    if (std::abs(angle) > 1.0) EXPECT_GT(s.linear.energy(U), 1e6) << angle << " rad";
  }
}

// A small motion: the corotational force is K U to first order; its error is second order in
// the motion (a rotation of 1e-6 rad makes terms of 1e-12 relative). Scale 1e-6 m: bound 1e-4 of
// |K U| (the linear and second-order terms differ by six decades; a wrong sign or a missing
// rotation back is an O(1) error).
TEST(ElasticForce, SmallMotionIsTheLinearForce) {
  const S4 s;
  Eigen::VectorXd U(s.model.size());
  for (int i = 0; i < U.size(); ++i) U(i) = 1e-6 * std::sin(1.0 + 3.7 * i);
  Eigen::VectorXd f, g;
  s.corot.apply(U, f);
  s.linear.apply(U, g);
  const Eigen::VectorXd ku = s.model.K() * U;
  EXPECT_LT((g - ku).norm(), 1e-12 * ku.norm());  // no corotational body: exactly K U
  EXPECT_LT((f - ku).norm(), 1e-4 * ku.norm());
  EXPECT_NEAR(s.corot.energy(U), 0.5 * U.dot(ku), 1e-4 * 0.5 * U.dot(ku));
}

// A stretch of the turned striker: a rigid rotation by 2 rad, then each element stretched along
// its turned axis by e = 1e-4: the end nodes feel the axial force EA e, along the turned axis.
TEST(ElasticForce, StretchAlongTheTurnedAxisGivesTheAxialForce) {
  const S4 s;
  const double angle = 2.0, e = 1e-4;
  Eigen::VectorXd U = rigid_motion(s.model, angle, 0.0, 0.0);
  const Vec2 o = s.model.node_position(s.model.node_id(0, 0));
  const double c = std::cos(angle), sn = std::sin(angle);
  for (int node = 0; node < s.model.num_nodes(); ++node) {
    if (s.model.body_of_node(node) != 0) continue;
    const Vec2 p = s.model.node_position(node);
    const double rx = e * (p[0] - o[0]), ry = e * (p[1] - o[1]);
    U(s.model.equation(node, 0)) += c * rx - sn * ry;
    U(s.model.equation(node, 1)) += sn * rx + c * ry;
  }
  Eigen::VectorXd f;
  s.corot.apply(U, f);
  const Model::Element& el = s.model.elements()[0];
  const double N = el.E * el.area * e;  // tension
  const double axis = std::atan2(el.s, el.c) + angle;
  const int first = s.model.node_id(0, 0);
  // The first node is pulled towards the second: -N along the turned axis; roundoff 1e-9 of N.
  EXPECT_NEAR(f(s.model.equation(first, 0)), -N * std::cos(axis), 1e-9 * N);
  EXPECT_NEAR(f(s.model.equation(first, 1)), -N * std::sin(axis), 1e-9 * N);
  EXPECT_NEAR(f(s.model.equation(first, 2)), 0.0, 1e-9 * N);
}

}  // namespace
}  // namespace beamimpact::ida
