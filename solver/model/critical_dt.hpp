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
/// and a lower bound: when every elastic body is one run, the Laguerre bracket's lower end of
/// each run's top eigenvalue (the bound is then exact); otherwise the top eigenvalue of the run
/// that sets the bound with the equations it shares with the rest of its body held at zero. That
/// pencil is the whole model's restricted to the run's other equations, so its top eigenvalue is
/// a Rayleigh quotient of the model's (Cauchy's interlacing). omega_max lies in
/// [omega_lower, omega_max bound].

#include <solver/model/Model.hpp>

namespace beamimpact {

/// @brief Which upper estimate of omega_max^2 a CriticalStep is based on.
enum class CriticalBound {
  kNone,       ///< no stiffness (rigid bodies only): no stability limit
  kElement,    ///< the element bound (proven)
  kSubdomain,  ///< the subdomain bound (proven, runs of consecutive elements)
};

/// @brief "none" | "element" | "subdomain" (summary.json critical_step.bound).
const char* to_string(CriticalBound b);

/// @brief The critical step and how it was found.
struct CriticalStep {
  double omega_max = 0.0;         ///< rad/s, the proven upper bound of omega_max the step uses
  double dt = 0.0;                ///< s, 2/omega_max, reduced by damping when present
  double element_bound_dt = 0.0;  ///< s, the step of the element bound (proven, never above the limit)
  /// rad/s, a proven lower bound of omega_max (subdomain_bound()'s lower; 0 without stiffness)
  double omega_lower = 0.0;
  CriticalBound bound = CriticalBound::kNone;  ///< which estimate set dt
  /// @brief omega_max / omega_lower - 1 (>= 0): the true omega_max lies in [omega_lower,
  /// omega_max], so the step is at most this fraction below the true (undamped) limit.
  double margin() const { return omega_lower > 0.0 ? omega_max / omega_lower - 1.0 : 0.0; }
};

/// @brief Elements per subdomain of the subdomain bound (frame: a pencil of up to 99 DOFs; covers
/// every body of the paper's scenes whole).
inline constexpr int kSubdomainElements = 32;

/// @brief Computes the critical step of `model` from the smaller of the element and subdomain
/// bounds, with the subdomain bound's lower bound of omega_max.
CriticalStep critical_step(const Model& model);

/// @brief The subdomain bound on omega_max^2 (rad^2/s^2): the largest eigenvalue of the free
/// DOFs of any run of at most max_elements consecutive elements of one elastic body.
/// @param model the assembled model
/// @param max_elements elements per run (>= 1; 1 gives the element bound on free DOFs)
double subdomain_bound(const Model& model, int max_elements);

/// @brief The subdomain bound and the lower bound its runs prove.
struct SubdomainBound {
  double upper = 0.0;  ///< rad^2/s^2, the subdomain bound on omega_max^2
  double lower = 0.0;  ///< rad^2/s^2, a lower bound of omega_max^2 (see the file's brief); 0 if none
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
