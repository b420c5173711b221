#include <references/ida/penalty_law.hpp>

#include <cmath>
#include <stdexcept>

namespace beamimpact::ida {

double PenaltyLaw::slip_sign(double vt) const { return vt / std::sqrt(vt * vt + v_reg * v_reg); }

double PenaltyLaw::slip_sign_derivative(double vt) const {
  const double s = vt * vt + v_reg * v_reg;
  return v_reg * v_reg / (s * std::sqrt(s));
}

double restitution_for_damping_ratio(double zeta) {
  if (zeta < 0.0) throw std::invalid_argument("damping ratio must be >= 0");
  // Unit natural frequency; penetration d(0) = 0, d'(0) = 1. Release at d'' = 0 (force zero).
  if (zeta < 1.0 - 1e-9) {
    const double wd = std::sqrt(1.0 - zeta * zeta);
    // d'' = e^{-zeta t} (-2 zeta cos(wd t) + (2 zeta^2 - 1)/wd sin(wd t)) = 0
    const double t = std::atan2(2.0 * zeta * wd, 2.0 * zeta * zeta - 1.0) / wd;
    const double dd = std::exp(-zeta * t) * (std::cos(wd * t) - zeta / wd * std::sin(wd * t));
    return -dd;
  }
  if (zeta <= 1.0 + 1e-9) return std::exp(-2.0);
  const double r = std::sqrt(zeta * zeta - 1.0);
  const double q = (zeta - r) / (zeta + r);  // slow root / fast root, in (0, 1)
  return std::pow(q, (1.0 + q) / (1.0 - q));
}

double damping_ratio_for_restitution(double e) {
  if (!(e > 0.0 && e <= 1.0)) throw std::invalid_argument("restitution must lie in (0, 1]");
  if (e == 1.0) return 0.0;
  // e(zeta) falls monotonically from 1 (zeta = 0) to 0 (zeta -> infinity).
  double lo = 0.0, hi = 1.0;
  while (restitution_for_damping_ratio(hi) > e) hi *= 2.0;
  while (hi - lo > 1e-14 * hi) {
    const double mid = 0.5 * (lo + hi);
    (restitution_for_damping_ratio(mid) > e ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace beamimpact::ida
