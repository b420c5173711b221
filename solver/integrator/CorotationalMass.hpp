#pragma once
/// @file CorotationalMass.hpp
/// @brief The consistent mass M_A(t) of rotating bodies (paper Eq. 22): each corotational
/// element's T(alpha)^T M_local T(alpha) at its current chord angle, updated in place on a fixed
/// sparsity pattern. Only the corotational elements are recomputed; a lumped mass never needs this
/// (it is the same in every frame).

#include <solver/integrator/InternalForce.hpp>

namespace beamimpact::paper {

/// @brief M(U) = M of the other elements + sum of the rotating elements' rotated mass.
class CorotationalMass {
 public:
  /// @brief model: consistent mass; fint: knows the corotational elements and their chords.
  CorotationalMass(const Model& model, const InternalForce& fint);
  /// @brief Rebuilds M for the configuration U (no allocation).
  void update(const Eigen::VectorXd& U);
  /// @brief The current mass (free x free).
  const SparseMatrix& M() const { return M_; }
  /// @brief Momentum covector of body b along direction c at the current angles: m^T V.
  double momentum(int b, int c, const Eigen::VectorXd& V) const;

 private:
  const Model& model_;
  const InternalForce& fint_;
  SparseMatrix M_, M_fixed_;  ///< current; non-rotating part (same pattern)
  std::vector<Vec2> dir_;     ///< current chord direction of each corotational element
  std::vector<char> rotating_body_;
};

}  // namespace beamimpact::paper
