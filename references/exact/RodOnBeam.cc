#include <references/exact/RodOnBeam.hpp>
#include <references/exact/gsl_ode_impl.hpp>
#include <references/exact/output_times.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <gsl/gsl_roots.h>
#include <solver/util/Progress.hpp>

namespace beamimpact::exact {
namespace {

// What the right-hand side needs: modal data, the contact mode and the delayed memory.
struct Dynamics {
  int N = 0;
  std::vector<double> phi, omega2, mass, momentum;  // per mode: shape at x_c, omega^2, modal mass, momentum
  double top_omega = 0.0;                           // rad/s, the highest mode's frequency
  double Z = 0.0, v0 = 0.0, T = 0.0, g0 = 0.0;
  bool closed = false;
  long past = -1;  // memory piece holding R(t - T); -1: before the first touch
  const DelayMemory* mem = nullptr;

  double delayed(double t) const {
    return past < 0 ? 0.0 : mem->value(static_cast<std::size_t>(past), t - T);
  }
  double beam_velocity(const double* y) const {
    double w = 0.0;
    for (int n = 0; n < N; ++n) w += phi[n] * y[N + n];
    return w;
  }
  double beam_deflection(const double* y) const {
    double w = 0.0;
    for (int n = 0; n < N; ++n) w += phi[n] * y[n];
    return w;
  }
  // Contact force if the gap were closed: the rod end must move with the beam point.
  double trial_force(double t, const double* y) const {
    return Z * (v0 - beam_velocity(y)) - 2.0 * delayed(t);
  }
  double force(double t, const double* y) const { return closed ? trial_force(t, y) : 0.0; }
  double gap(const double* y) const { return g0 + beam_deflection(y) - y[2 * N]; }
  // Event function: force while in contact (separation when it falls through 0), gap while apart.
  double event(double t, const double* y) const { return closed ? trial_force(t, y) : gap(y); }
};

// y = [q_1..q_N, q_1'..q_N', u (rod end), J (impulse of P), W (work of P on the rod end)]
int rhs(double t, const double y[], double dydt[], void* params) {
  const auto& d = *static_cast<const Dynamics*>(params);
  const int N = d.N;
  const double rho = d.delayed(t);
  const double P = d.closed ? d.Z * (d.v0 - d.beam_velocity(y)) - 2.0 * rho : 0.0;
  for (int n = 0; n < N; ++n) {
    dydt[n] = y[N + n];
    dydt[N + n] = -d.omega2[n] * y[n] + d.phi[n] * P / d.mass[n];
  }
  const double du = d.v0 - (P + 2.0 * rho) / d.Z;
  dydt[2 * N] = du;
  dydt[2 * N + 1] = P;
  dydt[2 * N + 2] = P * du;
  return GSL_SUCCESS;
}

using detail::Driver;

void check(int status, const char* what) { detail::check_gsl(status, "rod-on-beam", what); }

/// @brief Modal data of the beam at the struck point and the rod's constants, for rhs().
/// @param s problem data
/// @param modes the beam's modes (BeamModes.hpp)
/// @param mem the rod's reflection memory the dynamics reads the delayed wave from
Dynamics make_dynamics(const RodOnBeamSetup& s, const std::vector<BeamMode>& modes, const DelayMemory& mem) {
  Dynamics d;
  d.N = static_cast<int>(modes.size());
  d.Z = s.rod.impedance();
  d.v0 = s.v0;
  d.T = s.rod.round_trip();
  d.g0 = s.gap;
  d.mem = &mem;
  for (const BeamMode& m : modes) {
    d.phi.push_back(m.shape);
    d.omega2.push_back(m.omega * m.omega);
    d.mass.push_back(m.mass);
    d.momentum.push_back(m.momentum);
    d.top_omega = std::max(d.top_omega, m.omega);
  }
  return d;
}

/// @brief The steps of one solution and the state they share: rigid flight up to the first
/// touch, then smooth pieces between breakpoints (a piece start returns one rod round trip
/// later), each integrated through memory samples and output times, with contact onset and
/// separation located inside a piece. Fills the solution and the reflection memory it is given.
class Integration {
 public:
  /// @param s problem data
  /// @param sol the solution to fill
  /// @param mem the rod's reflection memory to fill
  Integration(const RodOnBeamSetup& s, RodOnBeamSolution& sol, DelayMemory& mem)
      : s_(s),
        sol_(sol),
        mem_(mem),
        d_(make_dynamics(s, beam_modes(s.beam, s.shear, s.x_c, s.modes), mem)),
        N_(d_.N),
        dim_(static_cast<std::size_t>(2 * N_ + 3)) {
    sol_.modes = N_;
    t0_ = s_.v0 > 0.0 ? s_.gap / s_.v0 : std::numeric_limits<double>::infinity();
    T_ = d_.T;
    // Memory samples a quarter radian of the highest mode apart (see DelayMemory::value).
    delta_ = std::min(0.25 / d_.top_omega, T_ / 32.0);
    sol_.sample_dt = delta_;
    out_t_ = output_times(s_.dt_out, s_.t_end);
  }
  Integration(const Integration&) = delete;  // rhs() and the drivers hold pointers into it
  Integration& operator=(const Integration&) = delete;

