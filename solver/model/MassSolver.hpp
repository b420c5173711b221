#pragma once
/// @file MassSolver.hpp
/// @brief Applies M^-1 without ever forming it: an elementwise divide for lumped mass, a sparse
/// LDL^T solve (factorised once) for consistent mass. O(n) resp. O(nnz(L)) per application.

#include <memory>

#include <Eigen/SparseCholesky>

#include <solver/model/Model.hpp>

namespace beamimpact {

/// @brief x = M^-1 b for the model's mass.
class MassSolver {
 public:
  /// @brief Factorises M (consistent) or stores 1/m (lumped). Throws if M is singular.
  explicit MassSolver(const Model& model);
  /// @brief Factorises a consistent M whose sparsity differs from the model's (symbolic and
  /// numeric): a rotating body's M_A(t) holds entries that are exactly zero in the reference
  /// frame of an axis-aligned body and were never stored in the model's M.
  void factorize_pattern(const SparseMatrix& M);
  /// @brief New values of a consistent M with the pattern last analysed (model's M or the one
  /// given to factorize_pattern()): numeric refactorisation only. Throws std::logic_error when
  /// the pattern differs (a numeric factorisation on another pattern corrupts memory).
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
  Eigen::Index pattern_nnz_ = 0, pattern_rows_ = 0;  ///< of the analysed pattern
};

}  // namespace beamimpact
