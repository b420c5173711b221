#pragma once
/// @file MassSolver.hpp
/// @brief Applies M^-1 without ever forming it: an elementwise divide for lumped mass, a sparse
/// LDL^T solve (factorised once) for consistent mass. O(n) resp. O(nnz(L)) per application.

#include <memory>

#include <Eigen/SparseCholesky>

#include <beamimpact/model/Model.hpp>

namespace beamimpact {

/// @brief x = M^-1 b for the model's mass.
class MassSolver {
 public:
  /// @brief Factorises M (consistent) or stores 1/m (lumped). Throws if M is singular.
  explicit MassSolver(const Model& model);
  /// @brief New values of a consistent M with the same sparsity (a rotating body's M_A(t)):
  /// numeric refactorisation only, the symbolic analysis is kept.
  void refactor(const SparseMatrix& M);
  /// @brief out = M^-1 in (out may not alias in for consistent mass).
  void apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) const;
  /// @brief True for the diagonal case (then inverse_diagonal() is M^-1).
  bool diagonal() const { return ldlt_ == nullptr; }
  /// @brief 1/m per equation (lumped mass only).
  const Eigen::VectorXd& inverse_diagonal() const { return inv_; }

 private:
  Eigen::VectorXd inv_;
  std::unique_ptr<Eigen::SimplicialLDLT<SparseMatrix>> ldlt_;
};

}  // namespace beamimpact
