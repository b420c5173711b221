#include <references/exact/CoaxialRods.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace beamimpact::exact {

// Waves in rod X, xi = distance from its contact end, compressive force positive: f(t - xi/c)
// runs away from the contact end, g(t + xi/c) back towards it; the force is f + g and the
// particle velocity away from the contact (f - g) / Z. At the contact end f = P - g. A free far
// end (zero force) returns g(t) = -f(t - T), a fixed one (zero velocity) g(t) = +f(t - T): with
// eps = +1 (free) or -1 (fixed), f = P + eps S and S(t) = f(t - T) = sum_{k>=1} eps^(k-1) P(t - k T),
// so the contact end moves at (f - g) / Z = (P + 2 eps S) / Z, away from the contact.
CoaxialRods::CoaxialRods(const Rod& a, const Rod& b, double v0, double gap, double t_end, FarEnd far)
    : a_(a),
      b_(b),
      v0_(v0),
      gap0_(gap),
      t_end_(t_end),
      t0_(v0 > 0.0 ? gap / v0 : std::numeric_limits<double>::infinity()),
      eb_(far == FarEnd::kFixed ? -1.0 : 1.0) {
  solve();
}

const RodsSegment& CoaxialRods::piece_at(double s) const {
  auto it = std::upper_bound(segs_.begin(), segs_.end(), s,
                             [](double x, const RodsSegment& g) { return x < g.start; });
  return it == segs_.begin() ? *it : *std::prev(it);
}

// R_X(s) = P(s) + eps_X S_X(s), with S_X(s) = sum_{k>=1} eps_X^(k-1) P(s - k T_X) = R_X(s - T_X):
// constant on every piece (each piece start echoes after T_A and T_B), zero before the touch.
double CoaxialRods::wave(double s, bool striker) const {
  if (s < t0_) return 0.0;
  const RodsSegment& q = piece_at(s);
  return striker ? q.ra : q.rb;
}

void CoaxialRods::solve() {
  const double ZA = a_.impedance(), ZB = b_.impedance();
  const double TA = a_.round_trip(), TB = b_.round_trip();
  segs_.push_back({0.0, 0.0, v0_, 0.0, 0.0, 0.0, gap0_, false});
  if (!(t0_ < t_end_)) return;
  // Two breakpoints closer than eps are one (equal transit times computed with roundoff).
  const double eps = 1e-12 * std::max({TA, TB, t_end_});
  // |P_trial| below tolP is an exact zero polluted by roundoff: the zero-force, zero-gap phase.
  const double tolP = 1e-10 * v0_ / (1.0 / ZA + 1.0 / ZB);
  std::set<double> pending;
  double s = t0_, ua = gap0_, ub = 0.0, g = 0.0;
  bool closed = true;
  pending.insert({s + TA, s + TB});
  while (s < t_end_) {
    while (!pending.empty() && *pending.begin() <= s + eps) pending.erase(pending.begin());
    const double nb = *pending.begin();
    // P is constant on (s, nb): evaluate the memories at the midpoint, away from any jump.
    const double mid = 0.5 * (s + nb);
    const double SA = wave(mid - TA, true), SB = wave(mid - TB, false);
    double P = 0.0, va = v0_ - 2.0 * SA / ZA, vb = 2.0 * eb_ * SB / ZB;
    if (closed) {
      const double trial = (v0_ - 2.0 * SA / ZA - 2.0 * eb_ * SB / ZB) / (1.0 / ZA + 1.0 / ZB);
      if (trial > tolP) {
        P = trial;
        va = vb = v0_ - (P + 2.0 * SA) / ZA;
      } else if (trial >= -tolP) {
        vb = va;  // zero force, gap stays closed: the ends move together
      } else {
        closed = false;  // the ends part: the gap opens at vb - va > 0
      }
    }
    segs_.push_back({s, P, va, vb, ua, ub, g, closed, P + SA, P + eb_ * SB, 0.0});
    double end = nb;
    bool recontact = false;
    if (!closed && vb < va) {
      const double te = s + g / (va - vb);  // exact: the gap is linear on the piece
      if (te < nb - eps) {
        end = te;
        recontact = true;
      }
    }
    ua += va * (end - s);
    ub += vb * (end - s);
    g = closed ? 0.0 : g + (vb - va) * (end - s);
    if (recontact) {
      g = 0.0;
      closed = true;
    }
    s = end;
    pending.insert({s + TA, s + TB});  // every piece start echoes after each round trip
  }
  double J = 0.0;  // the impulse at each piece start, summed in time order
  for (std::size_t i = 0; i + 1 < segs_.size(); ++i) {
    segs_[i].impulse = J;
    J += segs_[i].P * (segs_[i + 1].start - segs_[i].start);
  }
  segs_.back().impulse = J;
}