  /// @brief Output rows before the first touch: rigid rod, beam at rest.
  void add_rows_before_touch() {
    while (out_i_ < out_t_.size() && out_t_[out_i_] < t0_) {
      RodOnBeamRow r;
      r.t = out_t_[out_i_++];
      r.u = s_.v0 * r.t;
      r.du = s_.v0;
      r.gap = s_.gap - r.u;
      r.rod.kinetic = 0.5 * s_.rod.mass() * s_.v0 * s_.v0;
      r.rod.momentum = s_.rod.mass() * s_.v0;
      sol_.rows.push_back(r);
    }
  }

  /// @brief True when every output row has been written.
  bool all_rows_written() const { return out_i_ == out_t_.size(); }

  /// @brief Integrates from the first touch to t_end, piece by piece.
  void integrate_from_touch() {
    allocate_drivers();
    y_.assign(dim_, 0.0);
    y_[2 * N_] = s_.gap;  // the rod end has travelled the gap at first touch
    t_ = t0_;
    d_.closed = true;
    contact_start_ = t0_;
    eps_ = 1e-12 * std::max(T_, s_.t_end);
    Progress progress("exact (" + std::to_string(N_) + " modes)", s_.t_end);  // stderr, long runs only
    while (t_ < s_.t_end - eps_) {
      progress.update(t_);
      const double nb = next_breakpoint();
      begin_piece();
      if (!integrate_piece(nb)) t_ = nb;
    }
  }

  /// @brief Closes an open contact interval at t_end, writes the remaining output rows and the
  /// totals (impulse, energy balance error).
  void finish() {
    if (d_.closed) sol_.intervals.push_back({contact_start_, s_.t_end});
    while (out_i_ < out_t_.size()) sol_.rows.push_back(make_row(t_, y_.data())), ++out_i_;
    sol_.impulse = y_[2 * N_ + 1];
    sol_.energy_error = energy_balance_error();
  }

 private:
  /// @brief The main and the root-finding rk8pd drivers, with absolute tolerances rtol times
  /// natural scales: displacement v0 x (time scale), velocity v0, impulse Z v0 x (time scale),
  /// work (impulse) v0.
  void allocate_drivers() {
    const double tc = std::min(T_, s_.t_end - t0_) > 0.0 ? std::min(T_, s_.t_end - t0_) : T_;
    const double X = s_.v0 * tc, V = s_.v0, J = d_.Z * s_.v0 * tc, W = J * s_.v0;
    scale_.assign(dim_, X);
    for (int n = 0; n < N_; ++n) scale_[N_ + n] = V;
    scale_[2 * N_ + 1] = J;
    scale_[2 * N_ + 2] = W;
    sys_ = {rhs, nullptr, dim_, &d_};
    const double h0 = 0.1 * delta_;
    drv_.reset(gsl_odeiv2_driver_alloc_scaled_new(&sys_, gsl_odeiv2_step_rk8pd, h0, s_.rtol, s_.rtol, 1.0,
                                                  0.0, scale_.data()));
    aux_.reset(gsl_odeiv2_driver_alloc_scaled_new(&sys_, gsl_odeiv2_step_rk8pd, h0, s_.rtol, s_.rtol, 1.0,
                                                  0.0, scale_.data()));
  }

