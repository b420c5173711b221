#pragma once
/// @file turned_chord.hpp
/// @brief Tests' turned target: S3 struck next to B's pin, and displacements that turn B's first
/// element about the pin with the striker placed against the turned chord.

#include <Eigen/Core>

#include <solver/scene/Scene.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact::testing {

/// @brief S3 (B from (0, 0) to (10, 0) m in 1 m elements, pinned at its start) with the striker's
/// lower end over B's first element, 0.5 m from the pin and 0.1 m above it.
inline Scene strike_next_to_the_pin() {
  return load_paper_scene("s3_surface_10", {"bodies.A.start=[0.5, 5.1]", "bodies.A.end=[0.5, 0.1]"});
}

/// @brief A displacement of strike_next_to_the_pin()'s model with B's first element turned about
/// the pin (B's node 1 moved `drop` along y: the chord is y = drop x for x in [0, 1] m) and the
/// striker node moved `along` along x and placed `below` under that chord, straight down (y);
/// every other displacement zero. ModelT is solver/model's Model: a layer above this folder, so
/// this header takes it as a template parameter and includes none of it.
/// @param model the model of strike_next_to_the_pin() (bending kept)
/// @param striker the striker's node (ContactPair::striker_node)
/// @param drop B's node 1 along y (m; -0.6: a turn of atan 0.6 = 0.54 rad)
/// @param along the striker's move along x (m)
/// @param below the striker's depth under the chord along y (m; negative: above it)
template <class ModelT>
Eigen::VectorXd turned_chord(const ModelT& model, int striker, double drop, double along, double below) {
  Eigen::VectorXd U = Eigen::VectorXd::Zero(model.size());
  U(model.equation(model.node_id(1, 1), 1)) = drop;
  const Vec2 X = model.node_position(striker);
  U(model.equation(striker, 0)) = along;
  U(model.equation(striker, 1)) = ((X[0] + along) * drop - below) - X[1];
  return U;
}

}  // namespace beamimpact::testing
