#pragma once
/// @file ExplicitContactIntegrator.hpp
/// @brief The paper's scheme (Pu & Chi 2011, Eq. 3-5): explicit Newmark (beta = 0, gamma = 1/2)
/// in which the contact force of step p acts on U^{p+1} and is whatever makes the predicted
/// step satisfy the contact conditions (forward-increment Lagrange multipliers):
///   Ubar^{p+1} = U^p + dt Vbar^p + dt^2/2 M^-1 (F^P - f_int(U^p) - C Vbar^p)
///   U^{p+1}    = Ubar^{p+1} + dt^2 H (R^p + tau^p),   H = M^-1 (I - dt/4 C M^-1)
///   Vbar^{p+1} = Vbar^p + M^-1 (-dt/2 (f_int(U^{p+1}) + f_int(U^p)) + dt F^P - C (U^{p+1} - U^p) + dt (R^p +
///   tau^p)) V^p        = Vbar^p + dt/2 M^-1 (R^p + tau^p)          (physical velocity, reported)
/// F^P is the constant external load ([loads], model/load_vector.hpp): it is folded into the
/// stored internal forces (f_int(U) - F^P), so a scene without loads runs the same operations.
/// Cost per step: one f_int (one sparse K U product when linear) and O(n) vector work (one fused
/// sweep for lumped, undamped models); no allocation in the loop.

#include <array>
#include <vector>

#include <memory>
#include <string>

#include <solver/contact/ContactSolver.hpp>
#include <solver/integrator/CorotationalMass.hpp>
#include <solver/integrator/InternalForce.hpp>
#include <solver/model/Effects.hpp>
#include <solver/model/MassSolver.hpp>
#include <solver/util/ThreadTeam.hpp>

namespace beamimpact::paper {

/// @brief Equations below which a second thread does not pay for its barrier (the step at
/// 2 threads is not faster than at 1; measured in docs/threads.md).
inline constexpr int kThreadsMinDofs = 20000;

/// @brief The largest thread count a run takes.
inline constexpr int kMaxThreads = 1024;

/// @brief Whether n is a thread count a run takes (1..kMaxThreads): the one rule behind
/// `[paper] threads`, `--threads` and RunOptions::threads.
/// @param n the count asked for
inline bool valid_thread_count(long n) { return n >= 1 && n <= kMaxThreads; }

/// @brief The thread count a run takes unless told: the cores available (available_cores(): the
/// hardware threads, fewer under a CPU affinity mask), and 1 for a model of fewer than
/// kThreadsMinDofs equations.
/// @param dofs the model's equations
int default_threads(int dofs);

/// @brief One run of the paper's integrator on a model. The state of step p is always complete:
/// U^p, Vbar^p and the contact forces R^p, tau^p that act on U^{p+1}; the physical V^p is formed
/// from them on demand (V()). The constructor leaves step 0 complete; each step() moves to the
/// next complete step.
class ExplicitContactIntegrator {
 public:
  /// @brief Sets up step 0 (zero displacement, the scene's velocities) and solves its contacts.
  /// @param model the beam model (M, K, C)
  /// @param scene contacts and friction coefficients
  /// @param effects which code paths run (damping, friction, corotational bodies)
  /// @param dt time step (s)
  /// @param surface how the struck point of a surface contact is interpolated (the paper's
  ///        linear weights by default)
  /// @param threads the step's threads asked for (>= 1), as set_threads() (threads() says how
  ///        many are used)
  ExplicitContactIntegrator(const Model& model, const Scene& scene, const Effects& effects, double dt,
                            SurfaceInterpolation surface = SurfaceInterpolation::kLinear, int threads = 1);

  /// @brief Moves from step p to p+1 with the forces of step p (Eq. 3-5), then solves the
  /// contact forces of step p+1. dissipated() then includes the contact work of p+1.
  void step() {
    if (fused_) {
      advance_fused();
      resolve_contacts();
      return;
    }
    advance();
    solve_contacts();
  }

  /// @brief Runs the step's element sweep on `threads` threads (made here, kept for the run),
  /// with the same bits as one thread (InternalForce::set_parts). Only the fused step (lumped,
  /// undamped, fixed mass) is split; any other runs on one thread, and so does a model with
  /// fewer than two elements per thread.
  /// @param threads the number asked for (>= 1)
  /// @return the number used; threads_note() says why when it is fewer
  int set_threads(int threads);
  /// @brief The step's threads in use (1 unless split).
  int threads() const { return team_ ? team_->size() : 1; }
  /// @brief The step's threads, idle between steps, for the work of an output row (null when the
  /// step runs on one thread).
  ThreadTeam* team() const { return team_.get(); }
  /// @brief Why fewer threads are used than were asked for ("" when as asked).
  const std::string& threads_note() const { return threads_note_; }

