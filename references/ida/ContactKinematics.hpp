#pragma once
/// @file ContactKinematics.hpp
/// @brief Linear contact kinematics of the IDA reference: the gap and the relative tangential
/// displacement of one contact pair as linear functionals of the equation vector U, in global
/// axes with the target's reference-configuration normal. Written here, independently of the
/// paper integrator's contact code (solver/contact is not used).

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include <solver/model/Model.hpp>
#include <solver/schema/output_schema.hpp>

namespace beamimpact::ida {

/// @brief The contact pair's geometry at one displacement state.
struct ContactFrame {
  double g0 = 0.0;               ///< m, gap at U = 0: gap = g0 + sum(n_terms . U)
  std::vector<DofTerm> n_terms;  ///< d gap / dU (striker +n, struck point -xi n)
  std::vector<DofTerm> t_terms;  ///< d(relative tangential displacement)/dU (striker +t, target -xi t)
  int segment = 0;               ///< target element that holds the struck point (sparsity identity)
  double xi2 = 0.0;              ///< weight of the segment's second node (0 at its first node)
  double beyond = 0.0;           ///< m, how far the striker is past the target's end (0 over the surface)
  /// The struck point slides over a deflected target: d gap/dt = n . V_terms - rate_coupling
  /// t . V_terms, rate_coupling = n.u_b' / (1 + t.u_b') with u_b' the element chord's slope (its
  /// displacement per metre along the target). 0 for an end-to-end pair and past the end.
  double rate_coupling = 0.0;

  /// @brief Gap (m) = g0 + n . U over the surface; past the target's end the surface has ended
  /// and the gap is the distance beyond it (> 0: the contact opens, no phantom surface).
  double gap(const Eigen::VectorXd& U) const;
  /// @brief d gap / dt (m/s) for a velocity V: n_terms . V less the slide over the deflected
  /// surface (rate_coupling). The normal force still acts along n_terms (the reference normal,
  /// as the paper's contact): its power R n_terms . V differs from the spring's by R
  /// rate_coupling v_t, work the run books in `dissipated` (it may then decrease).
  double normal_rate(const Eigen::VectorXd& V) const;
  /// @brief n_terms . V (m/s): the velocity along the normal force's direction.
  double force_rate(const Eigen::VectorXd& V) const;
  /// @brief t . V (m/s): relative tangential (slip) velocity of striker over target.
  double tangential_rate(const Eigen::VectorXd& V) const;
};

/// @brief One contact pair: evaluates its frame for a displacement vector.
class ContactKinematics {
 public:
  virtual ~ContactKinematics() = default;
  /// @brief The frame at displacement U (the struck point may slide with U).
  virtual ContactFrame evaluate(const Eigen::VectorXd& U) const = 0;
};

/// @brief A pair with fixed terms (two nodes, or a test's hand-built system).
class FixedContact : public ContactKinematics {
 public:
  /// @brief frame is returned for every U.
  explicit FixedContact(ContactFrame frame) : frame_(std::move(frame)) {}
  ContactFrame evaluate(const Eigen::VectorXd&) const override { return frame_; }

 private:
  ContactFrame frame_;
};

/// @brief A scene contact on the assembled model.
///
/// Kinds: "end_to_end" when the striker node lies on the extension of the target's axis (the
/// normal is the target's outward axis at that end, the struck point its end node); otherwise
/// the struck point is the foot of the striker node on the target's reference line, with normal
/// the target's reference normal pointing to the striker. Its position slides with the
/// striker's and target's tangential displacement; the weights xi1 = 1 - xi2, xi2 interpolate
/// the displacements of the element's two nodes linearly ("node_to_node" when it starts on a
/// node, "node_to_surface" otherwise). Linear kinematics: geometry from the reference
/// configuration plus displacements, no rotation of the normal.
class ModelContact : public ContactKinematics {
 public:
  /// @brief striker_node, target_body: as in Scene::Contact (node index within the striker body).
  ModelContact(const Model& model, const Scene& scene, int contact_index);
  ContactFrame evaluate(const Eigen::VectorXd& U) const override;

  /// @brief End-to-end, node-to-node or node-to-surface (string forms in schema/output_schema.hpp).
  ContactKind kind() const { return kind_; }
  /// @brief Global node id of the striker's contact node.
  int striker_node() const { return striker_node_; }
  /// @brief Global node ids of the target element's nodes for a frame (same node twice end-on).
  std::array<int, 2> segment_nodes(const ContactFrame& f) const;
  /// @brief Unit normal (of the target, toward the striker) and tangent, global axes.
  const Vec2& normal() const { return n_; }
  const Vec2& tangent() const { return t_; }
  /// @brief Axial stiffness EA/le (N/m) of the stiffer of the elements that meet at the contact.
  double element_stiffness() const { return k_elem_; }

 private:
  const Model& model_;
  ContactKind kind_ = ContactKind::kEndToEnd;
  int striker_node_ = 0;
  int target_first_node_ = 0, target_elements_ = 0;
  double le_ = 0.0;     ///< m, target element length
  double s_ref_ = 0.0;  ///< m, reference coordinate of the striker node along the target
  double g0_ = 0.0;
  Vec2 n_{}, t_{};
  double k_elem_ = 0.0;
  std::vector<DofTerm> striker_n_, striker_t_;
  std::vector<DofTerm> end_n_, end_t_;  ///< end_to_end: the target end node's terms
  int end_node_ = -1;
  /// Struck point's coordinate along the target (m), clamped to it; `beyond` receives how far
  /// the unclamped one lies past an end (0 over the surface).
  double coordinate(const Eigen::VectorXd& U, double* beyond = nullptr) const;
};

}  // namespace beamimpact::ida
