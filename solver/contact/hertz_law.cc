#include <solver/contact/hertz_law.hpp>

#include <algorithm>
#include <cmath>

namespace beamimpact::paper {

double hertz_potential(double g, double k) {
  if (!(g < 0.0)) return 0.0;
  const double d = -g;
  return 0.4 * k * d * d * std::sqrt(d);
}

double hertz_secant_force(double x, double gp, double k) {
  const double dx = std::max(-x, 0.0), dp = std::max(-gp, 0.0);
  if (dx == 0.0 && dp == 0.0) return 0.0;
  const double u = std::sqrt(dx), v = std::sqrt(dp);
  if (dx > 0.0 && dp > 0.0) {
    // (u^5 - v^5) / (u^2 - v^2) = (u^4 + u^3 v + u^2 v^2 + u v^3 + v^4) / (u + v): no cancellation,
    // and 5/2 u^3 at u = v (the force k delta^(3/2) itself).
    const double num = (((u + v) * u + v * v) * u + v * v * v) * u + v * v * v * v;
    return 0.4 * k * num / (u + v);
  }
  // One gap open: the denominator is at least the other's indentation, never 0.
  return 0.4 * k * (dx * dx * u - dp * dp * v) / (gp - x);
}

double hertz_step_force(double a, double b, double gp, double k) {
  const double top = b * hertz_secant_force(a, gp, k);
  if (!(top > 0.0)) return 0.0;
  auto h = [&](double y) { return y - b * hertz_secant_force(a + y, gp, k); };
  double lo = 0.0, hi = top, hlo = h(lo), hhi = h(hi);
  if (hhi <= 0.0) return hi / b;  // D flat over the bracket (roundoff)
  int side = 0;
  for (int it = 0; it < 200 && hi - lo > 4e-16 * hi; ++it) {
    double y = (lo * hhi - hi * hlo) / (hhi - hlo);
    if (!(y > lo && y < hi)) y = 0.5 * (lo + hi);
    const double hy = h(y);
    if (hy == 0.0) return y / b;
    if (hy < 0.0) {
      lo = y;
      hlo = hy;
      if (side == -1) hhi *= 0.5;  // Illinois: halve the stale end's value
      side = -1;
    } else {
      hi = y;
      hhi = hy;
      if (side == 1) hlo *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (lo + hi) / b;
}

}  // namespace beamimpact::paper
