#pragma once
/// @file timoshenko_element.hpp
/// @brief 2D Timoshenko frame element: axial bar + a bending part with shear deformation and
/// rotary inertia, on the interdependent interpolation of Friedman and Kosmatka (1993): the
/// cubic deflection and quadratic rotation that solve the static Timoshenko equations on the
/// element, so the stiffness is exact for end loads and does not lock as the beam gets slender
/// (phi -> 0 gives the Hermite Euler-Bernoulli element). Local DOF order per node as in
/// frame_element.hpp: (u along the axis, v across it, theta).

#include <solver/model/frame_element.hpp>

namespace beamimpact {

/// @brief Shear parameter phi = 12 E I / (kappa G A L^2) of an element of length L (m), with
/// G = E / (2 (1 + nu)): the ratio of shear to bending flexibility; 0 is Euler-Bernoulli.
/// @param I second moment of area (m^4) @param A area (m^2) @param L element length (m)
/// @param kappa shear coefficient (-) @param nu Poisson's ratio (-)
double shear_parameter(double I, double A, double L, double kappa, double nu);

/// @brief Local stiffness: EA/L bar plus the Timoshenko bending block
/// EI / ((1 + phi) L^3) [12, 6L, -12, 6L; 6L, (4 + phi) L^2, -6L, (2 - phi) L^2; ...].
Mat6 timoshenko_stiffness_local(double E, double A, double I, double L, double phi);

/// @brief Consistent mass in local axes: linear bar m/6 [2 1; 1 2] plus rho A int N_v^T N_v
/// (translational) and rho I int N_theta^T N_theta (rotary) of the interdependent interpolation.
Mat6 timoshenko_mass_consistent_local(double rho, double A, double I, double L, double phi);

/// @brief Lumped mass diagonal: m/2 on each translation and the section's rotary inertia
/// rho I L / 2 on each rotation (the theory's own rotary inertia, in every frame).
Vec6 timoshenko_mass_lumped(double rho, double A, double I, double L);

/// @brief End moments (M1, M2) of the bending block for end rotations th1, th2 relative to the
/// chord (rad): EI / ((1 + phi) L) [(4 + phi) th1 + (2 - phi) th2, (2 - phi) th1 + (4 + phi) th2].
std::array<double, 2> timoshenko_end_moments(double E, double I, double L, double phi, double th1,
                                             double th2);

}  // namespace beamimpact
