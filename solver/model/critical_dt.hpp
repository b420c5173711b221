#pragma once
/// @file critical_dt.hpp
/// @brief Stability limit of explicit central differences for the assembled model:
/// dt_crit = 2 / omega_max (reduced for Rayleigh damping), omega_max^2 the largest eigenvalue of
/// M^-1 K from Lanczos on the sparse operator: O(nnz) per iteration, no dense eigen-solve.

#include <string>

#include <beamimpact/model/Model.hpp>

namespace beamimpact {

/// @brief The critical step and how it was found.
struct CriticalStep {
  double omega_max = 0.0;         ///< rad/s, largest undamped natural frequency (Lanczos)
  double dt = 0.0;                ///< s, 2/omega_max, reduced by damping when present
  double element_bound_dt = 0.0;  ///< s, 2/max element omega (lumped mass: a lower bound of dt)
  int iterations = 0;             ///< Lanczos iterations used
};

/// @brief Computes the critical step of `model`. Lanczos (M-inner product, no reorthogonalisation:
/// extreme Ritz values converge first and lost orthogonality only duplicates them) until the
/// largest Ritz value is stable to 1e-12 relative, at most 400 iterations.
CriticalStep critical_step(const Model& model);

/// @brief Largest eigenvalue of M^-1 K by Lanczos (exposed for tests).
double largest_eigenvalue(const Model& model, int max_iter, int* iterations = nullptr);

}  // namespace beamimpact
