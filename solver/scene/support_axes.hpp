#pragma once
/// @file support_axes.hpp
/// @brief What a body's supports hold at one node, with global (x, y) and body-axis (axial,
/// normal) entries combined: the translations held as directions in global axes.

#include <string>
#include <vector>

#include <solver/scene/Scene.hpp>

namespace beamimpact {

/// @brief Two held directions closer to parallel than this (|sin| of the angle between them)
/// are one: a mixed entry such as ["x", "normal"] on a beam along y holds one direction.
inline constexpr double kParallelTolerance = 1e-9;

/// @brief The translations the supports of a body hold at one of its nodes.
struct NodeHold {
  int held = 0;            ///< translations held: 0 (free), 1 (a roller), 2 (both: a pin)
  Vec2 direction{};        ///< held == 1: the unit direction held, global axes
  bool body_axes = false;  ///< held == 1: the direction is the body's axial or normal one
  bool normal = false;     ///< held == 1 and body_axes: the normal (else the axial) direction
  bool theta = false;      ///< the rotation is held
};

/// @brief Combines every support of `body` at `node`. When a held global direction and a held
/// body direction are parallel (kParallelTolerance), the body's direction is the one kept.
NodeHold node_hold(const Body& body, int node);

/// @brief True when the body's axis lies along x or y (within kParallelTolerance): global and
/// body axes then name the same directions.
bool axis_aligned(const Body& body);

/// @brief The warning for a roller in global axes (one of x, y held at a node, no body-axis
/// entry) on a body whose axis is along neither x nor y, empty otherwise: such a roller holds
/// another direction than the one across the body. `file` and `key` ("bodies[1].supports[1]")
/// are named in it.
std::string global_roller_warning(const Body& body, const Support& s, const std::string& file,
                                  const std::string& key);

}  // namespace beamimpact
