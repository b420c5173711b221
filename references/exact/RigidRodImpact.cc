#include <references/exact/RigidRodImpact.hpp>

#include <cmath>

namespace beamimpact::exact {

RigidRodImpact rigid_rod_impact(double m, double l, double theta, double V, double mu, double e) {
  const double s = std::sin(theta), c = std::cos(theta);
  RigidRodImpact r;
  r.mu_star = 3 * s * c / (1 + 3 * s * s);
  r.stick = mu >= r.mu_star;
  if (r.stick) {
    r.p_n = (1 + e) * m * V * (1 + 3 * s * s) / 4;
    r.p_t = r.p_n * r.mu_star;
  } else {
    r.p_n = (1 + e) * m * V / (1 + 3 * c * c - 3 * s * c * mu);
    r.p_t = mu * r.p_n;
  }
  // Newton's laws with the impulses at the end (l/2 from the centre, below and on the side
  // opposite to the centre's): the centre's velocity and the spin.
  r.v_n = -V + r.p_n / m;
  r.v_t = r.p_t / m;
  r.omega = (l / 2) * (c * r.p_n - s * r.p_t) / (m * l * l / 12);
  return r;
}

}  // namespace beamimpact::exact
