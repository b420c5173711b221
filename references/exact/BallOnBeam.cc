#include <references/exact/BallOnBeam.hpp>
#include <references/exact/gsl_ode_impl.hpp>
#include <references/exact/output_times.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>

namespace beamimpact::exact {
namespace {

// y = [q_1..q_N, q_1'..q_N', z (striker), z', J (impulse of R)]
struct BallDynamics {
  int N = 0;
  std::vector<double> phi, omega2;
  double M = 0.0, m = 0.0, k = 0.0, g0 = 0.0;

  double w(const double* y) const {
    double s = 0.0;
    for (int n = 0; n < N; ++n) s += phi[n] * y[n];
    return s;
  }
  double dw(const double* y) const {
    double s = 0.0;
    for (int n = 0; n < N; ++n) s += phi[n] * y[N + n];
    return s;
  }
  /// Indentation (m): the striker's advance past the beam point under it.
  double delta(const double* y) const { return y[2 * N] - g0 - w(y); }
  /// Indentation rate (m/s): its zero inside a contact is the contact's peak force.
  double rate(const double* y) const { return y[2 * N + 1] - dw(y); }
  double force(const double* y) const {
    const double d = delta(y);
    return d > 0.0 ? k * d * std::sqrt(d) : 0.0;
  }
};

int ball_rhs(double, const double y[], double f[], void* params) {
  const auto& d = *static_cast<const BallDynamics*>(params);
  const int N = d.N;
  const double R = d.force(y);
  for (int n = 0; n < N; ++n) {
    f[n] = y[N + n];
    f[N + n] = -d.omega2[n] * y[n] + d.phi[n] * R / d.M;
  }
  f[2 * N] = y[2 * N + 1];
  f[2 * N + 1] = -R / d.m;
  f[2 * N + 2] = R;
  return GSL_SUCCESS;
}

using detail::Driver;

void check(int status, const char* what) { detail::check_gsl(status, "ball-on-beam", what); }

/// @brief Brent's root of f in (a, b), f(a) and f(b) of opposite signs (or f(b) == 0).
/// @return the end of the final bracket on b's side (f there has f(b)'s sign)
double brent_root(const std::function<double(double)>& f, double a, double b) {
  gsl_function F;
  F.function = [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); };
  F.params = const_cast<std::function<double(double)>*>(&f);
  const double fb = f(b);
  if (fb == 0.0 || f(a) * fb > 0.0) return b;  // on b already, or no bracket left by roundoff
  std::unique_ptr<gsl_root_fsolver, void (*)(gsl_root_fsolver*)> s(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  check(gsl_root_fsolver_set(s.get(), &F, a, b), "root bracketing");
  double lo = a, hi = b;
  for (int it = 0; it < 200; ++it) {
    check(gsl_root_fsolver_iterate(s.get()), "root finding");
    lo = gsl_root_fsolver_x_lower(s.get());
    hi = gsl_root_fsolver_x_upper(s.get());
    if (gsl_root_test_interval(lo, hi, 1e-14 * (1.0 + std::abs(hi)), 0.0) == GSL_SUCCESS) break;
  }
  return (f(hi) > 0.0) == (fb > 0.0) ? hi : lo;
}

/// @brief The integration of one solution: free flight to the first touch, then stops every
/// stop_dt (and at the output times); between two stops a change of the indentation's sign is a
/// contact end, located and restarted from, and a change of its rate's sign inside a contact is
/// that contact's peak, located.
class BallIntegration {
 public:
  BallIntegration(const BallOnBeamSetup& s, BallOnBeamSolution& sol) : s_(s), sol_(sol) {
    d_.N = N_ = s.modes;
    d_.M = s.beam.modal_mass();
    d_.m = s.mass;
    d_.k = s.stiffness;
    d_.g0 = s.gap;
    for (int n = 1; n <= N_; ++n) {
      d_.phi.push_back(s.beam.shape(n, s.x_c));
      d_.omega2.push_back(s.beam.omega(n) * s.beam.omega(n));
    }
    dim_ = static_cast<std::size_t>(2 * N_ + 3);
    sol_.modes = N_;
    sol_.stop_dt = h_ = ball_stop_spacing(s, N_);
    t0_ = s.v0 > 0.0 ? s.gap / s.v0 : std::numeric_limits<double>::infinity();
    out_t_ = output_times(s.dt_out, s.t_end);
  }
  BallIntegration(const BallIntegration&) = delete;  // the drivers point into it
  BallIntegration& operator=(const BallIntegration&) = delete;

