#pragma once
/// @file frame_element.hpp
/// @brief 2D Euler-Bernoulli frame element (axial bar + Hermite bending) and its 1-DOF-per-node
/// bar reduction: local stiffness, lumped and consistent mass, rotation to global axes.
/// Local DOF order per node: (u along the axis, v across it, theta).

#include <Eigen/Dense>

#include <solver/scene/Scene.hpp>

namespace beamimpact {

/// @brief 6x6 frame matrix in local or global axes.
using Mat6 = Eigen::Matrix<double, 6, 6>;
/// @brief 6-vector (diagonal of a lumped mass, element DOF values).
using Vec6 = Eigen::Matrix<double, 6, 1>;

/// @brief The local stiffness of a two-node plane frame element from its five distinct terms
/// (DOFs u1, v1, theta1, u2, v2, theta2): the bar's ea and the bending block's k1 (shear
/// force per deflection), k2 (per rotation), k3 (moment at a node per its own rotation) and k4
/// (per the other node's rotation). The Euler-Bernoulli and Timoshenko elements share it.
Mat6 frame_stiffness_from_terms(double ea, double k1, double k2, double k3, double k4);

/// @brief Local stiffness: EA/L bar plus the Hermite bending block with EI.
Mat6 frame_stiffness_local(double E, double A, double I, double L);

/// @brief Lumped mass diagonal: m/2 on each translation; rotary inertia HRZ (m L^2/78) or
/// section (rho I L/2). Invariant under rotation (equal x and y masses).
Vec6 frame_mass_lumped(double rho, double A, double I, double L, RotaryInertia rotary);

/// @brief Consistent mass in local axes: linear bar (m/6 [2 1; 1 2]) + Hermite transverse (m/420 ...).
Mat6 frame_mass_consistent_local(double rho, double A, double L);

/// @brief Block-diagonal rotation T(alpha) with u_local = T u_global (c = cos alpha, s = sin alpha).
Mat6 frame_rotation(double c, double s);

/// @brief Global matrix T^T K_local T for an element at angle (c, s).
Mat6 to_global(const Mat6& local, double c, double s);

/// @brief Bar (1 DOF per node, along the axis) stiffness EA/L [1 -1; -1 1].
Eigen::Matrix2d bar_stiffness(double E, double A, double L);
/// @brief Bar lumped mass diagonal (m/2, m/2).
Eigen::Vector2d bar_mass_lumped(double rho, double A, double L);
/// @brief Bar consistent mass m/6 [2 1; 1 2].
Eigen::Matrix2d bar_mass_consistent(double rho, double A, double L);

}  // namespace beamimpact
