#include <references/exact/BeamModes.hpp>

#include <algorithm>

namespace beamimpact::exact {
namespace {

/// @brief Frequency (rad/s) of mode n >= 1 of a branch (1 or 2).
double branch_omega(const SimpleBeam& beam, const BeamShear& shear, long n, int branch) {
  if (!shear.timoshenko()) return beam.omega(static_cast<int>(n));
  return timoshenko_roots(beam, shear, n)[branch - 1].omega;
}

/// @brief How many of the `count` lowest modes are on the second branch: the largest m in
/// [0, count] with omega_2(m) <= omega_1(count - m + 1) (both branches rise with n).
long second_branch_modes(const SimpleBeam& beam, const BeamShear& shear, long count) {
  if (!shear.timoshenko()) return 0;
  long lo = 0, hi = count;  // the predicate holds at lo
  while (lo < hi) {
    const long m = lo + (hi - lo + 1) / 2;
    if (branch_omega(beam, shear, m, 2) <= branch_omega(beam, shear, count - m + 1, 1))
      lo = m;
    else
      hi = m - 1;
  }
  return lo;
}

/// @brief Mode n of a branch with its modal data at the struck point x_c (m).
BeamMode make_mode(const SimpleBeam& beam, const BeamShear& shear, double x_c, int n, int branch) {
  BeamMode m;
  m.n = n;
  m.branch = branch;
  m.shape = beam.shape(n, x_c);
  m.momentum = beam.rho * beam.area * beam.shape_integral(n);
  if (!shear.timoshenko()) {
    m.omega = beam.omega(n);
    m.mass = beam.modal_mass();
    return m;
  }
  const TimoshenkoRoot r = timoshenko_roots(beam, shear, n)[branch - 1];
  m.omega = r.omega;
  m.mass = beam.modal_mass() * (1.0 + beam.inertia / beam.area * r.ratio * r.ratio);
  return m;
}

}  // namespace

std::vector<BeamMode> beam_modes(const SimpleBeam& beam, const BeamShear& shear, double x_c, int count) {
  const int second = static_cast<int>(second_branch_modes(beam, shear, count));
  std::vector<BeamMode> modes;
  modes.reserve(static_cast<std::size_t>(count));
  for (int n = 1; n <= count - second; ++n) modes.push_back(make_mode(beam, shear, x_c, n, 1));
  for (int n = 1; n <= second; ++n) modes.push_back(make_mode(beam, shear, x_c, n, 2));
  std::stable_sort(modes.begin(), modes.end(),
                   [](const BeamMode& a, const BeamMode& b) { return a.omega < b.omega; });
  return modes;
}

double top_frequency(const SimpleBeam& beam, const BeamShear& shear, long count) {
  const long second = second_branch_modes(beam, shear, count);
  const double w1 = count - second > 0 ? branch_omega(beam, shear, count - second, 1) : 0.0;
  const double w2 = second > 0 ? branch_omega(beam, shear, second, 2) : 0.0;
  return std::max(w1, w2);
}

}  // namespace beamimpact::exact