  /// @brief End of the piece starting at t_ (s): the earliest pending breakpoint or t_end.
  /// The piece start itself becomes a breakpoint one rod round trip later.
  double next_breakpoint() {
    while (!pending_.empty() && *pending_.begin() <= t_ + eps_) pending_.erase(pending_.begin());
    pending_.insert(t_ + T_);  // this piece start comes back after one round trip in the rod
    return std::min(*pending_.begin(), s_.t_end);
  }

  /// @brief Starts a piece at t_: points the delayed wave at its memory piece, lets the
  /// breakpoint switch the contact state, opens a memory piece and samples it.
  void begin_piece() {
    d_.past = (t_ - T_ >= t0_ - eps_) ? mem_.piece_at(t_ - T_ + eps_) : -1;
    if (!after_event_) switch_state_at_breakpoint();
    after_event_ = false;
    if (sol_.pieces == 0) sol_.first_P = d_.force(t_, y_.data());
    ++sol_.pieces;
    mem_.start_piece(t_);
    memory_sample(t_, y_.data());
    track(t_, y_.data());
  }

  /// @brief A breakpoint can switch the contact state by itself (the delayed wave jumps):
  /// separation if the contact force would be negative, onset if the gap is closed and the
  /// beam point is slower than the rod end.
  void switch_state_at_breakpoint() {
    if (d_.closed && d_.trial_force(t_, y_.data()) < 0.0) {
      d_.closed = false;
      sol_.intervals.push_back({contact_start_, t_});
      y_[2 * N_] = d_.g0 + d_.beam_deflection(y_.data());  // drift removal, as in apply_event
      ++sol_.events;
    } else if (!d_.closed && d_.gap(y_.data()) <= 0.0 &&
               d_.beam_velocity(y_.data()) < s_.v0 - 2.0 * d_.delayed(t_) / d_.Z) {
      d_.closed = true;
      contact_start_ = t_;
      ++sol_.events;
    }
  }

