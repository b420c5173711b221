#pragma once
/// @file collinear.hpp
/// @brief Whether a scene is one-dimensional: every body and every velocity on one line. Such a
/// scene runs as axial rods (1 DOF per node) unless bending is forced on.

#include <solver/scene/Scene.hpp>

namespace beamimpact {

/// @brief True when all bodies lie on one straight line and all velocities point along it
/// (tolerances: 1e-9 on direction cosines, 1e-9 of the longest body on offsets).
/// @param scene the scene
/// @param axis if given, receives the common unit axis when the scene is collinear
bool scene_is_collinear(const Scene& scene, Vec2* axis = nullptr);

}  // namespace beamimpact
