#pragma once
/// @file BeamModes.hpp
/// @brief The normal modes of a simply supported beam as the modal solutions use them: one row
/// per mode, built from the Euler-Bernoulli beam (SimpleBeam.hpp) or from the Timoshenko beam
/// (TimoshenkoBeam.hpp, both frequency branches), ordered by frequency.

#include <vector>

#include <references/exact/SimpleBeam.hpp>
#include <references/exact/TimoshenkoBeam.hpp>

namespace beamimpact::exact {

/// @brief One normal mode, for a unit transverse amplitude W = 1: w(x) = sin(k x), and for a
/// Timoshenko beam the section rotation psi(x) = (Psi/W) cos(k x). The modal coordinate q obeys
/// mass (q'' + omega^2 q) = shape P for a point force P at the struck point; the mode's kinetic
/// energy is mass q'^2 / 2, its strain energy mass omega^2 q^2 / 2.
struct BeamMode {
  int n = 0;              ///< wavenumber index, k = n pi / L
  int branch = 1;         ///< 1: the bending branch; 2: the Timoshenko beam's second (shear) branch
  double omega = 0.0;     ///< rad/s, circular frequency
  double mass = 0.0;      ///< kg, modal mass rho A L/2 (1 + (I/A) (Psi/W)^2) (rho A L/2 for Euler-Bernoulli)
  double shape = 0.0;     ///< -, transverse shape sin(k x_c) at the struck point
  double momentum = 0.0;  ///< kg, transverse linear momentum per unit q': rho A times the shape's integral
};

/// @brief The `count` lowest modes of the simply supported beam, by frequency.
/// @param beam the section and span; @param shear Timoshenko data (Euler-Bernoulli when not set)
/// @param x_c m, the struck point; @param count modes kept (both branches counted), >= 1
std::vector<BeamMode> beam_modes(const SimpleBeam& beam, const BeamShear& shear, double x_c, int count);

/// @brief The frequency (rad/s) of the highest of the `count` lowest modes, without building them.
double top_frequency(const SimpleBeam& beam, const BeamShear& shear, long count);

}  // namespace beamimpact::exact
