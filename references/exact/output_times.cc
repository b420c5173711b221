#include <references/exact/output_times.hpp>

#include <algorithm>
#include <cmath>

namespace beamimpact::exact {

std::vector<double> output_times(double dt_out, double t_end) {
  std::vector<double> out_t;
  for (long k = 0;; ++k) {
    const double t = static_cast<double>(k) * dt_out;
    if (t > t_end * (1.0 + 1e-12)) break;
    out_t.push_back(std::min(t, t_end));
  }
  return out_t;
}

double output_row_count(double dt_out, double t_end) {
  return std::floor(t_end / dt_out * (1.0 + 1e-12)) + 1.0;
}

}  // namespace beamimpact::exact