  void run() {
    y_.assign(dim_, 0.0);
    y_[2 * N_ + 1] = s_.v0;
    while (out_i_ < out_t_.size() && out_t_[out_i_] < t0_) {  // free flight
      y_[2 * N_] = s_.v0 * out_t_[out_i_];
      write_row(out_t_[out_i_]);
    }
    if (t0_ <= s_.t_end) integrate_from_touch();
    sol_.impulse = y_[2 * N_ + 2];
    sol_.final_velocity = s_.v0 - sol_.impulse / s_.mass;
    const double E0 = 0.5 * s_.mass * s_.v0 * s_.v0;
    for (const BallOnBeamRow& r : sol_.rows)
      sol_.energy_error = std::max(sol_.energy_error, std::abs(0.5 * s_.mass * r.dz * r.dz + r.beam_kinetic +
                                                               r.beam_strain + r.spring - E0));
  }

 private:
  void allocate_drivers() {
    const double tc = half_space_contact_time(s_.mass, s_.stiffness, s_.v0);
    const double X = s_.v0 * tc, V = s_.v0, J = s_.mass * s_.v0;
    scale_.assign(dim_, X);
    for (int n = 0; n < N_; ++n) scale_[N_ + n] = V;
    scale_[2 * N_ + 1] = V;
    scale_[2 * N_ + 2] = J;
    sys_ = {ball_rhs, nullptr, dim_, &d_};
    for (Driver* d : {&drv_, &aux_})
      d->reset(gsl_odeiv2_driver_alloc_scaled_new(&sys_, gsl_odeiv2_step_rk8pd, 0.1 * h_, s_.rtol, s_.rtol,
                                                  1.0, 0.0, scale_.data()));
  }

  void integrate_from_touch() {
    allocate_drivers();
    t_ = t0_;
    y_[2 * N_] = s_.gap;
    closed_ = true;  // delta = 0 and rising at v0
    open_interval();
    long i = 0;  // stops at t0 + i h
    while (t_ < s_.t_end) {
      double stop = std::min(t0_ + static_cast<double>(i + 1) * h_, s_.t_end);
      const bool out = out_i_ < out_t_.size() && out_t_[out_i_] <= stop;
      if (out) stop = out_t_[out_i_];
      if (stop > t_ && step_to(stop)) continue;  // stopped at a contact end before `stop`
      if (out) write_row(stop);
      if (stop >= t0_ + static_cast<double>(i + 1) * h_) ++i;
      if (stop >= s_.t_end) break;
    }
    while (out_i_ < out_t_.size()) write_row(out_t_[out_i_]);
    if (closed_) close_interval(s_.t_end);
  }

  /// @brief Integrates from t_ to stop; at a contact end inside, moves to it instead.
  /// @return true if the integration stopped at a contact end
  bool step_to(double stop) {
    const double ta = t_;
    const std::vector<double> ya = y_;
    const double rate_a = d_.rate(ya.data());
    gsl_odeiv2_driver_reset(drv_.get());
    check(gsl_odeiv2_driver_apply(drv_.get(), &t_, stop, y_.data()), "integration");
    sol_.steps += static_cast<long>(drv_->e->count);
    const auto at = [&](double t, auto&& g) { return g(integrate_copy(ta, ya, t).data()); };
    if (closed_ && rate_a > 0.0 && d_.rate(y_.data()) <= 0.0) {  // this contact's peak
      const double tp =
          brent_root([&](double t) { return at(t, [&](const double* y) { return d_.rate(y); }); }, ta, t_);
      track_peak(tp, d_.force(integrate_copy(ta, ya, tp).data()));
    }
    track_peak(t_, d_.force(y_.data()));
    const double dl = d_.delta(y_.data());
    if (closed_ ? dl > 0.0 : dl <= 0.0) return false;
    const double te =
        brent_root([&](double t) { return at(t, [&](const double* y) { return d_.delta(y); }); }, ta, t_);
    y_ = integrate_copy(ta, ya, te);
    t_ = te;
    if (closed_)
      close_interval(te);
    else
      open_interval();
    closed_ = !closed_;
    return true;
  }

  const std::vector<double>& integrate_copy(double ta, const std::vector<double>& ya, double tb) {
    return detail::integrate_copy(aux_.get(), ta, ya, tb, tmp_, sol_.steps, "ball-on-beam");
  }

  void open_interval() {
    sol_.intervals.push_back({t_, t_});
    sol_.interval_peaks.push_back(0.0);
    impulse_at_open_ = y_[2 * N_ + 2];
  }
  void close_interval(double te) {
    sol_.intervals.back()[1] = te;
    sol_.interval_impulses.push_back(y_[2 * N_ + 2] - impulse_at_open_);
  }