RodsEndState CoaxialRods::state(double t) const {
  auto it = std::upper_bound(segs_.begin(), segs_.end(), t,
                             [](double x, const RodsSegment& g) { return x < g.start; });
  const RodsSegment& q = *std::prev(it);
  const double d = t - q.start;
  RodsEndState r;
  r.P = q.P;
  r.va = q.va;
  r.vb = q.vb;
  r.ua = q.ua + q.va * d;
  r.ub = q.ub + q.vb * d;
  r.closed = q.closed;
  r.gap = q.closed ? 0.0 : q.gap + (q.vb - q.va) * d;
  return r;
}

double CoaxialRods::impulse(double t) const {
  // The last piece starting before t (none: no impulse yet).
  auto it = std::lower_bound(segs_.begin(), segs_.end(), t,
                             [](const RodsSegment& g, double x) { return g.start < x; });
  if (it == segs_.begin()) return 0.0;
  const RodsSegment& q = *std::prev(it);
  return q.impulse + q.P * (t - q.start);
}

double CoaxialRods::peak_force() const {
  double p = 0.0;
  for (const auto& q : segs_) p = std::max(p, q.P);
  return p;
}

std::vector<std::array<double, 2>> CoaxialRods::force_intervals() const {
  std::vector<std::array<double, 2>> out;
  bool open = false;
  double start = 0.0, last = 0.0;
  for (std::size_t i = 0; i < segs_.size() && segs_[i].start < t_end_; ++i) {
    const double end = (i + 1 < segs_.size()) ? std::min(segs_[i + 1].start, t_end_) : t_end_;
    if (segs_[i].P > 0.0) {
      if (!open) start = segs_[i].start;
      open = true;
      last = end;
    } else if (!segs_[i].closed && open) {  // the gap opened: the impact is over
      out.push_back({start, last});
      open = false;
    }
  }
  if (open) out.push_back({start, last});
  return out;
}

// The field in a rod at time t is two piecewise-constant force waves: f(xi) = R(t - xi/c)
// leaving the contact end and g(xi) = -eps R(t - T + xi/c) coming back after the far-end
// reflection (xi = distance from the contact end). R jumps only at piece starts, so the pieces
// starting in the window [t - T, t] cut the rod into intervals that are integrated exactly.
RodField CoaxialRods::field(const Rod& rod, double t, bool striker) const {
  const double c = rod.wave_speed(), T = rod.round_trip(), L = rod.length, Z = rod.impedance();
  const double eps = striker ? 1.0 : eb_;
  std::vector<double> xs = {0.0, L};
  auto j = std::lower_bound(segs_.begin() + 1, segs_.end(), t - T,
                            [](const RodsSegment& g, double x) { return g.start < x; });
  for (; j != segs_.end() && j->start <= t; ++j) {
    const double s = j->start;
    const double xi = (s >= t - 0.5 * T) ? c * (t - s) : c * (s - t + T);
    if (xi > 0.0 && xi < L) xs.push_back(xi);
  }
  std::sort(xs.begin(), xs.end());
  RodField r;
  const double rA = rod.rho * rod.area;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const double dx = xs[i + 1] - xs[i];
    if (dx <= 0.0) continue;
    const double xm = 0.5 * (xs[i] + xs[i + 1]);
    const double f = wave(t - xm / c, striker), g = -eps * wave(t - T + xm / c, striker);
    // Compressive waves: one moving away from the contact end carries particle velocity -f/Z
    // in the striker (+f/Z in the target); one moving back carries +g/Z (-g/Z).
    const double v = striker ? v0_ + (g - f) / Z : (f - g) / Z;
    r.strain += (f + g) * (f + g) / (2.0 * rod.E * rod.area) * dx;
    r.kinetic += 0.5 * rA * v * v * dx;
    r.momentum += rA * v * dx;
  }
  return r;
}

}  // namespace beamimpact::exact
