// The corotational element against the linear one (small motion) and against rigid motion (large).
#include <solver/integrator/InternalForce.hpp>

#include <bit>
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact::paper {
namespace {

using testing::soft_body;

Scene inclined(double angle) {
  Scene s;
  s.file = "test";
  const Vec2 d{std::cos(angle), std::sin(angle)};
  s.bodies = {soft_body("A", {0, 0}, {3 * d[0], 3 * d[1]}, 3), soft_body("B", {50, 50}, {51, 50}, 1)};
  return s;
}

TEST(InternalForce, ElementBlocksGiveTheAssembledProduct) {
  // The element-by-element product against Eigen's sparse K U on scenes with supports (S2's pin
  // and roller), rods (S1) and inclined frames: the same sums in another order, so equal to
  // roundoff (1e-13 of the largest term's size).
  for (const Model& m :
       {Model(load_scene(testing::paper_scene("s2_transverse")), true),
        Model(load_scene(testing::paper_scene("s1_central")), false), Model(inclined(1.0472), true)}) {
    const InternalForce f(m, std::vector<bool>(2, false));
    EXPECT_TRUE(f.element_blocks());  // else apply() is K U itself and this compares nothing
    Eigen::VectorXd U(m.size()), out(m.size());
    for (int i = 0; i < m.size(); ++i) U(i) = std::sin(1.7 * i + 0.3);
    f.apply(U, out);
    const Eigen::VectorXd ref = m.K() * U;
    const double scale = m.K().cwiseAbs().toDense().maxCoeff() * U.cwiseAbs().maxCoeff();
    EXPECT_LE((out - ref).cwiseAbs().maxCoeff(), 1e-13 * scale);
  }
}

TEST(InternalForce, StreamedProductHandsOverEachEquationOnceAndFinal) {
  // apply_streamed() against Eigen's sparse K U: every equation is handed over exactly once, and
  // its value at that moment is already the final one (equal to K U to the roundoff of the sums,
  // 1e-13 of the largest term's size), on layouts that break the chain: supports at both ends and
  // a clamp mid-span, a free rigid body (equations no element touches), several inclined bodies,
  // the rod layout.
  Scene s;
  s.file = "test";
  Body a = soft_body("A", {0, 0}, {4, 3}, 8);
  a.supports = {Support{0, true, true, false}, Support{3, true, true, true}, Support{8, false, true, false}};
  Body r = soft_body("R", {10, 0}, {11, 0}, 2);
  r.rigid = true;
  s.bodies = {a, r, soft_body("C", {0, 5}, {6, 9}, 6)};
  for (const Model& m : {Model(s, true), Model(load_scene(testing::paper_scene("s1_central")), false),
                         Model(load_scene(testing::paper_scene("s2_transverse"),
                                          {"bodies.A.elements=100", "bodies.B.elements=100"}),
                               true)}) {  // S2 refined: hand-overs in several batches
    const InternalForce f(m, std::vector<bool>(m.num_bodies(), false));
    ASSERT_TRUE(f.element_blocks());  // else apply_streamed() is apply() and one hand-over
    Eigen::VectorXd U(m.size()), out(m.size());
    for (int i = 0; i < m.size(); ++i) U(i) = std::sin(1.7 * i + 0.3);
    const Eigen::VectorXd ref = m.K() * U;
    const double scale = m.K().cwiseAbs().toDense().maxCoeff() * U.cwiseAbs().maxCoeff();
    std::vector<int> handed(m.size(), 0);
    double worst = 0.0;
    f.apply_streamed(U, out, [&](int lo, int hi) {
      for (int i = lo; i < hi; ++i) {
        ++handed[i];
        worst = std::max(worst, std::abs(out(i) - ref(i)));
      }
    });
    for (int i = 0; i < m.size(); ++i) EXPECT_EQ(handed[i], 1) << "equation " << i;
    EXPECT_LE(worst, 1e-13 * scale);
  }
}

/// The layouts of the streamed test: supports at both ends and a clamp mid-span, a free rigid
/// body, several inclined bodies (spans of one element between chains); S1's rods; S2 refined.
std::vector<Model> split_layouts() {
  Scene s;
  s.file = "test";
  Body a = soft_body("A", {0, 0}, {4, 3}, 8);
  a.supports = {Support{0, true, true, false}, Support{3, true, true, true}, Support{8, false, true, false}};
  Body r = soft_body("R", {10, 0}, {11, 0}, 2);
  r.rigid = true;
  s.bodies = {a, r, soft_body("C", {0, 5}, {6, 9}, 6)};
  std::vector<Model> m;
  m.emplace_back(s, true);
  m.emplace_back(load_scene(testing::paper_scene("s1_central")), false);
  m.emplace_back(
      load_scene(testing::paper_scene("s2_transverse"), {"bodies.A.elements=7", "bodies.B.elements=9"}),
      true);
  return m;
}

TEST(InternalForce, EverySplitGivesTheBitsOfTheWholeProduct) {
  // Each entry of f is 0.0 plus its elements' row sums in element order, whatever the split: the
  // first part touching an equation sums its own terms, the later parts' are added after them
  // in part order. So the split product has the same bits (no tolerance), for every number of
  // parts, i.e. every position of a range boundary: inside a chain, at a chain's first or last
  // element, at a support, between bodies. The parts run here in reverse order (they may run in
  // any), into an f of NaN: every entry must be written, each handed over exactly once.
  for (const Model& m : split_layouts()) {
    InternalForce f(m, std::vector<bool>(m.num_bodies(), false));
    ASSERT_TRUE(f.element_blocks());
    Eigen::VectorXd U(m.size()), whole(m.size());
    for (int i = 0; i < m.size(); ++i) U(i) = std::sin(1.7 * i + 0.3);
    f.apply_streamed(U, whole, [](int, int) {});
    int elastic = 0;
    for (int e = 0; e < static_cast<int>(m.elements().size()); ++e) elastic += m.element_group(e) >= 0;
    for (int parts = 2; 2 * parts <= elastic; ++parts) {
      ASSERT_EQ(f.set_parts(parts), parts) << m.size() << " DOFs";
      Eigen::VectorXd split = Eigen::VectorXd::Constant(m.size(), std::nan(""));
      std::vector<int> handed(m.size(), 0);
      auto count = [&](int lo, int hi) {
        for (int i = lo; i < hi; ++i) ++handed[i];
      };
      for (int t = parts - 1; t >= 0; --t) f.apply_part(t, U, split, count);
      f.finish_parts(split, count);
      for (int i = 0; i < m.size(); ++i) {
        EXPECT_EQ(handed[i], 1) << parts << " parts, equation " << i;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(split(i)), std::bit_cast<std::uint64_t>(whole(i)))
            << parts << " parts, equation " << i << ": " << split(i) << " vs " << whole(i);
      }
    }
    EXPECT_EQ(f.set_parts(elastic / 2 + 1), 1) << "fewer than two elements a part";
    EXPECT_EQ(f.set_parts(1), 1);
  }
}

TEST(InternalForce, CorotationalEqualsLinearForSmallMotion) {
  // For displacements of size eps the corotational force differs from K U by O(eps^2).
  for (double angle : {0.0, 1.0472, 2.2}) {
    const Model m(inclined(angle), true);
    const InternalForce lin(m, {false, false}), cr(m, {true, false});
    Eigen::VectorXd U = Eigen::VectorXd::Zero(m.size());
    for (int i = 0; i < m.size(); ++i) U(i) = 1e-6 * std::sin(1.7 * i + 0.3);
    Eigen::VectorXd fl(m.size()), fc(m.size());
    lin.apply(U, fl);
    cr.apply(U, fc);
    EXPECT_LT((fl - fc).norm(), 1e-4 * fl.norm()) << "angle " << angle;  // relative O(eps / h) ~ 1e-6
    EXPECT_NEAR(cr.strain_energy(U), lin.strain_energy(U), 1e-4 * lin.strain_energy(U));
  }
}

class RigidRotation : public ::testing::TestWithParam<double> {};

TEST_P(RigidRotation, CorotationalIsForceFree) {
  // Rotate body A rigidly about its first node: no strain, no force (the linear element sees a
  // spurious stretch of order the rotation squared). Angles past pi check the branch of the chord
  // angle: a spinning body's nodal rotations keep growing while atan2 wraps.
  const Model m(inclined(0.5), true);
  const InternalForce cr(m, {true, false}), lin(m, {false, false});
  const double phi = GetParam() * M_PI / 180.0, c = std::cos(phi) - 1.0, s = std::sin(phi);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(m.size());
  for (int n = 0; n < 4; ++n) {
    const Vec2 x = m.node_position(n);
    U(m.equation(n, 0)) = c * x[0] - s * x[1];
    U(m.equation(n, 1)) = s * x[0] + c * x[1];
    U(m.equation(n, 2)) = phi;
  }
  Eigen::VectorXd f(m.size()), fl(m.size());
  cr.apply(U, f);
  lin.apply(U, fl);
  EXPECT_LT(f.norm(), 1e-9 * fl.norm());
  EXPECT_LT(cr.strain_energy(U), 1e-12 * lin.strain_energy(U));
}

INSTANTIATE_TEST_SUITE_P(Angles, RigidRotation, ::testing::Values(40.0, 179.0, 181.0, 250.0, -200.0, 725.0));

}  // namespace
}  // namespace beamimpact::paper
