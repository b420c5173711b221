#pragma once
/// @file ContactSolver.hpp
/// @brief The paper's contact forces from displacement compatibility (Eq. 2, 20, 30-31 in the
/// general form): for each active contact, (W^T H W) [R, tau] = -(predicted violation), with
/// W the normal (and, with friction, tangent) rows. Stick first; slip when |tau| > mu R with
/// tau = mu R sign(tau_stick) and R re-solved; open when R <= 0. Several contacts are coupled
/// through H and solved by Gauss-Seidel sweeps (one sweep for a single contact).

#include <algorithm>
#include <functional>
#include <vector>

#include <solver/contact/ContactPair.hpp>
#include <solver/contact/contact_search.hpp>
#include <solver/schema/output_schema.hpp>

namespace beamimpact::paper {

/// @brief How the stick test of a closure step (the step in which an open contact closes)
/// measures the tangential increment.
enum class ClosureSlip {
  kWholeStep,    ///< the paper: over the whole step, although the contact is closed only for the
                 ///< part after the closure instant (the discrete stick threshold then moves with
                 ///< the closure phase)
  kFromClosure,  ///< only the part after the closure instant, (1 - phi) of it with phi = g^p /
                 ///< (g^p - gbar^{p+1}) the linear closure instant within the step
};

/// @brief Per-contact result of one step.
struct ContactForce {
  double R = 0.0, tau = 0.0;  ///< N; R >= 0 compressive, tau along the target tangent on the striker
  double gap_next = 0.0;      ///< m, gap after the corrected step
  double slip_next = 0.0;     ///< m, relative tangential increment of the corrected step
  ContactState state = ContactState::kOpen;
};

/// @brief Solves the contact forces of one step given the predicted displacement.
class ContactSolver {
 public:
  /// @brief apply_H(f, out): out = dt^2 H f (the response of U^{p+1} to a force f).
  using ApplyH = std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>;
  /// @brief friction: build tangent rows (false: normal rows only, tau = 0 and no 2x2 solves);
  /// gap_tol: per contact, the penetration (m) below which a predicted gap counts as closed.
  ContactSolver(std::vector<ContactPair>& pairs, std::vector<double> mu, bool friction, int n,
                std::vector<double> gap_tol, ApplyH apply_H);

  /// @brief Declares dt^2 H diagonal (a lumped, undamped model): (dt^2 H f)_i = (inv_i f_i) dt2.
  /// A response column is then formed on its row's equations alone, O(row) instead of O(n) (a
  /// sliding contact re-forms its columns every step), with apply_H's bits. Call before the
  /// first solve; `inv` must outlive the solver.
  /// @param inv the diagonal of M^-1; @param dt2 dt * dt (s^2)
  void set_diagonal_response(const Eigen::VectorXd* inv, double dt2);

