#pragma once
/// @file ElasticForce.hpp
/// @brief The IDA reference's internal force f_int(U), its tangent and the strain energy: K U for
/// linear bodies; for the bodies listed as corotational, each element's rigid rotation taken out
/// and its local linear stiffness applied in the rotated frame (element-independent corotation):
///   beta = current chord angle, alpha = beta - beta0 (the element's rigid rotation, taken on the
///   branch nearest the mean of its nodes' rotations so a spinning body keeps counting),
///   d_local = [0, 0, theta1 - alpha, l - L, 0, theta2 - alpha] (node 1 at the origin, node 2 on
///   the rotated axis), f_local = K_local d_local with its transverse pair set by the moments'
///   equilibrium on the current chord, +-(M1 + M2) / l (the energy's gradient),
///   f_e = T(beta)^T f_local,
/// with T the local-from-global rotation and K_local the element's own local stiffness
/// (solver/model's frame_stiffness_local or timoshenko_stiffness_local). The tangent is
/// T^T K_local T (no geometric stiffness); the energy is d_local^T K_local d_local / 2.
/// Written apart from the paper integrator's corotational code, so a fault there is not shared.

#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <solver/model/Model.hpp>

namespace beamimpact::ida {

/// @brief Internal force of the model with optional corotational bodies.
class ElasticForce {
 public:
  /// @brief rotating[b]: body b's elastic elements are corotational (frame layout only). The
  /// model must outlive this object.
  /// @param model the assembled model (frame layout when some body rotates)
  /// @param rotating one flag per body
  ElasticForce(const Model& model, const std::vector<bool>& rotating);
  ElasticForce(const ElasticForce&) = delete;
  ElasticForce& operator=(const ElasticForce&) = delete;
  /// @brief f = f_int(U) (N, N m), f resized to the model's size.
  void apply(const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::VectorXd& f) const;
  /// @brief Adds the tangent df_int/dU at U, scaled by `scale`, as triplets at (row0 + i, col0 + j).
  /// The pattern does not depend on U.
  void add_tangent(const Eigen::Ref<const Eigen::VectorXd>& U, double scale, int row0, int col0,
                   std::vector<Eigen::Triplet<double>>& out) const;
  /// @brief Strain energy at U (J).
  double energy(const Eigen::Ref<const Eigen::VectorXd>& U) const;
  /// @brief True when some element is corotational.
  bool corotational() const { return !elements_.empty(); }
  /// @brief The rigid rotation alpha (rad) of corotational element k (k-th in the list) at U.
  double rigid_rotation(int k, const Eigen::Ref<const Eigen::VectorXd>& U) const;

 private:
  /// One corotational element: its equations (-1 fixed), reference node positions, reference
  /// axis angle and length, and local stiffness.
  struct Element {
    Eigen::Matrix<int, 6, 1> eq;
    double x1, y1, x2, y2, beta0, length;
    Eigen::Matrix<double, 6, 6> k_local;
  };
  /// The element's current chord angle beta, its local deformation d_local, and T(beta).
  struct Frame {
    double beta, alpha, length;  ///< rad, rad, m (current chord)
    Eigen::Matrix<double, 6, 1> d;
    Eigen::Matrix<double, 6, 6> T;
  };
  Frame frame(const Element& el, const Eigen::Ref<const Eigen::VectorXd>& U) const;
  const SparseMatrix* K_linear_;  ///< the model's K, or K_own_ when some element is corotational
  SparseMatrix K_own_;            ///< K less the corotational elements' reference stiffness
  std::vector<Element> elements_;
};

}  // namespace beamimpact::ida
