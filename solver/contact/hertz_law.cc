#include <solver/contact/hertz_law.hpp>

#include <algorithm>
#include <cmath>

namespace beamimpact::paper {

double hertz_force(double a, double b, double k) {
  if (!(a < 0.0)) return 0.0;
  const double bk = b * k;
  double x = std::min(-a, std::cbrt((a / bk) * (a / bk)));  // both >= the root
  for (int it = 0; it < 100; ++it) {
    const double s = std::sqrt(x);
    const double h = a + bk * x * s + x;
    const double step = h / (1.5 * bk * s + 1.0);
    const double next = std::max(0.0, x - step);
    if (!(next < x) || x - next <= 1e-15 * x) {
      x = std::min(x, next);
      break;
    }
    x = next;
  }
  return k * x * std::sqrt(x);
}

double hertz_energy(double R, double k) {
  if (!(R > 0.0)) return 0.0;
  return 0.4 * R * std::cbrt((R / k) * (R / k));
}

}  // namespace beamimpact::paper
