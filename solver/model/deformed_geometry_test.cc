// The real gap's geometry against closed forms: a straight beam, a rigid rotation (exact), a
// circular arc of constant curvature (the beam cubic's error is O(kappa^2 le^3)), an end-on rod.
#include <solver/model/deformed_geometry.hpp>

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>

namespace beamimpact {
namespace {

using testing::soft_body;

/// A free 10 m target B along x (10 elements) and a one-element striker A whose end is at `tip`.
Scene scene_with_tip(Vec2 tip) {
  Scene s;
  s.bodies = {soft_body("A", {tip[0], tip[1] + 1.0}, tip, 1), soft_body("B", {0, 0}, {10, 0}, 10)};
  return s;
}

/// U of the frame model: B's node i moved to the point (x, y) with rotation th (global).
void place(const Model& m, Eigen::VectorXd& U, int node, Vec2 to, double th) {
  const Vec2 X = m.node_position(node);
  U(m.equation(node, 0)) = to[0] - X[0];
  U(m.equation(node, 1)) = to[1] - X[1];
  U(m.equation(node, 2)) = th;
}

TEST(DeformedGeometry, UndeformedTargetGivesTheHeight) {
  const Model m(scene_with_tip({4.3, 0.25}), true);
  DeformedSurface s(m, 1, m.node_id(0, 1));
  const RealGap g = s.gap(Eigen::VectorXd::Zero(m.size()));
  EXPECT_NEAR(g.gap, 0.25, 1e-14);
  EXPECT_EQ(g.element, 4);
  EXPECT_NEAR(g.xi, 0.3, 1e-12);
}

// B rotated rigidly by 30 deg about its start (every node on the rotated line, every rotation
// 30 deg): the real gap is the perpendicular distance to that line, exactly.
TEST(DeformedGeometry, RigidRotationIsExact) {
  const Model m(scene_with_tip({4.3, 2.0}), true);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(m.size());
  const double a = std::numbers::pi / 6;
  for (int i = 0; i <= 10; ++i) place(m, U, m.node_id(1, i), {i * std::cos(a), i * std::sin(a)}, a);
  DeformedSurface s(m, 1, m.node_id(0, 1));
  const Vec2 tip{4.3, 2.0};                                              // A is not moved
  const double expected = -tip[0] * std::sin(a) + tip[1] * std::cos(a);  // left of the rotated axis
  EXPECT_NEAR(s.gap(U).gap, expected, 1e-12);
}

// B bent into a circular arc of radius rho (nodes on the arc, rotations tangent to it): the gap of
// a point above the arc's middle is its distance to the arc; the element's cubic differs from the
// arc by O(le^3 / rho^2) = 1e-3 / 100 here (le = 1 m, rho = 10 m): 1e-4 m accepted.
TEST(DeformedGeometry, ConstantCurvatureFollowsTheCubicNotTheChord) {
  const double rho = 10.0, h = 0.3;
  const Model m(scene_with_tip({4.5, 0.0}), true);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(m.size());
  for (int i = 0; i <= 10; ++i) {
    const double phi = (i - 5.0) / rho;  // arc length i - 5 from the middle
    // the tangent (cos phi, -sin phi) makes the angle -phi with x
    place(m, U, m.node_id(1, i), {5.0 + rho * std::sin(phi), -rho * (1 - std::cos(phi))}, -phi);
  }
  // The striker's tip at (4.5, 0) moved to the point h above the arc at arc length -0.5.
  const double phi = -0.5 / rho;
  const Vec2 on_arc{5.0 + rho * std::sin(phi), -rho * (1 - std::cos(phi))};
  const Vec2 up{std::sin(phi), std::cos(phi)};  // the arc's left normal
  const int tip = m.node_id(0, 1);
  U(m.equation(tip, 0)) = on_arc[0] + h * up[0] - 4.5;
  U(m.equation(tip, 1)) = on_arc[1] + h * up[1];
  DeformedSurface s(m, 1, tip);
  EXPECT_NEAR(s.gap(U).gap, h, 1e-4);
  // The chord of element 4 lies below the arc by le^2 / (8 rho) = 1.25 cm at its middle: a gap
  // measured to the chord (linear interpolation) is off by that much, the cubic's is not.
  const Vec2 a = s.point(U, 4, 0.0), b = s.point(U, 4, 1.0);
  const Vec2 x{4.5 + U(m.equation(tip, 0)), U(m.equation(tip, 1))};
  const double chord_gap =
      ((b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0])) / std::hypot(b[0] - a[0], b[1] - a[1]);
  EXPECT_NEAR(chord_gap - h, rho * (1 - std::cos(0.5 / rho)), 1e-6);  // the sagitta
  // Measured against the chords alone, the gap is that chord gap: the sagitta to the same 1e-6
  // (the arc's sagitta against the chord's exact one differs by O(le^4 / rho^3) = 1e-7 m).
  DeformedSurface chords(m, 1, tip, Centreline::kChord);
  EXPECT_NEAR(chords.gap(U).gap - h, rho * (1 - std::cos(0.5 / rho)), 1e-6);
}

// Two collinear rods, end-on: the gap is the distance beyond the target's end.
// The arc's tangent at arc length a from the middle has turned by -a/rho from x. The cubic
// turns from its chord by atan(phi), phi the node's rotation relative to the chord (0.05 rad
// here: atan departs from the angle by phi^3/3 = 4e-5 rad), and inside an element follows the
// arc to O(le^2 / rho^2) of the turn: 1e-4 rad accepted at le = 1 m, rho = 10 m.
TEST(DeformedGeometry, TurnOfTheTangentFollowsTheArc) {
  const double rho = 10.0;
  const Model m(scene_with_tip({4.5, 0.5}), true);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(m.size());
  for (int i = 0; i <= 10; ++i) {
    const double phi = (i - 5.0) / rho;
    place(m, U, m.node_id(1, i), {5.0 + rho * std::sin(phi), -rho * (1 - std::cos(phi))}, -phi);
  }
  DeformedSurface s(m, 1, m.node_id(0, 1));
  EXPECT_NEAR(s.turn(U, 7, 0.0), -0.2, 1e-4);
  EXPECT_NEAR(s.turn(U, 2, 1.0), 0.2, 1e-4);
  EXPECT_NEAR(s.turn(U, 4, 0.5), 0.05, 1e-4);
  EXPECT_NEAR(s.turn(Eigen::VectorXd::Zero(m.size()), 4, 0.5), 0.0, 1e-15);
}

TEST(DeformedGeometry, EndOnGapIsTheDistanceBeyondTheEnd) {
  Scene s;
  s.bodies = {soft_body("A", {-3.0, 0}, {-0.5, 0}, 5), soft_body("B", {0, 0}, {10, 0}, 10)};
  const Model m(s, false);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(m.size());
  DeformedSurface surf(m, 1, m.node_id(0, 5));
  EXPECT_NEAR(surf.gap(U).gap, 0.5, 1e-14);
  U(m.equation(m.node_id(0, 5), 0)) = 0.7;  // A's end 0.2 m into B
  EXPECT_NEAR(surf.gap(U).gap, -0.2, 1e-14);
}

// A striker node above a node of the target that has risen towards it (every other node in
// place): the closest point is that node, shared by two elements, and the walk along the target
// meets both. On the chords (Centreline::kChord) the two elements form a peak whose sides each
// have their foot point beyond the node (xi > 1 on the left one, xi < 0 on the right one); on the
// frame's cubics (all rotations 0, so both have zero slope at the node) the foot is the node to
// roundoff, which may point either way. The gap is the distance to the node from a walk that starts at either
// end of the target, and the walk ends (the second call starts where the first ended).
TEST(DeformedGeometry, StrikerAboveARisenNodeGivesTheDistanceToIt) {
  constexpr int kElements = 300;
  constexpr double kLength = 7.0, kHeight = 0.25, kRise = 0.01;  // m
  for (const Centreline line : {Centreline::kChord, Centreline::kBeam}) {
    for (const int i : {1, 2, 150, 151, 298, 299}) {
      const double x = kLength * i / kElements;
      Scene s;
      s.bodies = {soft_body("A", {x, kHeight + 1.0}, {x, kHeight}, 1),
                  soft_body("B", {0, 0}, {kLength, 0}, kElements)};
      const Model m(s, true);
      Eigen::VectorXd U = Eigen::VectorXd::Zero(m.size());
      const int node = m.node_id(1, i);
      U(m.equation(node, 1)) = kRise;
      const double x_node = m.node_position(node)[0];
      const double expected = std::hypot(x - x_node, kHeight - kRise);
      DeformedSurface surf(m, 1, m.node_id(0, 1), line);
      // Roundoff of positions of order 10 m: 1e-14.
      ASSERT_NEAR(surf.gap(U).gap, expected, 1e-14)
          << "node " << i << (line == Centreline::kChord ? ", chords" : ", cubics");
      const RealGap g = surf.gap(U);
      EXPECT_NEAR(g.gap, expected, 1e-14) << "node " << i << ", second call";
      EXPECT_NEAR(g.element + g.xi, i, 1e-9) << "node " << i;
    }
  }
}

}  // namespace
}  // namespace beamimpact
