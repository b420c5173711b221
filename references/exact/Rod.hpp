#pragma once
/// @file Rod.hpp
/// @brief A uniform St. Venant rod (1D elastic bar): the data the exact wave solutions need.

#include <cmath>

namespace beamimpact::exact {

/// @brief A uniform elastic rod, SI units.
struct Rod {
  double length = 0.0;  ///< m
  double E = 0.0;       ///< N/m^2, Young's modulus
  double rho = 0.0;     ///< kg/m^3
  double area = 0.0;    ///< m^2

  /// @brief Bar wave speed c = sqrt(E/rho) (m/s).
  double wave_speed() const { return std::sqrt(E / rho); }
  /// @brief Impedance Z = rho c A (N s/m): force per unit particle velocity of a travelling wave.
  double impedance() const { return rho * wave_speed() * area; }
  /// @brief Round-trip time T = 2 L / c of a wave in the rod (s).
  double round_trip() const { return 2.0 * length / wave_speed(); }
  /// @brief Mass rho A L (kg).
  double mass() const { return rho * area * length; }
};

/// @brief How the target's far end (the one away from the contact) reflects a wave.
enum class FarEnd {
  kFree,   ///< stress-free: a compressive wave returns as tension (the free rods of references.md 1)
  kFixed,  ///< displacement held: a compressive wave returns as compression
};

}  // namespace beamimpact::exact
