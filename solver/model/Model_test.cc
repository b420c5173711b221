// The assembled model against beam and rod theory: natural frequencies converge to the exact
// ones at the order the discretisation predicts.
#include <solver/model/Model.hpp>

#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

using testing::soft_body;

/// Scene with one body to study (and a far-away dummy body, scenes need two).
Scene single(const Body& b, MassKind mass) {
  Scene s;
  s.file = "test";
  // On b's line, far beyond its end: keeps the scene collinear when b is (rod layout).
  const Vec2 d{b.end[0] - b.start[0], b.end[1] - b.start[1]};
  s.bodies = {b, soft_body("far", {b.start[0] + 10 * d[0], b.start[1] + 10 * d[1]},
                           {b.start[0] + 11 * d[0], b.start[1] + 11 * d[1]}, 1)};
  s.model.mass = mass;
  return s;
}

/// Sorted generalized eigenvalues omega^2 of the model, restricted to body 0's equations.
Eigen::VectorXd omegas(const Model& m) {
  // The dummy body adds its own modes; it is far and free: its rigid and (high) elastic modes are
  // filtered below by taking body-0 modes only, through the equations of body 0.
  std::vector<int> eqs;
  for (int n = 0; n < m.num_nodes(); ++n)
    if (m.body_of_node(n) == 0)
      for (int c = 0; c < m.dofs_per_node(); ++c)
        if (m.equation(n, c) >= 0) eqs.push_back(m.equation(n, c));
  const int k = static_cast<int>(eqs.size());
  Eigen::MatrixXd K(k, k), M(k, k);
  const Eigen::MatrixXd Kd(m.K()), Md(m.M());
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      K(i, j) = Kd(eqs[i], eqs[j]);
      M(i, j) = Md(eqs[i], eqs[j]);
    }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M);
  return es.eigenvalues().cwiseMax(0.0).cwiseSqrt();
}

/// Relative error of the first simply supported bending frequency with n elements.
double ss_error(int n, MassKind mass, RotaryInertia rot) {
  Body b = soft_body("B", {0, 0}, {10, 0}, n);
  b.supports = {{0, true, true, false}, {n, false, true, false}};
  Scene s = single(b, mass);
  s.model.rotary_inertia = rot;
  const Model m(s, true);
  // Exact Euler-Bernoulli: omega_1 = (pi/L)^2 sqrt(EI / (rho A)).
  const double exact = std::pow(M_PI / 10.0, 2) * std::sqrt(b.E * b.inertia / (b.rho * b.area));
  // The lowest non-zero frequency: the body's axial rigid mode is held by the pin; the first mode
  // is bending (axial modes are far higher for this slender beam).
  return std::abs(omegas(m)(0) - exact) / exact;
}

TEST(Model, SimplySupportedBendingFrequencyConvergesSecondOrderWithLumpedMass) {
  const double e8 = ss_error(8, MassKind::kLumped, RotaryInertia::kHrz);
  const double e16 = ss_error(16, MassKind::kLumped, RotaryInertia::kHrz);
  const double e32 = ss_error(32, MassKind::kLumped, RotaryInertia::kHrz);
  const double p1 = std::log2(e8 / e16), p2 = std::log2(e16 / e32);
  // Lumped mass: frequency error O(h^2). Observed orders within 0.2 of 2 once asymptotic.
  EXPECT_NEAR(p2, 2.0, 0.2) << e8 << " " << e16 << " " << e32;
  EXPECT_NEAR(p1, 2.0, 0.3);
  EXPECT_LT(e32, 1e-3);
}

TEST(Model, SimplySupportedBendingFrequencyConvergesFourthOrderWithConsistentMass) {
  const double e4 = ss_error(4, MassKind::kConsistent, RotaryInertia::kHrz);
  const double e8 = ss_error(8, MassKind::kConsistent, RotaryInertia::kHrz);
  const double e16 = ss_error(16, MassKind::kConsistent, RotaryInertia::kHrz);
  // Hermite cubics with consistent mass: frequency error O(h^4).
  EXPECT_NEAR(std::log2(e8 / e16), 4.0, 0.3) << e4 << " " << e8 << " " << e16;
  EXPECT_LT(e16, 1e-5);
}

TEST(Model, HigherSimplySupportedModesConverge) {
  // Mode n = 1..3 at 64 elements within 0.5 % of (n pi / L)^2 sqrt(EI / rho A): the lumped
  // O((n h / L)^2) error is 0.3 % for n = 3.
  const int n = 64;
  Body b = soft_body("B", {0, 0}, {10, 0}, n);
  b.supports = {{0, true, true, false}, {n, false, true, false}};
  const Model m(single(b, MassKind::kLumped), true);
  const Eigen::VectorXd w = omegas(m);
  const double c = std::sqrt(b.E * b.inertia / (b.rho * b.area));
  for (int k = 1; k <= 3; ++k)
    EXPECT_NEAR(w(k - 1), std::pow(k * M_PI / 10.0, 2) * c, 5e-3 * std::pow(k * M_PI / 10.0, 2) * c);
}

