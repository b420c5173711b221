// The largest eigenvalue of banded pencils by inertia and Laguerre's iteration, against Eigen's
// dense generalized solver.
#include <solver/model/top_eigenvalue.hpp>

#include <random>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

namespace beamimpact {
namespace {

/// A chain of `elements` random 6x6 element blocks overlapping by 3 DOFs (a frame's envelope):
/// K = sum B^T B (positive semi-definite), M lumped (positive diagonal) or consistent (the same
/// pattern, diagonally dominant).
void chain(int elements, bool consistent, unsigned seed, Eigen::MatrixXd& K, Eigen::MatrixXd& M) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int d = 3 * elements + 3;
  K.setZero(d, d);
  M.setZero(d, d);
  for (int e = 0; e < elements; ++e) {
    Eigen::MatrixXd B(6, 6), C(6, 6);
    for (int i = 0; i < 36; ++i) B(i) = u(g), C(i) = u(g);
    K.block(3 * e, 3 * e, 6, 6) += B.transpose() * B;
    if (consistent) M.block(3 * e, 3 * e, 6, 6) += 0.05 * C.transpose() * C + Eigen::MatrixXd::Identity(6, 6);
  }
  if (!consistent)
    for (int i = 0; i < d; ++i) M(i, i) = 1.0 + 0.9 * u(g);
}

double dense_top(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M, Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();
}

TEST(TopEigenvalue, MatchesTheDenseSolveFromAnyStartAbove) {
  // 1e-13 relative: both are exact up to roundoff of O(d) operations on entries of size |K|
  // (measured up to 17 eps); the iteration proves each of its iterates above by its pivots.
  for (bool consistent : {false, true})
    for (int elements : {1, 4, 16, 32})
      for (unsigned seed : {1u, 2u, 3u})
        for (double start : {1.001, 1.1, 10.0}) {
          Eigen::MatrixXd K, M;
          chain(elements, consistent, seed, K, M);
          const double top = dense_top(K, M);
          const TopEigenvalue r = top_eigenvalue(EnvelopePencil::from_dense(K, M), start * top);
          ASSERT_TRUE(r.ok);
          EXPECT_NEAR(r.upper, top, 1e-13 * top) << elements << " " << consistent << " " << start;
          EXPECT_LE(r.lower, top * (1 + 1e-13));
          EXPECT_GE(r.lower, top * (1 - 1e-12));  // G's roundoff near the root: a bracket, not an exact value
          EXPECT_LE(r.factorizations, 16);        // cubic convergence: 10 passes at most here
        }
}

TEST(TopEigenvalue, InertiaSeparatesValuesAboveAndBelowTheTop) {
  Eigen::MatrixXd K, M;
  chain(20, false, 7, K, M);
  const double top = dense_top(K, M);
  const EnvelopePencil p = EnvelopePencil::from_dense(K, M);
  EXPECT_TRUE(above_spectrum(p, top * (1 + 1e-9)));
  EXPECT_FALSE(above_spectrum(p, top * (1 - 1e-9)));
  EXPECT_FALSE(top_eigenvalue(p, top * (1 - 1e-9)).ok);  // a start below the top is refused
}

TEST(TopEigenvalue, ADoubleTopFromTwoEqualBlocksConvergesInAFewPasses) {
  // Two uncoupled copies: the largest eigenvalue is double, where Laguerre's order drops.
  Eigen::MatrixXd K1, M1;
  chain(8, false, 5, K1, M1);
  const Eigen::Index d = K1.rows();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * d, 2 * d), M = K;
  K.topLeftCorner(d, d) = K.bottomRightCorner(d, d) = K1;
  M.topLeftCorner(d, d) = M.bottomRightCorner(d, d) = M1;
  const double top = dense_top(K1, M1);
  for (double start : {1.01, 1.1, 2.0}) {
    const TopEigenvalue r = top_eigenvalue(EnvelopePencil::from_dense(K, M), start * top);
    ASSERT_TRUE(r.ok);
    EXPECT_NEAR(r.upper, top, 1e-13 * top);
    // Laguerre's step alone only halves the distance to a double root per pass: 26-29 passes
    // here. The lane that takes the root as double lands on it: 5-8.
    EXPECT_LE(r.factorizations, 10) << start;
  }
}

TEST(TopEigenvalue, AZeroMassIsRefused) {
  // A DOF with stiffness and no mass: infinite frequency, sigma M - K is never positive definite.
  Eigen::MatrixXd K, M;
  chain(3, false, 9, K, M);
  M(4, 4) = 0.0;
  EXPECT_FALSE(top_eigenvalue(EnvelopePencil::from_dense(K, M), 1e12).ok);
}

}  // namespace
}  // namespace beamimpact
