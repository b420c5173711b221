#pragma once
/// @file TimoshenkoBeam.hpp
/// @brief The simply supported uniform Timoshenko beam's normal modes (docs/beam-theories.md):
/// with w = W sin(k x), psi = Psi cos(k x), k = n pi / L, the equations
///   rho A w_tt = kappa G A (w_x - psi)_x,  rho I psi_tt = E I psi_xx + kappa G A (w_x - psi)
/// give (rho A omega^2 - kappa G A k^2) W + kappa G A k Psi = 0 and
/// kappa G A k W + (rho I omega^2 - E I k^2 - kappa G A) Psi = 0, whose determinant is the
/// frequency equation
///   rho A rho I omega^4 - (rho A E I + rho I kappa G A + rho A kappa G A / k^2) k^2 omega^2
///     + kappa G A E I k^4 = 0,
/// two roots omega^2 per wavenumber: the bending branch and the second (shear) branch, which
/// starts at the cutoff sqrt(kappa G A / (rho I)) as k -> 0.

#include <array>

#include <references/exact/SimpleBeam.hpp>

namespace beamimpact::exact {

/// @brief A Timoshenko beam's shear data; both zero: an Euler-Bernoulli beam.
struct BeamShear {
  double kappa = 0.0;  ///< -, shear coefficient (5/6 for a rectangle)
  double G = 0.0;      ///< N/m^2, shear modulus
  /// @brief True when the beam is a Timoshenko beam (kappa G > 0).
  bool timoshenko() const { return kappa > 0.0 && G > 0.0; }
};

/// @brief One root of the frequency equation.
struct TimoshenkoRoot {
  double omega = 0.0;  ///< rad/s
  double ratio = 0.0;  ///< 1/m, amplitude ratio Psi / W of the section rotation to the deflection
};

/// @brief Both roots for wavenumber index n >= 1: [0] the bending branch, [1] the second branch.
std::array<TimoshenkoRoot, 2> timoshenko_roots(const SimpleBeam& beam, const BeamShear& shear, long n);

}  // namespace beamimpact::exact