TEST(Model, FreeRodAxialFrequenciesConvergeSecondOrder) {
  auto err = [](int n) {
    const Model m(single(soft_body("A", {0, 0}, {10, 0}, n), MassKind::kLumped), false);
    const Eigen::VectorXd w = omegas(m);
    EXPECT_NEAR(w(0), 0.0, 1e-6);             // the rigid mode
    const double exact = M_PI * 10.0 / 10.0;  // omega_1 = pi c / L, c = 10 m/s
    return std::abs(w(1) - exact) / exact;
  };
  const double e10 = err(10), e20 = err(20), e40 = err(40);
  // Lumped rod: omega_k = (2c/h) sin(k pi h / (2L)), error ~ (k pi h / L)^2 / 24: order 2.
  EXPECT_NEAR(std::log2(e10 / e20), 2.0, 0.05);
  EXPECT_NEAR(std::log2(e20 / e40), 2.0, 0.05);
  EXPECT_NEAR(e10, std::pow(M_PI / 10.0, 2) / 24.0, 0.05 * e10);  // the leading term itself
}

TEST(Model, RodLayoutNeedsACollinearScene) {
  Scene s = single(soft_body("A", {0, 0}, {10, 0}, 4), MassKind::kLumped);
  s.bodies[1] = soft_body("B", {0, 1}, {10, 1}, 4);  // parallel but offset: not one line
  EXPECT_THROW(Model(s, false), InputError);
}

TEST(Model, MomentumCovectorGivesRigidMomentum) {
  // A rigid translation v carries momentum m v, for lumped and consistent mass alike.
  for (MassKind mk : {MassKind::kLumped, MassKind::kConsistent}) {
    Body a = soft_body("A", {0, 0}, {3, 4}, 5, {0.3, -0.7});
    Scene s = single(a, mk);
    const Model m(s, true);
    const Eigen::VectorXd v = m.initial_velocity();
    const double mass = a.rho * a.area * 5.0;
    EXPECT_NEAR(m.body_mass(0), mass, 1e-12);
    EXPECT_NEAR(m.momentum_covector(0, 0).dot(v), 0.3 * mass, 1e-12);
    EXPECT_NEAR(m.momentum_covector(0, 1).dot(v), -0.7 * mass, 1e-12);
  }
}

TEST(Model, StiffnessAndMassAreTheTripletAssemblyOfTheElementMatrices) {
  // K and M against Eigen's setFromTriplets over the element matrices in element order (the
  // assembly of earlier versions): equal to the last bit, pattern and values, for frames and
  // rods, lumped and consistent, with supports, a mid-span support and an inclined body (whose
  // global matrices are not exactly symmetric in floating point).
  Body a = soft_body("A", {0, 0}, {3, 4}, 7, {0.3, -0.7});
  a.supports = {Support{0, true, true, false}, Support{4, false, true, false}};
  const Model models[] = {Model(single(a, MassKind::kLumped), true),
                          Model(single(a, MassKind::kConsistent), true),
                          Model(load_scene(testing::paper_scene("s4_oblique_45")), true),
                          Model(load_scene(testing::paper_scene("s1_central")), false)};
  for (const Model& m : models) {
    std::vector<Eigen::Triplet<double>> kt, mt;
    for (int e = 0; e < static_cast<int>(m.elements().size()); ++e) {
      const Model::Element& el = m.elements()[e];
      if (el.rigid) continue;
      const Eigen::MatrixXd Ke = m.element_stiffness(e, el.c, el.s), Me = m.element_mass(e, el.c, el.s);
      const Eigen::Matrix<int, 6, 1> eq = m.element_equations(e);
      for (int i = 0; i < Ke.rows(); ++i)
        for (int j = 0; j < Ke.cols(); ++j) {
          if (eq(i) < 0 || eq(j) < 0) continue;
          if (Ke(i, j) != 0.0) kt.emplace_back(eq(i), eq(j), Ke(i, j));
          if (Me(i, j) != 0.0) mt.emplace_back(eq(i), eq(j), Me(i, j));
        }
    }
    SparseMatrix K(m.size(), m.size()), M(m.size(), m.size());
    K.setFromTriplets(kt.begin(), kt.end());
    M.setFromTriplets(mt.begin(), mt.end());
    ASSERT_EQ(m.K().nonZeros(), K.nonZeros());
    EXPECT_EQ((m.K() - K).cwiseAbs().sum(), 0.0);
    ASSERT_EQ(m.M().nonZeros(), M.nonZeros());
    EXPECT_EQ((m.M() - M).cwiseAbs().sum(), 0.0);
  }
}

}  // namespace
}  // namespace beamimpact

