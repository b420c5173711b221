#pragma once
/// @file SimpleBeam.hpp
/// @brief A simply supported uniform Euler-Bernoulli beam and its normal modes
/// (references.md section 2): w(x,t) = sum_n q_n(t) sin(n pi x / L).

#include <cmath>
#include <numbers>

namespace beamimpact::exact {

/// @brief A uniform Euler-Bernoulli beam, pinned at x = 0 and x = L (transverse motion only).
struct SimpleBeam {
  double length = 0.0;   ///< m
  double E = 0.0;        ///< N/m^2
  double rho = 0.0;      ///< kg/m^3
  double area = 0.0;     ///< m^2
  double inertia = 0.0;  ///< m^4, second moment of area

  /// @brief Modal mass M_n = rho A L / 2 (kg), the same for every mode.
  double modal_mass() const { return 0.5 * rho * area * length; }
  /// @brief sqrt(E I / (rho A)) (m^2/s), the dispersion constant a of the beam equation.
  double dispersion() const { return std::sqrt(E * inertia / (rho * area)); }
  /// @brief Natural circular frequency Omega_n = (n pi / L)^2 sqrt(E I / (rho A)) (rad/s), n >= 1.
  double omega(int n) const {
    const double k = n * std::numbers::pi / length;
    return k * k * dispersion();
  }
  /// @brief Mode shape sin(n pi x / L) at x (m).
  double shape(int n, double x) const { return std::sin(n * std::numbers::pi * x / length); }
  /// @brief Integral of the mode shape over the span, L (1 - cos n pi) / (n pi) (m): the modal
  /// coordinate's share of the beam's linear momentum per unit q_n' and rho A.
  double shape_integral(int n) const { return (n % 2 == 1) ? 2.0 * length / (n * std::numbers::pi) : 0.0; }
};

}  // namespace beamimpact::exact
