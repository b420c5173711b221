#include <beamimpact/exact/RodOnBeam.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <beamimpact/util/Progress.hpp>
#include <gsl/gsl_roots.h>

namespace beamimpact::exact {
namespace {

// What the right-hand side needs: modal data, the contact mode and the delayed memory.
struct Dynamics {
  int N = 0;
  std::vector<double> phi, omega2;
  double M = 0.0, Z = 0.0, v0 = 0.0, T = 0.0, g0 = 0.0;
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
    dydt[N + n] = -d.omega2[n] * y[n] + d.phi[n] * P / d.M;
  }
  const double du = d.v0 - (P + 2.0 * rho) / d.Z;
  dydt[2 * N] = du;
  dydt[2 * N + 1] = P;
  dydt[2 * N + 2] = P * du;
  return GSL_SUCCESS;
}

struct DriverDeleter {
  void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};
using Driver = std::unique_ptr<gsl_odeiv2_driver, DriverDeleter>;

void check(int status, const char* what) {
  if (status != GSL_SUCCESS)
    throw std::runtime_error(std::string("rod-on-beam: ") + what + ": " + gsl_strerror(status));
}

}  // namespace

RodOnBeam::RodOnBeam(const RodOnBeamSetup& setup) : s_(setup) { run(); }

void RodOnBeam::run() {
  gsl_set_error_handler_off();
  const Rod& rod = s_.rod;
  const SimpleBeam& beam = s_.beam;
  Dynamics d;
  d.N = s_.modes;
  d.M = beam.modal_mass();
  d.Z = rod.impedance();
  d.v0 = s_.v0;
  d.T = rod.round_trip();
  d.g0 = s_.gap;
  d.mem = &mem_;
  for (int n = 1; n <= d.N; ++n) {
    d.phi.push_back(beam.shape(n, s_.x_c));
    d.omega2.push_back(beam.omega(n) * beam.omega(n));
  }
  const int N = d.N;
  const std::size_t dim = static_cast<std::size_t>(2 * N + 3);
  sol_.modes = N;
  const double t0 = s_.v0 > 0.0 ? s_.gap / s_.v0 : std::numeric_limits<double>::infinity();
  const double T = d.T;
  // Memory samples a quarter radian of the highest mode apart (see DelayMemory::value).
  const double delta = std::min(0.25 / beam.omega(N), T / 32.0);
  sol_.sample_dt = delta;

  // Output grid.
  std::vector<double> out_t;
  for (long k = 0;; ++k) {
    const double t = static_cast<double>(k) * s_.dt_out;
    if (t > s_.t_end * (1.0 + 1e-12)) break;
    out_t.push_back(std::min(t, s_.t_end));
  }
  std::size_t out_i = 0;
  auto energies = [&](const double* y, RodOnBeamRow& r) {
    for (int n = 0; n < N; ++n) {
      r.beam_kinetic += 0.5 * d.M * y[N + n] * y[N + n];
      r.beam_strain += 0.5 * d.M * d.omega2[n] * y[n] * y[n];
      r.beam_momentum += beam.rho * beam.area * beam.shape_integral(n + 1) * y[N + n];
    }
  };
  auto make_row = [&](double t, const double* y) {
    RodOnBeamRow r;
    r.t = t;
    r.closed = d.closed;
    const double rho = d.delayed(t);
    r.P = d.force(t, y);
    r.gap = d.closed ? 0.0 : d.gap(y);
    r.u = y[2 * N];
    r.du = s_.v0 - (r.P + 2.0 * rho) / d.Z;
    r.w = d.beam_deflection(y);
    r.dw = d.beam_velocity(y);
    r.impulse = y[2 * N + 1];
    r.rod_work = y[2 * N + 2];
    energies(y, r);
    return r;
  };
  // Rows before the first touch: rigid rod, beam at rest.
  while (out_i < out_t.size() && out_t[out_i] < t0) {
    RodOnBeamRow r;
    r.t = out_t[out_i++];
    r.u = s_.v0 * r.t;
    r.du = s_.v0;
    r.gap = s_.gap - r.u;
    r.rod.kinetic = 0.5 * rod.mass() * s_.v0 * s_.v0;
    r.rod.momentum = rod.mass() * s_.v0;
    sol_.rows.push_back(r);
  }
  if (out_i == out_t.size()) return;

  // Natural scales for the absolute tolerances: displacement v0 x (time scale), velocity v0.
  const double tc = std::min(T, s_.t_end - t0) > 0.0 ? std::min(T, s_.t_end - t0) : T;
  const double X = s_.v0 * tc, V = s_.v0, J = d.Z * s_.v0 * tc, W = J * s_.v0;
  std::vector<double> scale(dim, X);
  for (int n = 0; n < N; ++n) scale[N + n] = V;
  scale[2 * N + 1] = J;
  scale[2 * N + 2] = W;
  gsl_odeiv2_system sys = {rhs, nullptr, dim, &d};
  const double h0 = 0.1 * delta;
  Driver drv(gsl_odeiv2_driver_alloc_scaled_new(&sys, gsl_odeiv2_step_rk8pd, h0, s_.rtol,
                                                  s_.rtol, 1.0, 0.0, scale.data()));
  Driver aux(gsl_odeiv2_driver_alloc_scaled_new(&sys, gsl_odeiv2_step_rk8pd, h0, s_.rtol,
                                                 s_.rtol, 1.0, 0.0, scale.data()));
  // Integrates a copy of (ta, ya) to tb with the auxiliary driver (used by root finding).
  std::vector<double> tmp(dim);
  auto integrate_copy = [&](double ta, const std::vector<double>& ya, double tb) {
    tmp = ya;
    gsl_odeiv2_driver_reset(aux.get());
    double t = ta;
    if (tb > ta) check(gsl_odeiv2_driver_apply(aux.get(), &t, tb, tmp.data()), "integration");
    sol_.steps += static_cast<long>(aux->e->count);
    return tmp;
  };

  std::vector<double> y(dim, 0.0);
  y[2 * N] = s_.gap;  // the rod end has travelled the gap at first touch
  double t = t0;
  d.closed = true;
  double contact_start = t0;
  bool after_event = false;
  double last_event_t = -std::numeric_limits<double>::infinity();
  const double eps = 1e-12 * std::max(T, s_.t_end);
  std::set<double> pending;
  double E_err = 0.0;
  auto track = [&](double tt, const double* yy) {
    const double w = d.beam_deflection(yy);
    if (w > sol_.w_max) {
      sol_.w_max = w;
      sol_.t_w_max = tt;
    }
    sol_.w_min = std::min(sol_.w_min, w);
    sol_.peak_P = std::max(sol_.peak_P, d.force(tt, yy));
  };
  auto memory_sample = [&](double tt, const double* yy) {
    mem_.add(tt, d.force(tt, yy) + d.delayed(tt));
  };

  Progress progress("exact (" + std::to_string(N) + " modes)", s_.t_end);  // stderr, long runs only
  while (t < s_.t_end - eps) {
    progress.update(t);
    while (!pending.empty() && *pending.begin() <= t + eps) pending.erase(pending.begin());
    pending.insert(t + T);  // this piece start comes back after one round trip in the rod
    const double nb = std::min(*pending.begin(), s_.t_end);
    d.past = (t - T >= t0 - eps) ? mem_.piece_at(t - T + eps) : -1;
    // A breakpoint can switch the contact state by itself (the delayed wave jumps).
    if (!after_event) {
      if (d.closed && d.trial_force(t, y.data()) < 0.0) {
        d.closed = false;
        sol_.intervals.push_back({contact_start, t});
        y[2 * N] = d.g0 + d.beam_deflection(y.data());  // drift removal, as below
        ++sol_.events;
      } else if (!d.closed && d.gap(y.data()) <= 0.0 &&
                 d.beam_velocity(y.data()) < s_.v0 - 2.0 * d.delayed(t) / d.Z) {
        d.closed = true;
        contact_start = t;
        ++sol_.events;
      }
    }
    after_event = false;
    if (sol_.pieces == 0) sol_.first_P = d.force(t, y.data());
    ++sol_.pieces;
    mem_.start_piece(t);
    memory_sample(t, y.data());
    track(t, y.data());

    // Stops: memory samples every delta, the output times, and the piece end.
    std::vector<std::pair<double, bool>> stops;  // (time, is an output time)
    for (double s = t + delta; s < nb - 0.25 * delta; s += delta) stops.push_back({s, false});
    stops.push_back({nb, false});
    for (std::size_t k = out_i; k < out_t.size() && out_t[k] <= nb; ++k) stops.push_back({out_t[k], true});
    std::stable_sort(stops.begin(), stops.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });

    gsl_odeiv2_driver_reset(drv.get());
    bool event = false;
    for (const auto& [stop, is_out] : stops) {
      if (stop <= t) {
        if (is_out && stop == t && out_i < out_t.size() && out_t[out_i] == stop) {
          sol_.rows.push_back(make_row(t, y.data()));
          ++out_i;
        }
        continue;
      }
      const double t_prev = t;
      const std::vector<double> y_prev = y;
      const double f_prev = d.event(t, y.data());
      check(gsl_odeiv2_driver_apply(drv.get(), &t, stop, y.data()), "integration");
      sol_.steps += static_cast<long>(drv->e->count);
      gsl_odeiv2_driver_reset(drv.get());
      const double f_now = d.event(t, y.data());
      if (f_now < 0.0) {
        // Separation (force through 0) or re-contact (gap through 0): Brent on the event
        // function, each evaluation integrating from the last accepted stop.
        double te = t_prev;
        if (f_prev > 0.0) {
          struct RootCtx {
            decltype(integrate_copy)* integ;
            double ta;
            const std::vector<double>* ya;
            const Dynamics* dyn;
          } rc{&integrate_copy, t_prev, &y_prev, &d};
          gsl_function F;
          F.function = [](double x, void* p) {
            auto& c = *static_cast<RootCtx*>(p);
            const auto yx = (*c.integ)(c.ta, *c.ya, x);
            return c.dyn->event(x, yx.data());
          };
          F.params = &rc;
          std::unique_ptr<gsl_root_fsolver, void (*)(gsl_root_fsolver*)> owner(
              gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
          gsl_root_fsolver* solver = owner.get();
          check(gsl_root_fsolver_set(solver, &F, t_prev, t), "root bracketing");
          double lo = t_prev, hi = t;
          for (int it = 0; it < 200; ++it) {
            check(gsl_root_fsolver_iterate(solver), "root finding");
            lo = gsl_root_fsolver_x_lower(solver);
            hi = gsl_root_fsolver_x_upper(solver);
            if (gsl_root_test_interval(lo, hi, 1e-13 * (1.0 + std::abs(hi)), 0.0) == GSL_SUCCESS) break;
          }
          te = hi;  // just past the crossing: the event function is <= 0 there
        }
        y = integrate_copy(t_prev, y_prev, te);
        t = te;
        memory_sample(t, y.data());
        track(t, y.data());
        if (te <= last_event_t) throw std::runtime_error("rod-on-beam: event location made no progress");
        last_event_t = te;
        if (d.closed) {
          sol_.intervals.push_back({contact_start, t});
          // The rod end and the beam point moved together: remove the integration drift of
          // u - w so that the opening gap starts from exactly zero.
          y[2 * N] = d.g0 + d.beam_deflection(y.data());
        } else {
          contact_start = t;
        }
        d.closed = !d.closed;
        ++sol_.events;
        event = true;
        after_event = true;
        break;
      }
      if (!is_out) memory_sample(t, y.data());
      track(t, y.data());
      if (is_out && out_i < out_t.size() && out_t[out_i] == stop) {
        sol_.rows.push_back(make_row(t, y.data()));
        ++out_i;
      }
    }
    if (!event) t = nb;
  }
  if (d.closed) sol_.intervals.push_back({contact_start, s_.t_end});
  while (out_i < out_t.size()) sol_.rows.push_back(make_row(t, y.data())), ++out_i;
  sol_.impulse = y[2 * N + 1];
  for (const auto& r : sol_.rows) E_err = std::max(E_err, std::abs(r.beam_kinetic + r.beam_strain - r.rod_work));
  sol_.energy_error = E_err;
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
