#include <solver/model/frame_element.hpp>

namespace beamimpact {

Mat6 frame_stiffness_from_terms(double ea, double k1, double k2, double k3, double k4) {
  Mat6 k;
  // clang-format off
  k <<  ea,   0,   0, -ea,   0,   0,
         0,  k1,  k2,   0, -k1,  k2,
         0,  k2,  k3,   0, -k2,  k4,
       -ea,   0,   0,  ea,   0,   0,
         0, -k1, -k2,   0,  k1, -k2,
         0,  k2,  k4,   0, -k2,  k3;
  // clang-format on
  return k;
}

Mat6 frame_stiffness_local(double E, double A, double I, double L) {
  const double ei = E * I;
  return frame_stiffness_from_terms(E * A / L, 12.0 * ei / (L * L * L), 6.0 * ei / (L * L), 4.0 * ei / L,
                                    2.0 * ei / L);
}

Vec6 frame_mass_lumped(double rho, double A, double I, double L, RotaryInertia rotary) {
  const double m = rho * A * L;
  // HRZ: diagonal scaled so translations keep m/2; the rotation then gets m L^2/78.
  const double j = rotary == RotaryInertia::kHrz ? m * L * L / 78.0 : rho * I * L / 2.0;
  Vec6 d;
  d << m / 2, m / 2, j, m / 2, m / 2, j;
  return d;
}

Mat6 frame_mass_consistent_local(double rho, double A, double L) {
  const double m = rho * A * L;
  const double a = m / 6.0, b = m / 420.0;
  Mat6 M = Mat6::Zero();
  M(0, 0) = M(3, 3) = 2 * a;
  M(0, 3) = M(3, 0) = a;
  const int t[4] = {1, 2, 4, 5};
  // clang-format off
  const double h[4][4] = {{156,      22 * L,    54,     -13 * L},
                          {22 * L,   4 * L * L, 13 * L, -3 * L * L},
                          {54,       13 * L,    156,    -22 * L},
                          {-13 * L, -3 * L * L, -22 * L, 4 * L * L}};
  // clang-format on
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) M(t[i], t[j]) = b * h[i][j];
  return M;
}

Mat6 frame_rotation(double c, double s) {
  Mat6 T = Mat6::Zero();
  for (int n = 0; n < 2; ++n) {
    const int o = 3 * n;
    T(o, o) = c;
    T(o, o + 1) = s;
    T(o + 1, o) = -s;
    T(o + 1, o + 1) = c;
    T(o + 2, o + 2) = 1.0;
  }
  return T;
}

Mat6 to_global(const Mat6& local, double c, double s) {
  const Mat6 T = frame_rotation(c, s);
  return T.transpose() * local * T;
}

Eigen::Matrix2d bar_stiffness(double E, double A, double L) {
  const double k = E * A / L;
  return (Eigen::Matrix2d() << k, -k, -k, k).finished();
}

Eigen::Vector2d bar_mass_lumped(double rho, double A, double L) {
  return Eigen::Vector2d::Constant(rho * A * L / 2.0);
}

Eigen::Matrix2d bar_mass_consistent(double rho, double A, double L) {
  const double a = rho * A * L / 6.0;
  return (Eigen::Matrix2d() << 2 * a, a, a, 2 * a).finished();
}

}  // namespace beamimpact
