#pragma once
/// @file deformed_geometry.hpp
/// @brief The real gap: where a striker node is relative to a target body's DEFORMED centreline,
/// measured from the geometry of U and the target's own interpolation, never from a method's
/// contact rows. Frames: each element is its deformed chord plus the beam's cubic (Hermite) from
/// the nodal rotations relative to the chord; rods: the deformed chord. Geometry only: every
/// method (the paper's integrator, IDA) can report it about its own solution.

#include <vector>

#include <Eigen/Core>

#include <solver/model/Model.hpp>

namespace beamimpact {

/// @brief The real gap of one striker node against one target body.
struct RealGap {
  double gap = 0.0;  ///< m; > 0 apart, < 0 penetration (signed distance to the deformed centreline)
  int element = 0;   ///< target element (0-based within the body) of the closest point
  double xi = 0.0;   ///< position of the closest point along it, 0..1
  bool beyond_end =
      false;  ///< a surface contact whose striker is past the target's end (gap = distance to the end)
};

/// @brief Which deformed centreline a DeformedSurface measures against.
enum class Centreline {
  kBeam,   ///< each element's chord plus the beam's cubic from the nodal rotations (frames)
  kChord,  ///< the chords only: the polyline through the deformed nodes (linear weights' surface)
};

/// @brief The deformed centreline of one body and the real gap of points against it.
class DeformedSurface {
 public:
  /// @param model the beam model
  /// @param body the target body
  /// @param striker_node global id of the striker node, which fixes the side (reference
  ///        configuration) and whether the contact is end-on (striker on the target's axis,
  ///        beyond an end) or across the surface
  /// @param line the centreline measured against (rods: the chord either way)
  DeformedSurface(const Model& model, int body, int striker_node, Centreline line = Centreline::kBeam);

  /// @brief The real gap of the striker node in configuration U. Starts the closest-point search
  /// at the element of the previous call (O(1) per call while the contact point moves little).
  RealGap gap(const Eigen::VectorXd& U);

  /// @brief Deformed position of the point at xi (0..1) of element e (0-based within the body).
  Vec2 point(const Eigen::VectorXd& U, int e, double xi) const;

  /// @brief How far the deformed centreline's tangent at xi (0..1) of element e has turned from
  /// the element's reference direction (rad, counter-clockwise positive).
  double turn(const Eigen::VectorXd& U, int e, double xi) const;

 private:
  struct Shape {
    Vec2 a, c, n;
    double L, phi1, phi2;
  };
  Shape shape(const Eigen::VectorXd& U, int e) const;
  const Model& model_;
  int first_ = 0;  ///< the body's first element in model.elements() (a body's elements follow each other)
  int count_ = 0;  ///< the body's elements
  int striker_;
  double side_ = 1.0;  ///< +1: striker left of the target's axis (reference), -1: right
  int end_on_ = 0;     ///< 0: surface contact; -1 / +1: end-on at the start / end
  int hint_ = 0;
  Centreline line_;
};

}  // namespace beamimpact
