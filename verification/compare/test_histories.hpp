#pragma once
/// @file test_histories.hpp
/// @brief Synthetic histories with known answers, for the comparison and gate tests.

#include <cmath>
#include <functional>
#include <numbers>

#include <verification/compare/StoredRun.hpp>

namespace beamimpact::testing {
using verification::StoredRun;

/// @brief A one-contact history on t = 0, h, ..., T: R(t) from `force`, ua_x from `ua`, every
/// other column of docs/scene-format.md zero except the energies (kinetic = 1 J constant).
inline StoredRun synthetic(
    double h, double T, const std::function<double(double)>& force,
    const std::function<double(double)>& ua = [](double) { return 0.0; }) {
  std::map<std::string, std::vector<double>> c;
  const auto n = static_cast<std::size_t>(std::llround(T / h));
  for (std::size_t i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) * h;
    c["t"].push_back(t);
    c["R"].push_back(force(t));
    c["ua_x"].push_back(ua(t));
    for (const char* z : {"tau", "gap", "ua_y", "va_x", "va_y", "ub_x", "ub_y", "vb_x", "vb_y", "strain",
                          "dissipated", "load_work", "px", "py"})
      c[z].push_back(0.0);
    c["kinetic"].push_back(1.0);
  }
  return StoredRun::from_columns(std::move(c));
}

}  // namespace beamimpact::testing