  /// @brief How a closure step's stick test measures the tangential increment (ClosureSlip;
  /// the paper's whole step unless set).
  void set_closure_slip(ClosureSlip c) { solver_.set_closure_slip(c); }

  /// @brief Current time t_p (s) and step p.
  double time() const { return static_cast<double>(p_) * dt_; }
  long step_index() const { return p_; }
  double dt() const { return dt_; }
  /// @brief U^p and physical V^p.
  const Eigen::VectorXd& U() const { return U_; }
  const Eigen::VectorXd& V() const {
    if (!solver_.any_force()) return Vbar_;
    if (v_stale_) form_velocity();
    return V_;
  }
  /// @brief The physical velocity along a row of equations, sum of coeff V^p_i: what
  /// ContactPair::eval(row, V()) gives, without forming the whole V^p on a lumped model (a step
  /// in contact then reads O(row) entries, not every equation).
  /// @param row the equations and their coefficients (a contact row)
  double velocity_along(const std::vector<DofTerm>& row) const;
  /// @brief Half-step velocity Vbar^p (for the discrete energy identity).
  const Eigen::VectorXd& Vbar() const { return Vbar_; }
  /// @brief Forces of the last solve, per contact.
  const std::vector<ContactForce>& forces() const { return solver_.forces(); }
  /// @brief Contact geometry, per node pair (one per scene contact unless a contact searches).
  const std::vector<ContactPair>& pairs() const { return search_.pairs; }
  /// @brief Per scene contact: its pairs, the declared (or, for node = "all", nearest) one first.
  const std::vector<std::vector<int>>& pair_groups() const { return search_.group; }
  /// @brief Energy of the initial conditions (J): kinetic 1/2 V0^T M V0 of the scene's
  /// velocities at U = 0, before any contact force (V^0 carries the step-0 contact force when a
  /// contact closes in the first step).
  double initial_energy() const { return initial_energy_; }
  /// @brief Kinetic 1/2 V^T M V and strain energy at step p (J). Both, and momentum(), are sums
  /// over the equations in fixed chunks (ordered_sum) shared by the step's threads: an output row
  /// costs what its share of the step costs, with the same bits on any thread count.
  double kinetic_energy() const;
  double strain_energy() const;
  /// @brief Work of the external loads up to step p, F^P . U^p (J; 0 without loads).
  double load_work() const { return load_.size() ? load_.dot(U_) : 0.0; }
  /// @brief Energy stored in the Hertz contact springs at step p (J; 0 with the hard law).
  double contact_energy() const { return hertz_energy_; }
  /// @brief Linear momentum of body b along global axis c (0 = x, 1 = y) at step p (N s).
  double momentum(int b, int c) const;
  /// @brief What an output row sums over the equations at step p.
  struct RowSums {
    double kinetic = 0.0;  ///< J, as kinetic_energy()
    double strain = 0.0;   ///< J, as strain_energy()
    Vec2 momentum{0, 0};   ///< N s, the sum over the bodies, in body order, of momentum(b, c)
  };
  /// @brief kinetic_energy(), strain_energy() and every body's momentum(b, c) with their bits, in
  /// one pass over the equations shared by the step's threads (one hand-over, not one per sum)
  /// on the fused step with linear elements; otherwise the separate sums.
  RowSums row_sums() const;
  /// @brief The current mass: the model's, or M_A(t) when a rotating body has consistent mass.
  const SparseMatrix& mass() const { return cmass_ ? cmass_->M() : model_.M(); }
  /// @brief Cumulative energy removed by contact forces (closures, friction) and damping (J).
  double dissipated() const { return dissipated_; }
  /// @brief The model.
  const Model& model() const { return model_; }
  /// @brief The internal force (its element end forces serve the field output).
  const InternalForce& internal_force() const { return fint_; }

