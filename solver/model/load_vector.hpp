#pragma once
/// @file load_vector.hpp
/// @brief The external load vector F^P of the paper's Eq. 3 for a scene's [loads]: constant in
/// time, so its work up to step p is F^P . U^p (U^0 = 0).

#include <Eigen/Dense>

#include <solver/model/Model.hpp>

namespace beamimpact {

/// @brief F^P (N, N m per equation): gravity as M times the rigid translation of every body by g
/// (the consistent load with consistent mass, m_i g per node with lumped mass, m g on a rigid
/// body's centre), plus each point force projected on its node's equations. Empty (size 0) when
/// the scene has no loads. Throws InputError naming the key when a load has a component across
/// the axis of a rod model (no bending: that component would be dropped silently).
/// @param model the assembled model of `scene`
/// @param scene the scene (its [loads])
Eigen::VectorXd load_vector(const Model& model, const Scene& scene);

/// @brief The net force of a load vector on the bodies' linear momentum (N): F . r_c with r_c
/// the rigid translation of every body along axis c (the rate of the total momentum the loads
/// drive; supports and contacts add their own). Zero for an empty load.
/// @param model the assembled model
/// @param load F^P (load_vector), or empty
Vec2 net_load_force(const Model& model, const Eigen::VectorXd& load);

}  // namespace beamimpact
