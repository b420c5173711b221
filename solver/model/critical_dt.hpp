#pragma once
/// @file critical_dt.hpp
/// @brief Stability limit of explicit central differences for the assembled model:
/// dt_crit = 2 / omega_max (reduced for Rayleigh damping), from proven upper bounds of
/// omega_max^2 (the largest eigenvalue of M^-1 K), O(n) in time and memory:
///  - the element bound (Irons): K = sum K_e and M = sum M_e (+ rigid-body masses), so the
///    Rayleigh quotient of the assembled pair is a ratio of sums of element quotients and no
///    assembled eigenvalue exceeds max_e lambda_max(K_e, M_e) (lumped and consistent mass);
///  - the subdomain bound: the same argument with runs of up to kSubdomainElements consecutive
///    elements of a body in place of single elements. Each distinct run's largest eigenvalue
///    comes from the inertia of sigma M - K (top_eigenvalue.hpp: Laguerre's iteration down from
///    the element bound, every iterate proven above by its LDL^T pivots), and a run whose
///    sigma M - K is positive definite at the largest value so far is skipped. It is never above
///    the element bound, and exact for bodies of at most kSubdomainElements elements (bodies are
///    not coupled in K);
/// and a lower estimate by Lanczos (a fixed small number of iterations): the top Ritz value is
/// a Rayleigh quotient, so omega_max lies in [ritz_omega, omega_max bound]. Lanczos's
/// a-posteriori residual (Ritz value + residual norm) is reported but not used for the step: it
/// bounds the distance to *some* eigenvalue, not necessarily the largest (a mode with little
/// weight in the start vector, such as a free end's, can be missing from the Krylov space).

#include <beamimpact/model/Model.hpp>

namespace beamimpact {

/// @brief Which upper estimate of omega_max^2 a CriticalStep is based on.
enum class CriticalBound {
  kNone,       ///< no stiffness (rigid bodies only): no stability limit
  kElement,    ///< the element bound (proven)
  kSubdomain,  ///< the subdomain bound (proven, runs of consecutive elements)
};

/// @brief "none" | "element" | "subdomain" (summary.json critical_step.bound).
const char* to_string(CriticalBound b);

/// @brief Largest eigenvalue of M^-1 K estimated by Lanczos.
struct LanczosEstimate {
  double ritz = 0.0;      ///< rad^2/s^2, largest Ritz value (a lower estimate)
  double residual = 0.0;  ///< rad^2/s^2, beta_{k+1} |s_k|, the residual norm of the top Ritz pair
  int iterations = 0;     ///< Lanczos iterations used
  /// @brief ritz + residual: an eigenvalue of M^-1 K lies in [ritz - residual, ritz + residual].
  double upper() const { return ritz + residual; }
};

/// @brief The critical step and how it was found.
struct CriticalStep {
  double omega_max = 0.0;         ///< rad/s, the proven upper bound of omega_max the step uses
  double dt = 0.0;                ///< s, 2/omega_max, reduced by damping when present
  double element_bound_dt = 0.0;  ///< s, the step of the element bound (proven, never above the limit)
  /// s, the step of Ritz value + residual (not safe: reported only); 0 without Lanczos
  double lanczos_dt = 0.0;
  /// rad/s, a lower bound of omega_max: sqrt of the top Ritz value, or, when every elastic body
  /// is one subdomain (the bound is exact; no Lanczos runs), of the Laguerre bracket's lower end
  double ritz_omega = 0.0;
  double residual = 0.0;          ///< rad^2/s^2, residual norm of the top Ritz pair (0 without Lanczos)
  int iterations = 0;             ///< Lanczos iterations used (0 without Lanczos)
  CriticalBound bound = CriticalBound::kNone;  ///< which estimate set dt
  /// @brief omega_max / ritz_omega - 1 (>= 0): the true omega_max lies in [ritz_omega,
  /// omega_max], so the step is at most this fraction below the true (undamped) limit.
  double margin() const { return ritz_omega > 0.0 ? omega_max / ritz_omega - 1.0 : 0.0; }
};

/// @brief Lanczos iterations at most (each costs about one time step of the run).
inline constexpr int kLanczosMaxIterations = 16;
/// @brief Elements per subdomain of the subdomain bound (frame: a pencil of up to 99 DOFs; covers
/// every body of the paper's scenes whole).
inline constexpr int kSubdomainElements = 32;

/// @brief Computes the critical step of `model` from the smaller of the element and subdomain
/// bounds, and a lower bound of omega_max: the subdomain bound's own when every elastic body is
/// one run, else the Lanczos lower estimate (M-inner product, no reorthogonalisation: extreme
/// Ritz values converge first and lost orthogonality only duplicates them; at most
/// kLanczosMaxIterations iterations, stopped once the residual is below 1e-12 of the Ritz value).
CriticalStep critical_step(const Model& model);

/// @brief Largest eigenvalue of M^-1 K by Lanczos with its residual bound (exposed for tests).
/// @param model the assembled model
/// @param max_iter iteration cap
LanczosEstimate lanczos_largest(const Model& model, int max_iter);

/// @brief The subdomain bound on omega_max^2 (rad^2/s^2): the largest eigenvalue of the free
/// DOFs of any run of at most max_elements consecutive elements of one elastic body.
/// @param model the assembled model
/// @param max_elements elements per run (>= 1; 1 gives the element bound on free DOFs)
double subdomain_bound(const Model& model, int max_elements);

/// @brief The subdomain bound and the lower bound its runs prove.
struct SubdomainBound {
  double upper = 0.0;  ///< rad^2/s^2, the subdomain bound on omega_max^2
  double lower = 0.0;  ///< rad^2/s^2, the largest run's Laguerre lower end; omega_max^2 >= lower when `exact`
  bool exact = false;  ///< every elastic body is one run: upper is omega_max^2 (up to roundoff)
};

/// @brief subdomain_bound() with the element bound already known, and its lower end.
/// @param model the assembled model
/// @param max_elements elements per run (>= 1)
/// @param lam_element element_bound(model): no run's eigenvalue exceeds it
SubdomainBound subdomain_bound(const Model& model, int max_elements, double lam_element);

/// @brief The element bound on omega_max^2 (rad^2/s^2): the largest eigenvalue of any single
/// element's (K_e, M_e); 0 without elastic elements.
/// @param model the assembled model
double element_bound(const Model& model);

}  // namespace beamimpact