 private:
  /// Predicts U^{p+1} without contact, solves the contact forces of step p and the physical
  /// velocity V^p, and adds this step's contact work to the dissipated energy.
  void solve_contacts();
  /// solve_contacts() after the prediction (Ubar, V = Vbar) is made.
  void resolve_contacts();
  /// advance() and the prediction of solve_contacts() for lumped, undamped models with a fixed
  /// mass: the same operations on each entry in the same order (bit-for-bit the same results),
  /// in one sweep over memory: f_int is streamed into the update (InternalForce::apply_streamed).
  void advance_fused();
  /// f_int(U^{p+1}) into fint_next_, calling done(lo, hi) on each range as soon as it is final:
  /// on the team's threads when the sweep is split (each part's ranges on its own thread, the
  /// boundary equations after them on this one).
  template <class Done>
  void sweep_f_int(const Done& done) {
    if (!team_) {
      fint_.apply_streamed(U_next_, fint_next_, done);
      return;
    }
    auto part = [&](int t) { fint_.apply_part(t, U_next_, fint_next_, done); };
    team_->run(part);
    fint_.finish_parts(fint_next_, done);
  }
  /// Moves from p to p+1 with the forces of the last solve_contacts().
  void advance();
  /// The team for the parts fint_ has made (set_threads after the split; the reason when fewer).
  int start_team(int threads);
  void apply_Minv(const Eigen::VectorXd& in, Eigen::VectorXd& out) const { minv_.apply(in, out); }
  void apply_H(const Eigen::VectorXd& f, Eigen::VectorXd& out);
  /// V^p = Vbar^p + dt/2 M^-1 f_c (Eq. 5) on demand (V is read only on output rows).
  void form_velocity() const;
  /// The fused path's contact force: zeroes the last step's entries, adds this step's, and lists
  /// the equations it touches in fc_dofs_ (sorted, unique), so that the contact costs O(pairs).
  void gather_contact_force();
  void subtract_damping_force(const Eigen::VectorXd& v, Eigen::VectorXd& f);
  /// f = f_int(U) - F^P (the net force of the step's equations).
  void net_force(const Eigen::VectorXd& U, Eigen::VectorXd& f) const {
    fint_.apply(U, f);
    if (load_.size()) f -= load_;
  }
  /// Books the damper's work on the contact part dt/2 M^-1 f_c of the physical velocity: half
  /// of dt/2 (M^-1 f_c) . C du for the current f_c and the last step's du (damped models).
  void book_damper_contact_share();
  /// The damper's share of the step's strain energy change (damped models; J).
  double damper_strain_share();

  const Model& model_;
  double dt_;
  bool damped_, friction_;
  bool fused_ = false;  ///< lumped, undamped, fixed mass: advance_fused()
  MassSolver minv_;
  InternalForce fint_;
  std::unique_ptr<CorotationalMass> cmass_;  ///< only for consistent mass with rotating bodies
  ContactPairs search_;                      ///< the contact pairs and the scene contact of each
  std::unique_ptr<SearchBoxes> boxes_;
  ContactSolver solver_;
  Eigen::VectorXd load_;  ///< F^P, empty without loads
  long p_ = 0;
  // fint_U_, fint_next_: f_int - F^P at U^p, U^{p+1} (the net force of the step's equations)
  Eigen::VectorXd U_prev_, U_, U_next_,  // U^{p-1}, U^p, U^{p+1} (rotated by swaps)
      Vbar_, fint_U_, fint_next_, Ubar_, fc_, work_, work2_;
  Eigen::VectorXd du_, scratch_, hwork_, c_du_, c_z_;  ///< the damper's work vectors: empty when undamped
  mutable Eigen::VectorXd V_, vwork_;  ///< V^p when a contact force acts (formed by form_velocity)
  std::vector<int> fc_dofs_;           ///< fused path: the equations where fc_ may be non-zero
  std::vector<double> vbar_saved_;     ///< fused path: Vbar^p at fc_dofs_ during the sweep
  double dissipated_ = 0.0;
  bool hertz_ = false;         ///< some contact has the Hertz law
  double hertz_energy_ = 0.0;  ///< J, in the Hertz springs (ContactSolver::hertz_energy)
  double initial_energy_ = 0.0;
  std::unique_ptr<ThreadTeam> team_;  ///< the sweep's threads when split (set_threads)
  std::string threads_note_;
  mutable bool v_stale_ = false;            ///< V_ is still to be formed from Vbar_ and fc_
  mutable std::vector<double> sum_chunks_;  ///< the energies' and momentum's chunk sums
  mutable std::vector<double> row_totals_;  ///< row_sums(): kinetic, strain, then 2 b + c
  /// The chunk [first, last)'s terms of 2 kinetic energy at velocity v (fused step: of 2 strain
  /// energy too).
  double kinetic_terms(const Eigen::VectorXd& v, long long first, long long last) const;
  double strain_terms(long long first, long long last) const;
  /// The chunk [first, last)'s terms of momentum(b, c) at velocity v: its covector's support
  /// within the chunk.
  double momentum_terms(const Eigen::VectorXd& v, int b, int c, long long first, long long last) const;
  /// V^p on [first, last) of the fused step (M^-1 diagonal), entry by entry.
  void form_velocity_range(long long first, long long last) const;
  std::vector<std::array<long long, 2>>
      momentum_support_;  ///< [lo, hi) of each covector's non-zeros, 2 b + c
};

}  // namespace beamimpact::paper
