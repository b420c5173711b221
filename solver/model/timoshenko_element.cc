#include <solver/model/timoshenko_element.hpp>

#include <cmath>

namespace beamimpact {
namespace {

/// The interdependent shape functions at xi = x / L in [0, 1]: deflection N_v (m per DOF of
/// (v1, th1, v2, th2)) and rotation N_theta (rad per DOF), Friedman and Kosmatka (1993).
void shape(double xi, double L, double phi, double nv[4], double nt[4]) {
  const double d = 1.0 / (1.0 + phi), x2 = xi * xi, x3 = x2 * xi;
  nv[0] = d * (2 * x3 - 3 * x2 - phi * xi + 1 + phi);
  nv[1] = d * L * (x3 - (2 + phi / 2) * x2 + (1 + phi / 2) * xi);
  nv[2] = -d * (2 * x3 - 3 * x2 - phi * xi);
  nv[3] = d * L * (x3 - (1 - phi / 2) * x2 - (phi / 2) * xi);
  nt[0] = 6 * d / L * (x2 - xi);
  nt[1] = d * (3 * x2 - (4 + phi) * xi + 1 + phi);
  nt[2] = -6 * d / L * (x2 - xi);
  nt[3] = d * (3 * x2 - (2 - phi) * xi);
}

}  // namespace

double shear_parameter(double I, double A, double L, double kappa, double nu) {
  // 12 E I / (kappa G A L^2) with E / G = 2 (1 + nu).
  return 24.0 * (1.0 + nu) * I / (kappa * A * L * L);
}

Mat6 timoshenko_stiffness_local(double E, double A, double I, double L, double phi) {
  const double ea = E * A / L;
  const double b = E * I / ((1.0 + phi) * L * L * L);
  return frame_stiffness_from_terms(ea, 12 * b, 6 * b * L, (4 + phi) * b * L * L, (2 - phi) * b * L * L);
}

Mat6 timoshenko_mass_consistent_local(double rho, double A, double I, double L, double phi) {
  const double m = rho * A * L;
  Mat6 M = Mat6::Zero();
  M(0, 0) = M(3, 3) = m / 3.0;
  M(0, 3) = M(3, 0) = m / 6.0;
  // 4-point Gauss-Legendre on [0, 1]: exact for the degree-6 products N_v N_v.
  const double g = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
  const double h = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
  const double wg = (18.0 - std::sqrt(30.0)) / 36.0, wh = (18.0 + std::sqrt(30.0)) / 36.0;
  const double pts[4] = {-g, -h, h, g}, wts[4] = {wg, wh, wh, wg};
  const int t[4] = {1, 2, 4, 5};
  for (int q = 0; q < 4; ++q) {
    double nv[4], nt[4];
    shape(0.5 * (1.0 + pts[q]), L, phi, nv, nt);
    const double w = 0.5 * wts[q] * L;  // dx = L dxi, dxi = dpt / 2
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) M(t[i], t[j]) += w * (rho * A * nv[i] * nv[j] + rho * I * nt[i] * nt[j]);
  }
  return M;
}

Vec6 timoshenko_mass_lumped(double rho, double A, double I, double L) {
  const double m = rho * A * L, j = rho * I * L / 2.0;
  Vec6 d;
  d << m / 2, m / 2, j, m / 2, m / 2, j;
  return d;
}

std::array<double, 2> timoshenko_end_moments(double E, double I, double L, double phi, double th1,
                                             double th2) {
  const double k = E * I / ((1.0 + phi) * L);
  return {k * ((4 + phi) * th1 + (2 - phi) * th2), k * ((2 - phi) * th1 + (4 + phi) * th2)};
}

}  // namespace beamimpact