  /// @brief Where the integration of a piece stops (s, is an output time): memory samples
  /// every delta, the output times up to nb, and the piece end nb, in time order.
  std::vector<std::pair<double, bool>> piece_stops(double nb) const {
    std::vector<std::pair<double, bool>> stops;
    for (double s = t_ + delta_; s < nb - 0.25 * delta_; s += delta_) stops.push_back({s, false});
    stops.push_back({nb, false});
    for (std::size_t k = out_i_; k < out_t_.size() && out_t_[k] <= nb; ++k)
      stops.push_back({out_t_[k], true});
    std::stable_sort(stops.begin(), stops.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    return stops;
  }

  /// @brief Integrates the piece from t_ towards nb stop by stop, sampling the memory and
  /// writing output rows; stops at a contact event inside the piece.
  /// @return true if the piece ended at an event (t_ is then the event time)
  bool integrate_piece(double nb) {
    const auto stops = piece_stops(nb);
    gsl_odeiv2_driver_reset(drv_.get());
    for (const auto& [stop, is_out] : stops) {
      if (stop <= t_) {
        if (is_out && stop == t_ && next_output_is(stop)) write_row();
        continue;
      }
      const double t_prev = t_;
      const std::vector<double> y_prev = y_;
      const double f_prev = d_.event(t_, y_.data());
      check(gsl_odeiv2_driver_apply(drv_.get(), &t_, stop, y_.data()), "integration");
      sol_.steps += static_cast<long>(drv_->e->count);
      gsl_odeiv2_driver_reset(drv_.get());
      const double f_now = d_.event(t_, y_.data());
      if (f_now < 0.0) {
        // Separation (force through 0) or re-contact (gap through 0).
        const double te = f_prev > 0.0 ? locate_event(t_prev, y_prev, t_) : t_prev;
        apply_event(t_prev, y_prev, te);
        return true;
      }
      if (!is_out) memory_sample(t_, y_.data());
      track(t_, y_.data());
      if (is_out && next_output_is(stop)) write_row();
    }
    return false;
  }

  /// @brief Brent root finding on the event function in (ta, tb), each evaluation integrating
  /// from the last accepted stop (ta, ya).
  /// @return the upper end of the final bracket, just past the crossing (event function <= 0)
  double locate_event(double ta, const std::vector<double>& ya, double tb) {
    struct RootCtx {
      Integration* self;
      double ta;
      const std::vector<double>* ya;
    } rc{this, ta, &ya};
    gsl_function F;
    F.function = [](double x, void* p) {
      auto& c = *static_cast<RootCtx*>(p);
      const auto& yx = c.self->integrate_copy(c.ta, *c.ya, x);
      return c.self->d_.event(x, yx.data());
    };
    F.params = &rc;
    std::unique_ptr<gsl_root_fsolver, void (*)(gsl_root_fsolver*)> owner(
        gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
    gsl_root_fsolver* solver = owner.get();
    // Re-integrated from (ta, ya), the event function may already be <= 0 at ta (an event within
    // roundoff of the last stop, e.g. a beam so soft that the gap barely moves): the event is at ta.
    if (GSL_FN_EVAL(&F, ta) <= 0.0) return ta;
    // The driver saw the crossing by tb; re-integrated, the function may stay above 0 there by
    // roundoff (a gap or force that hovers at 1e-15): the event is at tb.
    if (GSL_FN_EVAL(&F, tb) > 0.0) return tb;
    check(gsl_root_fsolver_set(solver, &F, ta, tb), "root bracketing");
    double lo = ta, hi = tb;
    for (int it = 0; it < 200; ++it) {
      check(gsl_root_fsolver_iterate(solver), "root finding");
      lo = gsl_root_fsolver_x_lower(solver);
      hi = gsl_root_fsolver_x_upper(solver);
      if (gsl_root_test_interval(lo, hi, 1e-13 * (1.0 + std::abs(hi)), 0.0) == GSL_SUCCESS) break;
    }
    return hi;
  }

  /// @brief Moves the state to the event at te (from the last accepted stop (ta, ya)) and
  /// switches the contact state: closes the contact interval or opens a new one.
  void apply_event(double ta, const std::vector<double>& ya, double te) {
    y_ = integrate_copy(ta, ya, te);
    t_ = te;
    memory_sample(t_, y_.data());
    track(t_, y_.data());
    if (te <= last_event_t_)
      throw std::runtime_error(
          "exact rod-on-beam: two contact events at t = " + std::to_string(te) +
          " s cannot be ordered (the gap and the contact force both stay within roundoff of zero: "
          "the rod and the beam move together without a resolvable contact or separation); the "
          "semi-analytic solution does not resolve this scene (e.g. a target this soft or light): "
          "compare with --method ida or paper");
    last_event_t_ = te;
    if (d_.closed) {
      sol_.intervals.push_back({contact_start_, t_});
      // The rod end and the beam point moved together: remove the integration drift of
      // u - w so that the opening gap starts from exactly zero.
      y_[2 * N_] = d_.g0 + d_.beam_deflection(y_.data());
    } else {
      contact_start_ = t_;
    }
    d_.closed = !d_.closed;
    ++sol_.events;
    after_event_ = true;
  }

  /// @brief Integrates a copy of (ta, ya) to tb with the auxiliary driver (used by root
  /// finding); the result stays valid until the next call.
  const std::vector<double>& integrate_copy(double ta, const std::vector<double>& ya, double tb) {
    return detail::integrate_copy(aux_.get(), ta, ya, tb, tmp_, sol_.steps, "rod-on-beam");
  }

  /// @brief Stores R = P + R(t - T) at tt in the reflection memory.
  void memory_sample(double tt, const double* yy) { mem_.add(tt, d_.force(tt, yy) + d_.delayed(tt)); }

  /// @brief Updates the extremes of the deflection and of the contact force.
  void track(double tt, const double* yy) {
    const double w = d_.beam_deflection(yy);
    if (w > sol_.w_max) {
      sol_.w_max = w;
      sol_.t_w_max = tt;
    }
    sol_.w_min = std::min(sol_.w_min, w);
    sol_.peak_P = std::max(sol_.peak_P, d_.force(tt, yy));
  }

  /// @brief True if the next output time is exactly stop (s).
  bool next_output_is(double stop) const { return out_i_ < out_t_.size() && out_t_[out_i_] == stop; }

  /// @brief Writes the output row at the current state and moves to the next output time.
  void write_row() {
    sol_.rows.push_back(make_row(t_, y_.data()));
    ++out_i_;
  }

  /// @brief The output row of the state (t, y).
  RodOnBeamRow make_row(double t, const double* y) const {
    RodOnBeamRow r;
    r.t = t;
    r.closed = d_.closed;
    const double rho = d_.delayed(t);
    r.P = d_.force(t, y);
    r.gap = d_.closed ? 0.0 : d_.gap(y);
    r.u = y[2 * N_];
    r.du = s_.v0 - (r.P + 2.0 * rho) / d_.Z;
    r.w = d_.beam_deflection(y);
    r.dw = d_.beam_velocity(y);
    r.impulse = y[2 * N_ + 1];
    r.rod_work = y[2 * N_ + 2];
    add_beam_energies(y, r);
    return r;
  }

  /// @brief Adds the beam's modal kinetic and strain energy (J) and momentum (N s) to r.
  void add_beam_energies(const double* y, RodOnBeamRow& r) const {
    for (int n = 0; n < N_; ++n) {
      r.beam_kinetic += 0.5 * d_.mass[n] * y[N_ + n] * y[N_ + n];
      r.beam_strain += 0.5 * d_.mass[n] * d_.omega2[n] * y[n] * y[n];
      r.beam_momentum += d_.momentum[n] * y[N_ + n];
    }
  }

  /// @brief Largest |beam modal energy - work of P on the rod end| over the output rows (J).
  double energy_balance_error() const {
    double E_err = 0.0;
    for (const auto& r : sol_.rows)
      E_err = std::max(E_err, std::abs(r.beam_kinetic + r.beam_strain - r.rod_work));
    return E_err;
  }

  const RodOnBeamSetup& s_;
  RodOnBeamSolution& sol_;
  DelayMemory& mem_;
  Dynamics d_;  // rhs() reads it through sys_
  const int N_;
  const std::size_t dim_;
  double t0_ = 0.0, T_ = 0.0, delta_ = 0.0;  // s: first touch, rod round trip, memory spacing
  std::vector<double> out_t_;                // s, output times
  std::size_t out_i_ = 0;                    // next output row
  std::vector<double> scale_;                // absolute tolerance scales
  gsl_odeiv2_system sys_{};                  // the drivers point at it
  Driver drv_, aux_;                         // main and root-finding drivers
  std::vector<double> tmp_;                  // integrate_copy's result
  std::vector<double> y_;                    // state, see rhs()
  double t_ = 0.0;                           // s
  double contact_start_ = 0.0;               // s, start of the open contact interval
  bool after_event_ = false;                 // the current piece starts at a located event
  double last_event_t_ = -std::numeric_limits<double>::infinity();  // s
  double eps_ = 0.0;                                                // s, time tolerance of breakpoints
  std::set<double> pending_;                                        // s, breakpoints still ahead
};

}  // namespace

RodOnBeam::RodOnBeam(const RodOnBeamSetup& setup) : s_(setup) { run(); }

void RodOnBeam::run() {
  gsl_set_error_handler_off();
  Integration integration(s_, sol_, mem_);
  integration.add_rows_before_touch();
  if (integration.all_rows_written()) return;
  integration.integrate_from_touch();
  integration.finish();
  if (s_.rod_fields) compute_rod_fields();
}

void RodOnBeam::compute_rod_fields() {
  for (auto& r : sol_.rows) r.rod = rod_field(r.t);
}

// As for free rods (CoaxialRods.cc): f(xi) = R(t - xi/c) leaving the contact end and
// g(xi) = -R(t - T + xi/c) returning from the free end; here R is smooth between memory pieces,
// so each piece is integrated by 5-point Gauss-Legendre (exact to degree 9) on panels of about
// 4 sample spacings, i.e. one radian of the highest modal frequency: far below the memory's error.
RodField RodOnBeam::rod_field(double t) const {
  const Rod& rod = s_.rod;
  const double c = rod.wave_speed(), T = rod.round_trip(), L = rod.length, Z = rod.impedance();
  const double t0 = s_.v0 > 0.0 ? s_.gap / s_.v0 : std::numeric_limits<double>::infinity();
  RodField r;
  const double rA = rod.rho * rod.area;
  if (t <= t0) {
    r.kinetic = 0.5 * rod.mass() * s_.v0 * s_.v0;
    r.momentum = rod.mass() * s_.v0;
    return r;
  }
  std::vector<double> xs = {0.0, L};
  for (std::size_t i = 0; i < mem_.pieces(); ++i) {
    const double s = mem_.piece_start(i);
    if (s < t - T || s > t) continue;
    const double xi = (s >= t - 0.5 * T) ? c * (t - s) : c * (s - t + T);
    if (xi > 0.0 && xi < L) xs.push_back(xi);
  }
  std::sort(xs.begin(), xs.end());
  const double r1 = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
  const double r2 = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
  const double w1 = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0, w2 = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
  const double gx[5] = {-r2, -r1, 0.0, r1, r2}, gw[5] = {w2, w1, 128.0 / 225.0, w1, w2};
  const double panel = 4.0 * c * sol_.sample_dt;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const double a = xs[i], b = xs[i + 1];
    if (b <= a) continue;
    const int np = std::max(1, static_cast<int>(std::ceil((b - a) / panel)));
    const double h = (b - a) / np;
    for (int p = 0; p < np; ++p) {
      const double mid = a + (p + 0.5) * h;
      for (int k = 0; k < 5; ++k) {
        const double xi = mid + 0.5 * h * gx[k], wq = 0.5 * h * gw[k];
        const double f = mem_.value(t - xi / c), g = -mem_.value(t - T + xi / c);
        const double v = s_.v0 + (g - f) / Z;
        r.strain += wq * (f + g) * (f + g) / (2.0 * rod.E * rod.area);
        r.kinetic += wq * 0.5 * rA * v * v;
        r.momentum += wq * rA * v;
      }
    }
  }
  return r;
}

ModeStudy converge_modes(RodOnBeamSetup setup, int modes_min, int modes_max, double tol) {
  ModeStudy study;
  const bool fields = setup.rod_fields;
  setup.rod_fields = false;  // only the final run needs the rod's field split
  std::unique_ptr<RodOnBeam> run;
  for (int n = std::max(1, modes_min);; n *= 2) {
    setup.modes = n;
    run = std::make_unique<RodOnBeam>(setup);
    const RodOnBeamSolution& sol = run->solution();
    study.table.push_back({n, sol.impulse, sol.intervals, sol.w_max});
    if (study.table.size() >= 2) {
      const auto& a = study.table[study.table.size() - 2];
      const auto& b = study.table.back();
      study.impulse_change = std::abs(b.impulse - a.impulse) / std::max(std::abs(b.impulse), 1e-300);
      study.time_change = std::numeric_limits<double>::infinity();
      if (a.intervals.size() == b.intervals.size()) {
        study.time_change = 0.0;
        for (std::size_t i = 0; i < a.intervals.size(); ++i)
          for (int k = 0; k < 2; ++k)
            study.time_change = std::max(study.time_change, std::abs(a.intervals[i][k] - b.intervals[i][k]));
      }
      const double duration = b.intervals.empty() ? 1.0 : b.intervals[0][1] - b.intervals[0][0];
      if (study.impulse_change <= tol && study.time_change <= tol * duration) {
        study.converged = true;
        break;
      }
    }
    if (2 * n > modes_max) break;
  }
  if (fields) run->compute_rod_fields();
  study.solution = run->solution();
  return study;
}

}  // namespace beamimpact::exact
