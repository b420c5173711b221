#pragma once
/// @file Effects.hpp
/// @brief Which physical effects a scene calls for, so that a run pays only for those: bending
/// (else rods, 1 DOF per node), damping, friction, corotational rebuild (and for which bodies).

#include <string>
#include <vector>

#include <solver/scene/Scene.hpp>

namespace beamimpact {

/// @brief The effects of a scene after [effects] overrides.
struct Effects {
  bool bending = false;        ///< frame elements (3 DOF per node); false: axial rods
  bool damping = false;        ///< Rayleigh coefficients given (and not forced off)
  bool friction = false;       ///< some contact has mu > 0 (and not forced off)
  bool corotational = false;   ///< kinematics = "corotational" and some body can rotate
  bool loads = false;          ///< [loads] gives gravity or point forces (F^P of Eq. 3)
  std::vector<bool> rotating;  ///< per body: rebuilt every step (corotational only)

  /// @brief Names for summary.json, e.g. {"axial", "bending", "friction", "loads"}.
  std::vector<std::string> names() const;
};

/// @brief Derives the effects of `scene`.
Effects derive_effects(const Scene& scene);

/// @brief The scene as the model sees it: damping or friction forced off are zeroed.
Scene effective_scene(const Scene& scene, const Effects& effects);

/// @brief True when a body can rotate as a rigid body: translations fixed at fewer than two nodes.
bool body_can_rotate(const Body& body);

}  // namespace beamimpact
