#pragma once
/// @file PenaltyIda.hpp
/// @brief SUNDIALS IDA (variable-order BDF) on M U'' + C U' + K U = f_c(U, U') with penalty
/// contact, written as the residual F(t, y, y') = 0 with y = [U; V]:
///   F_u = U' - V,   F_v = M V' + C V + K U - F - sum_c (R_c G_n,c + tau_c G_t,c),
/// F the constant external load (set_load; none by default).
/// Each contact is open (R = 0) or closed (R = kn (-g) + cn (-g'), tau = regularised Coulomb).
/// Root functions locate the switches (open: g = 0 falling; closed: R = 0 falling); at each
/// event the state flips and IDA is re-initialised with a consistent y'. Impulses and the
/// dissipated energy are extra states Q' = q(U, V) under IDA's error control (IDA, unlike
/// IDAS, has no quadrature module). Independent of the paper integrator.

#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <references/ida/ContactKinematics.hpp>
#include <references/ida/ElasticForce.hpp>
#include <references/ida/penalty_law.hpp>
#include <solver/model/Model.hpp>

namespace beamimpact::ida {

/// @brief Linear solver of the Newton iteration.
enum class IdaLinearSolver { kDense, kKlu };

/// @brief Integration settings.
struct IdaSettings {
  double rtol = 1e-8;   ///< relative tolerance
  double atol = 1e-11;  ///< absolute tolerance (m, m/s, rad, rad/s alike)
  IdaLinearSolver linear_solver = IdaLinearSolver::kDense;
  double max_step = 0.0;     ///< s, 0 = IDA's own choice
  long max_events = 100000;  ///< guard against endless chatter
};

/// @brief Counters summed over all re-initialisations.
struct IdaCounters {
  long steps = 0, residual_evals = 0, jacobian_evals = 0, nonlinear_iters = 0;
  long error_test_fails = 0, nonlinear_conv_fails = 0, root_evals = 0, events = 0;
  long klu_pattern_changes = 0;
  long warnings = 0;  ///< IDA warnings (e.g. a root function still zero after a re-init)
};

/// @brief One contact switch located by root finding.
struct ContactEvent {
  int contact;  ///< index in the contact list
  double t;     ///< s
  bool onset;   ///< true: closes; false: releases
};

/// @brief The contact forces and kinematics of one pair at the current state.
struct ContactReading {
  bool closed = false;
  double R = 0.0, tau = 0.0;                          ///< N
  double gap = 0.0, gap_rate = 0.0, slip_rate = 0.0;  ///< m, m/s, m/s
  double force_rate = 0.0;      ///< m/s, V along the normal force's direction (its power is R force_rate)
  double penalty_energy = 0.0;  ///< J, kn g^2 / 2 while closed
  ContactFrame frame;
};

/// @brief The integrator. Holds references to its inputs (keep them alive).
class PenaltyIda {
 public:
  /// @brief C may be empty (0x0) for no damping. laws[i] belongs to contacts[i].
  PenaltyIda(const SparseMatrix& M, const SparseMatrix& K, const SparseMatrix& C,
             std::vector<const ContactKinematics*> contacts, std::vector<PenaltyLaw> laws,
             IdaSettings settings);
  ~PenaltyIda();
  PenaltyIda(const PenaltyIda&) = delete;
  PenaltyIda& operator=(const PenaltyIda&) = delete;

  /// @brief Replaces K U by elastic's f_int(U) (and K's Jacobian by its tangent); call before
  /// start(). The object must outlive the integrator; null restores K U.
  void set_elastic(const ElasticForce* elastic);
  /// @brief The constant external load F (one entry per equation, N); call before start().
  void set_load(const Eigen::VectorXd& F);
  /// @brief Sets the initial state (all contacts open: the initial gaps must be positive).
  void start(double t0, const Eigen::VectorXd& U0, const Eigen::VectorXd& V0);
  /// @brief Integrates to t_out exactly. on_step(t_prev) is called after every internal step
  /// and every event with the state at the step's end (read it through the accessors).
  void advance_to(double t_out, const std::function<void(double t_prev)>& on_step = {});

  double t() const;
  Eigen::Map<const Eigen::VectorXd> U() const;
  Eigen::Map<const Eigen::VectorXd> V() const;
  /// @brief Forces and kinematics of contact i at the current state.
  ContactReading contact(int i) const;
  /// @brief Normal and tangential impulse of contact i so far (N s).
  double impulse_normal(int i) const;
  double impulse_tangential(int i) const;
  /// @brief Energy dissipated so far by contact dashpots, friction and Rayleigh damping, plus
  /// the spring energy a dashpot-held penalty still stores when its force reaches zero (J).
  double dissipated() const;
  /// @brief Located events, in time order.
  const std::vector<ContactEvent>& events() const;
  /// @brief Solver counters so far.
  IdaCounters counters() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace beamimpact::ida