  /// @brief Solves for Ubar (predicted U^{p+1}) and U (current U^p). Re-locates sliding points.
  /// @param Ubar the contact-free prediction of U^{p+1}
  /// @param U the displacement U^p
  /// @param U_prev U^{p-1}, read by the Hertz pairs only (their force is the secant of the
  ///        spring's energy from the gap at U^{p-1}); nullptr: the gap at U^p stands in for it
  const std::vector<ContactForce>& solve(const Eigen::VectorXd& Ubar, const Eigen::VectorXd& U,
                                         const Eigen::VectorXd* U_prev = nullptr);
  /// @brief Forces of the last solve (all open before the first), per contact.
  const std::vector<ContactForce>& forces() const { return out_; }
  /// @brief Adds sum W lambda of the last solve into f (a force vector, N).
  /// @param f the force vector added to
  /// @param touched when given, the equations written are appended to it (duplicates possible)
  void add_forces(Eigen::VectorXd& f, std::vector<int>* touched = nullptr) const;
  /// @brief The most equations add_forces appends to `touched` (every row full, duplicates
  /// counted): room for them keeps a step free of allocation.
  std::size_t max_touched() const { return pairs_.size() * (friction_ ? 2 : 1) * ContactPair::kMaxRowTerms; }
  /// @brief Forgets the cached H W columns (the mass changed: a rotating body's M_A(t)).
  void invalidate() { std::fill(fresh_.begin(), fresh_.end(), 0); }
  /// @brief True when the last solve produced any non-zero force.
  bool any_force() const { return any_; }
  /// @brief Lets solve() skip open searched pairs whose node is outside the other body's box
  /// (nullptr: check every pair). The boxes must outlive the solver.
  void set_search_boxes(SearchBoxes* boxes) { boxes_ = boxes; }
  /// @brief How a closure step's stick test measures the tangential increment (default: the
  /// paper's whole step).
  void set_closure_slip(ClosureSlip c) { closure_slip_ = c; }
  /// @brief Per contact pair: the Hertz stiffness k (N/m^1.5), or 0 for the hard law (the
  /// default of every pair). A Hertz pair's spring force S follows its corrected gap,
  /// and the force applied at step p is the secant of the spring's energy V between the gaps at
  /// U^{p-1} and U^{p+1} (hertz_law.hpp): centred on step p (second order), and its work over
  /// the step is exactly the change of V, so the springs neither create nor lose energy at any
  /// step and any stiffness (for a linear spring it is the trapezoidal mean of the forces).
  void set_hertz(std::vector<double> k);
  /// @brief The energy stored in the Hertz springs after the last solve (J; 0 with the hard
  /// law): the mean of their energies at U^p and U^{p+1}, the quantity the secant force's work
  /// telescopes into.
  double hertz_energy() const;

 private:
  void refresh_response(int c);
  /// The steps of solve(): contact c's predicted gap and slide at Ubar and whether it is active;
  /// the other contacts' forces added to g and s; the hard law's local solve (stick or slip);
  /// the open contacts' gaps with the others' forces. Inline (defined in ContactSolver.cc, the
  /// only caller) so that the step loop pays no call for them in a position-independent build.
  inline void predict(int c, const Eigen::VectorXd& Ubar, const Eigen::VectorXd& U);
  inline void add_others(int c, double& g, double& s) const;
  inline ContactForce hard_local(int c, double g, double s, double Ann) const;
  inline void finish_open_gaps();
  /// The local solve of a Hertz pair c with predicted gap g and slip s (others' forces included).
  ContactForce hertz_local(int c, double g, double s, double Ann);
  bool hertz_pair(int c) const { return !hertz_.empty() && hertz_[c] > 0.0; }
  std::vector<ContactPair>& pairs_;
  std::vector<double> mu_;
  bool friction_;
  std::vector<double> tol_;
  ApplyH apply_H_;
  std::vector<ContactForce> out_;
  std::vector<Eigen::VectorXd> hn_, ht_;           ///< dt^2 H G_n, dt^2 H G_t per contact
  std::vector<char> fresh_;                        ///< response columns match the current rows
  const Eigen::VectorXd* h_inv_ = nullptr;         ///< set_diagonal_response: M^-1's diagonal, else null
  double h_dt2_ = 0.0;                             ///< s^2, dt * dt of set_diagonal_response
  std::vector<std::vector<int>> hn_eqs_, ht_eqs_;  ///< diagonal H: the equations each column holds
  Eigen::VectorXd scratch_;
  std::vector<double> gbar_, sbar_;  ///< predicted violations per contact (sized once)
  std::vector<char> active_;
  std::vector<char> candidate_;  ///< on the surface and not skipped by the box pass
  std::vector<int> engaged_;     ///< active pairs of this solve, in index order
  SearchBoxes* boxes_ = nullptr;
  ClosureSlip closure_slip_ = ClosureSlip::kWholeStep;
  std::vector<double> hertz_;                     ///< per pair: Hertz k (N/m^1.5), 0 = hard; empty: all hard
  std::vector<double> gap_prev_;                  ///< m, per Hertz pair: the gap at U^{p-1}
  std::vector<double> energy_now_, energy_next_;  ///< J, per pair: V at U^p and U^{p+1}
  const Eigen::VectorXd* U_prev_ = nullptr;       ///< U^{p-1} of the current solve
  bool any_ = false;
};

}  // namespace beamimpact::paper