namespace beamimpact {
namespace {

/// All generalized eigenvalues omega^2 of (K, M) of the whole model, sorted.
Eigen::VectorXd all_omega2(const Model& m) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(m.K()),
                                                               Eigen::MatrixXd(m.M()));
  return es.eigenvalues();
}

// A structure rotated with its supports has the same natural frequencies (a rigid rotation of
// the reference configuration changes no strain energy or kinetic energy). S2's two beams
// rotated by 37 and 90 degrees, the target's roller across it (fix = ["normal"]): every
// omega^2 of the model equals S2's. Tolerance: the dense eigen-solver's roundoff, 1e-9 of the
// largest omega^2 (cond(M) ~ 1e3 from HRZ rotary inertia, times 1e-15 and the matrix size).
TEST(ModelBodyAxes, RotatedModelHasTheSameFrequencies) {
  const Model s2(testing::load_paper_scene("s2_transverse"), true);
  const Eigen::VectorXd w2 = all_omega2(s2);
  for (double degrees : {37.0, 90.0}) {
    const Model r(testing::rotated_s2(degrees), true);
    ASSERT_EQ(r.size(), s2.size()) << degrees;
    const Eigen::VectorXd w = all_omega2(r);
    EXPECT_LT((w - w2).cwiseAbs().maxCoeff(), 1e-9 * w2.maxCoeff()) << degrees;
    // The roller's node turns with the body at 37 degrees: its free translation is along B.
    const int end = r.node_id(1, 10);
    EXPECT_EQ(r.rotated(end), degrees == 37.0) << degrees;
  }
  // The global roller ("y") left on the target at 37 degrees is another problem: some omega^2
  // moves by more than 1e-3 relative (the roller holds a slanted direction).
  const Eigen::VectorXd g = all_omega2(Model(testing::rotated_s2(37.0, true), true));
  EXPECT_GT(((g - w2).cwiseAbs().array() / (w2.array().abs() + 1e-300)).maxCoeff(), 1e-3);
}

// Mixed global and body axes at one node hold what their directions span: ["x", "normal"] on
// the target at 37 degrees holds two directions (a pin: one equation fewer than S2's roller);
// at 90 degrees "normal" is -x, one direction: S2's roller again, with S2's frequencies.
TEST(ModelBodyAxes, MixedGlobalAndBodyAxesHoldTheDirectionsTheySpan) {
  const Model s2(testing::load_paper_scene("s2_transverse"), true);
  for (double degrees : {37.0, 90.0}) {
    Scene s = testing::rotated_s2(degrees);
    s.bodies[1].supports[1].fix_x = true;  // with fix_normal
    const Model m(s, true);
    EXPECT_EQ(m.size(), degrees == 90.0 ? s2.size() : s2.size() - 1) << degrees;
    if (degrees == 90.0) {
      EXPECT_LT((all_omega2(m) - all_omega2(s2)).cwiseAbs().maxCoeff(), 1e-9 * all_omega2(s2).maxCoeff());
    }
  }
}

// The momentum covector and the initial velocity see global axes at a rotated node: B at rest
// moved rigidly by (vx, vy) has momentum m_B (vx, vy) (m_B = rho A L = 4 kg) although its end
// node's translations are in B's axes; the roller holds the normal part, so only a velocity
// along B is admissible there: take v along B.
TEST(ModelBodyAxes, TranslationAndMomentumInGlobalAxesAtARotatedNode) {
  const Scene s = testing::rotated_s2(37.0);
  const Model m(s, true);
  const Vec2 a = s.bodies[1].axis();
  std::vector<Vec2> d(2, Vec2{0.0, 0.0});
  d[1] = a;
  const Eigen::VectorXd V = m.translation(d);
  const int end = m.node_id(1, 10);
  const Vec2 u = m.node_vector(V, end);
  EXPECT_NEAR(u[0], a[0], 1e-15);
  EXPECT_NEAR(u[1], a[1], 1e-15);
  // The pin holds B's start, so the rigid translation lacks that node's mass: 4 kg minus the
  // end node's lumped half element (rho A le / 2 = 0.2 kg).
  for (int c = 0; c < 2; ++c) EXPECT_NEAR(m.momentum_covector(1, c).dot(V), 3.8 * a[c], 1e-13) << c;
}

}  // namespace
}  // namespace beamimpact