  void track_peak(double t, double R) {
    if (!sol_.interval_peaks.empty()) sol_.interval_peaks.back() = std::max(sol_.interval_peaks.back(), R);
    if (R > sol_.peak_R) {
      sol_.peak_R = R;
      sol_.t_peak = t;
      sol_.delta_max = std::pow(R / s_.stiffness, 2.0 / 3.0);
    }
  }

  /// @brief Writes the row at time t from the current state and moves to the next output time.
  void write_row(double t) {
    const double* y = y_.data();
    BallOnBeamRow r;
    r.t = t;
    r.R = d_.force(y);
    r.gap = -d_.delta(y);
    r.z = y[2 * N_];
    r.dz = y[2 * N_ + 1];
    r.w = d_.w(y);
    r.dw = d_.dw(y);
    r.impulse = y[2 * N_ + 2];
    const double dl = std::max(0.0, -r.gap);
    r.spring = 0.4 * s_.stiffness * dl * dl * std::sqrt(dl);
    for (int n = 0; n < N_; ++n) {
      r.beam_kinetic += 0.5 * d_.M * y[N_ + n] * y[N_ + n];
      r.beam_strain += 0.5 * d_.M * d_.omega2[n] * y[n] * y[n];
      r.beam_momentum += s_.beam.rho * s_.beam.area * s_.beam.shape_integral(n + 1) * y[N_ + n];
    }
    if (r.w > sol_.w_max) {
      sol_.w_max = r.w;
      sol_.t_w_max = t;
    }
    sol_.rows.push_back(r);
    ++out_i_;
  }

  const BallOnBeamSetup& s_;
  BallOnBeamSolution& sol_;
  BallDynamics d_;  // ball_rhs() reads it through sys_
  int N_ = 0;
  std::size_t dim_ = 0;
  double h_ = 0.0, t0_ = 0.0, t_ = 0.0;  // s: stop spacing, first touch, now
  std::vector<double> out_t_;            // s, output times
  std::size_t out_i_ = 0;                // next output row
  std::vector<double> scale_, y_, tmp_;  // tolerance scales, state, integrate_copy's result
  gsl_odeiv2_system sys_{};
  Driver drv_, aux_;  // main and root-finding drivers
  bool closed_ = false;
  double impulse_at_open_ = 0.0;  // N s
};

}  // namespace

double half_space_contact_time(double mass, double stiffness, double v0) {
  // (4/5) B(2/5, 1/2) = 2.9432 (Johnson 1985, section 11.4), from Gamma functions.
  const double c = 0.8 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  const double delta_max = std::pow(1.25 * mass * v0 * v0 / stiffness, 0.4);
  return c * delta_max / v0;
}

double ball_stop_spacing(const BallOnBeamSetup& s, int modes) {
  return std::min(0.25 / s.beam.omega(modes), half_space_contact_time(s.mass, s.stiffness, s.v0) / 400.0);
}

BallOnBeamSolution solve_ball_on_beam(const BallOnBeamSetup& setup) {
  gsl_set_error_handler_off();
  if (!(setup.mass > 0.0 && setup.stiffness > 0.0 && setup.v0 > 0.0 && setup.modes >= 1 &&
        setup.dt_out > 0.0))
    throw std::invalid_argument("ball-on-beam: expected mass, stiffness, v0, dt_out > 0 and modes >= 1");
  BallOnBeamSolution sol;
  BallIntegration integration(setup, sol);
  integration.run();
  return sol;
}

BallModeStudy converge_ball_modes(BallOnBeamSetup setup, int modes_min, int modes_max, double tol) {
  BallModeStudy study;
  for (int n = std::max(1, modes_min);; n *= 2) {
    setup.modes = n;
    study.solution = solve_ball_on_beam(setup);
    const BallOnBeamSolution& s = study.solution;
    study.table.push_back({n, s.impulse, s.peak_R, s.intervals});
    if (study.table.size() >= 2) {
      const BallModeEntry& a = study.table[study.table.size() - 2];
      const BallModeEntry& b = study.table.back();
      study.change = std::max(std::abs(b.impulse - a.impulse) / std::abs(b.impulse),
                              std::abs(b.peak_R - a.peak_R) / b.peak_R);
      if (a.intervals.size() != b.intervals.size()) {
        study.change = std::numeric_limits<double>::infinity();
      } else if (!b.intervals.empty()) {
        const double duration = b.intervals[0][1] - b.intervals[0][0];
        for (std::size_t i = 0; i < a.intervals.size(); ++i)
          for (int k = 0; k < 2; ++k)
            study.change = std::max(study.change, std::abs(a.intervals[i][k] - b.intervals[i][k]) / duration);
      }
      if (study.change <= tol) {
        study.converged = true;
        break;
      }
    }
    if (2 * n > modes_max) break;
  }
  return study;
}

}  // namespace beamimpact::exact
