#pragma once
/// @file ContactPair.hpp
/// @brief Geometry of one scene contact: where the striker node meets the target, the normal
/// and tangent, and the constraint rows g(U) = g0 + G_n . U (normal gap) and s(U) = G_t . U
/// (relative tangential displacement). Linear kinematics: normal and tangent are the target's
/// reference axes; the struck point may slide and is then re-located every step.

#include <array>
#include <string>
#include <utility>
#include <vector>

#include <solver/model/Model.hpp>
#include <solver/schema/output_schema.hpp>

namespace beamimpact::paper {

/// @brief How the target's displacement at the struck point is interpolated.
enum class SurfaceInterpolation {
  kLinear,   ///< the paper's Eq. 14-20: weights xi1, xi2 on the nodal translations (C0 surface)
  kHermite,  ///< normal displacement by the beam's own cubic (uses nodal rotations: C1 surface,
             ///< no kink at nodes for a sliding striker); tangential part stays linear
};

/// @brief One contact pair of the scene and its current contact point.
class ContactPair {
 public:
  /// @brief Locates contact `index` of the scene in the model. Throws InputError when the striker
  /// node faces neither the target's surface nor its end, or penetrates it at t = 0.
  ContactPair(const Model& model, const Scene& scene, int index,
              SurfaceInterpolation surface = SurfaceInterpolation::kLinear);

  /// @brief A pair of a contact search (contact_search.hpp): node `node` (0-based within body
  /// `striker`) against the surface of body `target`, for scene contact `index`. The node must
  /// lie off the target's axis (the side fixes the normal); one beyond the target's end starts
  /// off the surface (on_surface() false) and joins when it slides over it.
  ContactPair(const Model& model, const Scene& scene, int index, int striker, int node, int target,
              SurfaceInterpolation surface = SurfaceInterpolation::kLinear);

  /// @brief Kind found at t = 0.
  ContactKind kind() const { return kind_; }
  /// @brief Global node id of the striker node.
  int striker_node() const { return striker_; }
  /// @brief Target element (0-based within the target body) and weights of the struck point.
  int element() const { return element_; }
  double xi1() const { return xi1_; }
  double xi2() const { return xi2_; }
  /// @brief Unit normal of the target pointing to the striker, and tangent (n rotated -90 deg).
  const Vec2& normal() const { return n_; }
  const Vec2& tangent() const { return t_; }
  /// @brief Gap at U = 0 (m).
  double g0() const { return g0_; }
  /// @brief True when the struck point can move along the target (surface contacts).
  bool can_slide() const { return kind_ != ContactKind::kEndToEnd; }

  /// @brief Terms a row holds at most: the striker and two target nodes, up to 3 each (a node of
  /// a rigid body projects onto its centre's x, y and rotation: Model::append_projection), and
  /// each target node's rotation on a Hermite surface: 3 + 2 (3 + 1).
  static constexpr std::size_t kMaxRowTerms = 11;
  /// @brief Normal row: g(U) = g0 + sum(coeff * U[eq]).
  const std::vector<DofTerm>& normal_row() const { return gn_; }
  /// @brief Tangential row: relative tangential displacement s(U) = sum(coeff * U[eq]).
  const std::vector<DofTerm>& tangent_row() const { return gt_; }
  /// @brief Evaluates a row on U.
  static double eval(const std::vector<DofTerm>& row, const Eigen::VectorXd& U);

  /// @brief Re-locates the struck point from the configuration U (for a sliding striker): the
  /// element and weights under the striker node, walking across element boundaries. Returns
  /// true when the point changed (rows rebuilt). When the striker is beyond the target's end
  /// the rows keep the end point and on_surface() turns false.
  bool relocate(const Eigen::VectorXd& U);

  /// @brief False while a sliding striker is beyond the target's end node: the target's surface
  /// ends there, so the pair can carry no force (it is open whatever its extended gap says).
  bool on_surface() const { return on_surface_; }

  /// @brief True for a pair added by a contact search (not the scene's declared node).
  bool searched() const { return searched_; }
  /// @brief The target body (index into the scene's bodies).
  int target_body() const { return target_body_; }

  /// @brief Displacement of the struck point (interpolated as the rows are) from U (m).
  Vec2 target_vector(const Eigen::VectorXd& U) const;

  /// @brief The forces of contact force (R, tau) on the pair's nodes (N), as the rows apply them:
  /// R n + tau t on the striker node, and its reaction on the target element's two nodes by the
  /// rows' translation weights (the normal part by the surface interpolation's, the tangential
  /// part by xi1, xi2). Unlike the rows' forces on the equations, this holds for a rigid body's
  /// node and at a support too.
  /// @param R normal force (N)
  /// @param tau tangential force (N)
  std::array<std::pair<int, Vec2>, 3> nodal_forces(double R, double tau) const;

 private:
  void locate(const Scene& scene, int index, int striker_body, int node, int target);
  void build_rows();
  const Model& model_;
  SurfaceInterpolation surface_;
  ContactKind kind_ = ContactKind::kEndToEnd;
  int striker_ = 0, target_body_ = 0, target_first_ = 0, target_elements_ = 0;
  int element_ = 0;
  double xi1_ = 1.0, xi2_ = 0.0;
  std::array<double, 2> wn_{1.0, 0.0};  ///< the normal row's weights of the target's translations
  Vec2 n_{}, t_{};
  double g0_ = 0.0;
  bool on_surface_ = true;
  bool searched_ = false;
  std::vector<DofTerm> gn_, gt_;
};

}  // namespace beamimpact::paper
