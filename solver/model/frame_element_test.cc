// Element matrices checked against mechanics: rigid-body modes carry no force, mass totals.
#include <solver/model/frame_element.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace beamimpact {
namespace {

constexpr double kE = 2.0e11, kA = 0.02, kI = 3.0e-5, kL = 1.7, kRho = 7800.0;

// A rigid motion (translation + small rotation about node 1) in global axes of an element at angle a.
Vec6 rigid_mode(double a, double ux, double uy, double th) {
  const double dx = kL * std::cos(a), dy = kL * std::sin(a);
  Vec6 u;
  u << ux, uy, th, ux - th * dy, uy + th * dx, th;  // linearised rotation: u = th x r
  return u;
}

TEST(FrameElement, RigidBodyModesGiveZeroForce) {
  // K u = 0 for the three rigid modes, at any orientation; tolerance is roundoff relative to
  // the largest stiffness entry times the motion (1e-12).
  for (double a : {0.0, 0.3, M_PI / 2, 2.5, -1.1}) {
    const Mat6 K = to_global(frame_stiffness_local(kE, kA, kI, kL), std::cos(a), std::sin(a));
    for (const Vec6& u : {rigid_mode(a, 1, 0, 0), rigid_mode(a, 0, 1, 0), rigid_mode(a, 0, 0, 1e-3)}) {
      const double scale = K.cwiseAbs().maxCoeff() * u.cwiseAbs().maxCoeff();
      EXPECT_LT((K * u).cwiseAbs().maxCoeff(), 1e-12 * scale) << "angle " << a;
    }
  }
}

TEST(FrameElement, StiffnessHasRankThreeAndIsSymmetric) {
  const Mat6 K = to_global(frame_stiffness_local(kE, kA, kI, kL), std::cos(0.7), std::sin(0.7));
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-9 * K.cwiseAbs().maxCoeff());
  Eigen::SelfAdjointEigenSolver<Mat6> es(K);
  const double top = es.eigenvalues().maxCoeff();
  int zero = 0;
  for (int i = 0; i < 6; ++i) zero += std::abs(es.eigenvalues()(i)) < 1e-10 * top;
  EXPECT_EQ(zero, 3);  // exactly the three rigid modes
}

TEST(FrameElement, MassCarriesTheElementMassInEveryDirection) {
  const double m = kRho * kA * kL;
  for (double a : {0.0, 0.9}) {
    const Mat6 Mc = to_global(frame_mass_consistent_local(kRho, kA, kL), std::cos(a), std::sin(a));
    const Vec6 tx = rigid_mode(a, 1, 0, 0), ty = rigid_mode(a, 0, 1, 0);
    // Kinetic energy of a unit translation is m/2 in any direction (translation is exact in both bases).
    EXPECT_NEAR(tx.dot(Mc * tx), m, 1e-12 * m);
    EXPECT_NEAR(ty.dot(Mc * ty), m, 1e-12 * m);
  }
  const Vec6 d = frame_mass_lumped(kRho, kA, kI, kL, RotaryInertia::kHrz);
  EXPECT_DOUBLE_EQ(d(0) + d(3), m);
  EXPECT_DOUBLE_EQ(d(2), m * kL * kL / 78.0);  // HRZ rotary inertia of the Hermite beam
  EXPECT_DOUBLE_EQ(frame_mass_lumped(kRho, kA, kI, kL, RotaryInertia::kSection)(2), kRho * kI * kL / 2);
}

TEST(FrameElement, RotationIsOrthogonal) {
  const Mat6 T = frame_rotation(std::cos(1.2), std::sin(1.2));
  EXPECT_LT((T * T.transpose() - Mat6::Identity()).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(BarElement, RigidTranslationAndMass) {
  const Eigen::Matrix2d K = bar_stiffness(kE, kA, kL);
  EXPECT_LT((K * Eigen::Vector2d(1, 1)).norm(), 1e-6);  // EA/L ~ 2e9: roundoff 1e-6 absolute
  EXPECT_DOUBLE_EQ(bar_mass_lumped(kRho, kA, kL).sum(), kRho * kA * kL);
  EXPECT_NEAR(bar_mass_consistent(kRho, kA, kL).sum(), kRho * kA * kL, 1e-12 * kRho * kA * kL);
}

}  // namespace
}  // namespace beamimpact
