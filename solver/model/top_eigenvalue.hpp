#pragma once
/// @file top_eigenvalue.hpp
/// @brief Largest eigenvalue of a small symmetric pencil K x = lambda M x (M positive definite)
/// whose entries lie in a narrow envelope (a chain of beam elements), from the inertia of
/// sigma M - K: by Sylvester's law it has as many negative pivots in its LDL^T as the pencil has
/// eigenvalues above sigma, so all pivots positive proves sigma > lambda_max. Laguerre's
/// iteration on det(sigma M - K) = det(M) prod(sigma - lambda_i) (a polynomial with real roots
/// only) moves down from any sigma above the largest root and never below it (in exact
/// arithmetic): cubically once sigma - lambda_max is below the gap to the next eigenvalue,
/// linearly (a factor 0.3-0.6 per iterate) while a cluster of eigenvalues lies below. A chain's
/// top is often such a cluster: a close pair of modes, one at each end of the run. So each pass
/// factors two trial values at once: Laguerre's step, and the step that takes the top root as
/// double, which is kept when its pivots prove it above (the recurrence's chain of dependent
/// operations, not its arithmetic, sets the time, so a second lane costs little). From Irons'
/// bound a 16-element frame run takes 6 passes (9 with Laguerre's step alone), a 32-element run
/// 11 (15). Every iterate is checked by its pivots, so the answer is a proven upper bound of
/// lambda_max up to the factorization's roundoff. Cost: O(d w^2) per pass for a d x d pencil of
/// envelope width w, against O(d^3) for a dense eigen-solve.

#include <vector>

#include <Eigen/Core>

namespace beamimpact {

/// @brief A symmetric pencil (K, M) stored by rows within its envelope: row i holds columns
/// first(i)..i of both matrices (the lower triangle), packed one row after another. LDL^T fills
/// nothing outside the envelope.
class EnvelopePencil {
 public:
  /// @brief A pencil whose row i starts at column first[i] (<= i), all entries zero.
  explicit EnvelopePencil(std::vector<int> first);
  /// @brief The envelope of dense symmetric K and M (lower triangles read).
  static EnvelopePencil from_dense(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M);

  /// @brief Number of rows d.
  int size() const { return static_cast<int>(first_.size()); }
  /// @brief The first column of row i's envelope.
  int first(int i) const { return first_[i]; }
  /// @brief Where row i starts in the packed storage (entries first(i)..i).
  int row_offset(int i) const { return offset_[i]; }
  /// @brief Entries stored (both triangles' envelope counted once, diagonal included).
  int packed_size() const { return offset_.back(); }
  /// @brief Adds k to K(i, j) and m to M(i, j), first(i) <= j <= i.
  void add(int i, int j, double k, double m) {
    k_[offset_[i] + j - first_[i]] += k;
    m_[offset_[i] + j - first_[i]] += m;
  }
  /// @brief K(i, j), first(i) <= j <= i.
  double k(int i, int j) const { return k_[offset_[i] + j - first_[i]]; }
  /// @brief M(i, j), first(i) <= j <= i.
  double m(int i, int j) const { return m_[offset_[i] + j - first_[i]]; }
  /// @brief K and M as dense symmetric matrices (for dense solvers).
  void to_dense(Eigen::MatrixXd& K, Eigen::MatrixXd& M) const;

 private:
  std::vector<int> first_, offset_;
  std::vector<double> k_, m_;
};

/// @brief Result of top_eigenvalue().
struct TopEigenvalue {
  bool ok = false;     ///< false: sigma M - K was not positive definite at the start (start below
                       ///< lambda_max, or M not positive definite); upper and lower are then 0
  double upper = 0.0;  ///< the lowest sigma proven above lambda_max (all pivots positive)
  double lower = 0.0;  ///< sigma - d / G(sigma) at that sigma (G = sum 1/(sigma - lambda_i)): a lower bound
  int factorizations = 0;  ///< factorization passes used (each factors one or two trial values)
};

/// @brief Proves `sigma` above the largest eigenvalue of (K, M): true when every pivot of the
/// LDL^T of sigma M - K is positive.
/// @param p the pencil
/// @param sigma the trial bound
bool above_spectrum(const EnvelopePencil& p, double sigma);

/// @brief Largest eigenvalue of (K, M) by Laguerre's iteration from `start` downwards.
/// @param p the pencil (M positive definite)
/// @param start a value above lambda_max (e.g. Irons' element bound), checked by its pivots
TopEigenvalue top_eigenvalue(const EnvelopePencil& p, double start);

}  // namespace beamimpact
