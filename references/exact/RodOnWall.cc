#include <references/exact/RodOnWall.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace beamimpact::exact {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// The smallest root s in (0, len] where G0 + G1 s + G2 s^2 (G0 >= 0, the gap) reaches zero
/// from above; kInf when none. G0 = 0 (just released, or touching) keeps only a root beyond 0.
double first_touch(double G0, double G1, double G2, double len) {
  double s = kInf;
  if (G0 <= 0.0) {
    if (G2 != 0.0 && -G1 / G2 > 0.0) s = -G1 / G2;
  } else if (G2 == 0.0) {
    if (G1 < 0.0) s = -G0 / G1;
  } else {
    const double disc = G1 * G1 - 4.0 * G2 * G0;
    if (disc >= 0.0) {
      const double q = -0.5 * (G1 + std::copysign(std::sqrt(disc), G1));
      for (double r : {q / G2, q != 0.0 ? G0 / q : kInf})
        if (r > 0.0) s = std::min(s, r);
    }
  }
  return s <= len ? s : kInf;
}

}  // namespace

RodOnWall::RodOnWall(const RodOnWallSetup& setup) : s_(setup) {
  if (!(s_.gap > 0.0) || !(s_.t_end > 0.0) || !(s_.rod.length > 0.0))
    throw std::invalid_argument("RodOnWall: expected a positive gap, length and end time");
  T2_ = s_.rod.round_trip();
  Z_ = s_.rod.impedance();
  eps_t_ = 1e-12 * std::max(T2_, s_.t_end);
  tol_gap_ = 1e-13 * (s_.rod.length + s_.gap);
  tol_v_ = 1e-12 * (std::abs(s_.v0) + std::abs(s_.g) * std::max(T2_, s_.t_end) + 1e-300);
  solve();
}

const RodOnWall::Piece* RodOnWall::piece_at(double s) const {
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), s,
                             [](double x, const Piece& p) { return x < p.start; });
  return it == pieces_.begin() ? nullptr : &*std::prev(it);
}

double RodOnWall::p_line(double s, double where) const {
  const Piece* p = piece_at(where);
  return p ? p->p0 + p->ps * (s - p->start) : 0.0;
}

double RodOnWall::next_q_break(double t) const {
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), t - T2_ + eps_t_,
                             [](double x, const Piece& p) { return x < p.start; });
  return it == pieces_.end() ? kInf : it->start + T2_;
}

double RodOnWall::advance(double t, bool& closed, double& gap, double& I, double& J) {
  const double tn = std::min({s_.t_end, next_q_break(t), t + T2_});
  // q = p(. - T2) is linear on (t, tn): its line is the piece holding the midpoint, shifted.
  const double mid = 0.5 * (t + tn) - T2_;
  const Piece* qp = piece_at(mid);
  const double qs = qp ? qp->ps : 0.0, q0 = p_line(t - T2_, mid);
  const double w0 = s_.v0 + s_.g * t;
  double p0, ps, end = tn;
  bool toggles = false;
  if (closed) {
    const double r0 = w0 - 2.0 * q0, rs = s_.g - 2.0 * qs;  // R / Z on the piece
    if (r0 < -tol_v_ || (r0 <= tol_v_ && rs < 0.0)) {       // released here
      closed = false;
      intervals_.back()[1] = t;
      return t;
    }
    p0 = w0 - q0;
    ps = s_.g - qs;
    if (rs < 0.0 && t + r0 / -rs < tn) {
      end = t + r0 / -rs;
      toggles = true;
    }
  } else {
    const double G1 = 2.0 * q0 - w0, G2 = qs - 0.5 * s_.g;                  // gap = gap + G1 s + G2 s^2
    if (gap <= tol_gap_ && (G1 < -tol_v_ || (G1 <= tol_v_ && G2 < 0.0))) {  // touches here
      closed = true;
      gap = 0.0;
      if (!intervals_.empty() && t - intervals_.back()[1] <= eps_t_)
        intervals_.back()[1] = s_.t_end;  // no time apart: one contact
      else
        intervals_.push_back({t, s_.t_end});
      return t;
    }
    p0 = q0;
    ps = qs;
    const double s = first_touch(gap <= tol_gap_ ? 0.0 : gap, G1, G2, tn - t);
    if (s < kInf) {
      end = t + s;
      toggles = true;
    }
  }
  pieces_.push_back({t, p0, ps, q0, qs, closed, gap, I, J});
  const double h = end - t, r0 = Z_ * (p0 - q0), rs = Z_ * (ps - qs);
  if (closed) peak_ = std::max({peak_, r0, r0 + rs * h});
  J += I * h + r0 * h * h / 2.0 + rs * h * h * h / 6.0;
  I += r0 * h + rs * h * h / 2.0;
  gap = closed ? 0.0 : gap + (2.0 * q0 - w0) * h + (qs - 0.5 * s_.g) * h * h;
  if (toggles) {
    if (closed) {
      closed = false;
      intervals_.back()[1] = end;
    } else {
      gap = 0.0;
      closed = true;
      intervals_.push_back({end, s_.t_end});
    }
  }
  return end;
}

