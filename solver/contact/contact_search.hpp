#pragma once
/// @file contact_search.hpp
/// @brief Which node pairs a scene's contacts check. By default (the paper's method) each
/// [[contacts]] entry is one pair: its declared striker node against the target. With
/// node = "all" (a contact search) the entry also gets a pair for every other striker node that
/// lies off the target's axis, and one for each end node of the target against the striker's
/// surface; the pairs open and close as they come. A bounding-box pass (SearchBoxes) lets the
/// contact solver skip searched pairs whose node is far from the other body, so that the cost
/// per step stays O(nodes).

#include <vector>

#include <Eigen/Core>

#include <solver/contact/ContactPair.hpp>

namespace beamimpact::paper {

/// @brief The node pairs of all contacts, with the scene contact each one belongs to.
struct ContactPairs {
  std::vector<ContactPair> pairs;
  std::vector<int> contact;             ///< per pair: index into Scene::contacts
  std::vector<std::vector<int>> group;  ///< per scene contact: its pairs, the declared (or, for
                                        ///< "all", the nearest) one first
};

/// @brief Builds the pairs of every contact of the scene (declared pair first within a contact).
/// Throws InputError as ContactPair does for a declared node that faces nothing.
ContactPairs make_contact_pairs(const Model& model, const Scene& scene, SurfaceInterpolation surface);

/// @brief Axis-aligned boxes around the deformed nodes of the bodies a contact search involves.
class SearchBoxes {
 public:
  /// @param model the beam model
  /// @param bodies one flag per scene body: keep a box for it
  /// @param margin per body (m): how far outside its nodes' box a point still counts as near
  ///        (one element length: covers the deflection of an element between its nodes)
  SearchBoxes(const Model& model, std::vector<char> bodies, std::vector<double> margin);

  /// @brief Recomputes every box from the configuration U (O(nodes of the boxed bodies)).
  void update(const Eigen::VectorXd& U);
  /// @brief True when global node `node` (displaced by U) is inside body b's inflated box.
  bool near(const Eigen::VectorXd& U, int node, int body) const;

 private:
  const Model& model_;
  std::vector<char> boxed_;
  std::vector<double> margin_;
  std::vector<std::array<double, 4>> box_;  ///< per body: xmin, ymin, xmax, ymax (m)
};

}  // namespace beamimpact::paper