void RodOnWall::solve() {
  bool closed = false;
  double t = 0.0, gap = s_.gap, I = 0.0, J = 0.0;
  int stalled = 0;
  while (t < s_.t_end) {
    const double next = advance(t, closed, gap, I, J);
    stalled = next > t ? 0 : stalled + 1;
    if (stalled > 2) throw std::logic_error("RodOnWall: the contact switches back and forth at one instant");
    t = next;
  }
}

RodOnWallState RodOnWall::state(double t) const {
  const Piece* p = piece_at(t);
  if (!p) return {0.0, s_.gap, 0.0, s_.v0, false};
  const double h = t - p->start, pv = p->p0 + p->ps * h, qv = p->q0 + p->qs * h;
  const double w0 = s_.v0 + s_.g * p->start;
  RodOnWallState st;
  st.closed = p->closed;
  st.R = p->closed ? Z_ * (pv - qv) : 0.0;
  st.gap = p->closed ? 0.0 : std::max(0.0, p->gap + (2.0 * p->q0 - w0) * h + (p->qs - 0.5 * s_.g) * h * h);
  st.u = s_.gap - st.gap;
  st.v = s_.v0 + s_.g * t - (pv + qv);
  return st;
}

double RodOnWall::impulse(double t) const {
  const Piece* p = piece_at(t);
  if (!p) return 0.0;
  const double h = t - p->start;
  return p->I + Z_ * ((p->p0 - p->q0) * h + (p->ps - p->qs) * h * h / 2.0);
}

double RodOnWall::load_work(double t) const {
  const Piece* p = piece_at(t);
  const double m = s_.rod.mass();
  double J = 0.0;
  if (p) {
    const double h = t - p->start;
    J = p->J + p->I * h + Z_ * ((p->p0 - p->q0) * h * h / 2.0 + (p->ps - p->qs) * h * h * h / 6.0);
  }
  // Mean displacement towards the wall: v0 t + g t^2 / 2 less the wall's push J / m.
  return m * s_.g * (s_.v0 * t + 0.5 * s_.g * t * t - J / m);
}

RodField RodOnWall::field(double t) const {
  const double c = s_.rod.wave_speed(), L = s_.rod.length, w = s_.v0 + s_.g * t;
  // Breaks in x of the two waves: x = c (t - start) and x = c (start + T2 - t), inside the rod
  // only for the pieces starting in (t - T2, t): those found by binary search (with a margin,
  // the test on x deciding), not every piece for every row.
  std::vector<double> xs = {0.0, L};
  auto p = std::lower_bound(pieces_.begin(), pieces_.end(), t - 1.01 * T2_,
                            [](const Piece& q, double x) { return q.start < x; });
  for (; p != pieces_.end() && p->start <= t + 0.01 * T2_; ++p)
    for (double x : {c * (t - p->start), c * (p->start + T2_ - t)})
      if (x > 0.0 && x < L) xs.push_back(x);
  std::sort(xs.begin(), xs.end());
  RodField f;
  const double rhoA = s_.rod.rho * s_.rod.area, EA = s_.rod.E * s_.rod.area;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const double a = xs[i], b = xs[i + 1];
    if (b - a <= 0.0) continue;
    const double m = 0.5 * (a + b);
    // Both waves are linear on (a, b): evaluate each on the line of the piece at the midpoint.
    const double out_at = t - m / c, back_at = t + m / c - T2_;
    double vd[3], e[3];
    const double x3[3] = {a, m, b};
    for (int k = 0; k < 3; ++k) {
      const double po = p_line(t - x3[k] / c, out_at), pb = p_line(t + x3[k] / c - T2_, back_at);
      vd[k] = w - (po + pb);
      e[k] = (pb - po) / c;
    }
    // Simpson's rule is exact for these quadratics.
    const double h6 = (b - a) / 6.0;
    f.kinetic += 0.5 * rhoA * h6 * (vd[0] * vd[0] + 4.0 * vd[1] * vd[1] + vd[2] * vd[2]);
    f.strain += 0.5 * EA * h6 * (e[0] * e[0] + 4.0 * e[1] * e[1] + e[2] * e[2]);
    f.momentum += rhoA * h6 * (vd[0] + 4.0 * vd[1] + vd[2]);
  }
  return f;
}

}  // namespace beamimpact::exact
