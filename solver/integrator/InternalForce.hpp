#pragma once
/// @file InternalForce.hpp
/// @brief f_int(U) and the strain energy: K U for linear bodies, and the 2D corotational beam
/// (element frame rebuilt from the current chord every call) for bodies that rotate. Only bodies
/// listed as corotational pay for the rebuild; with none, this is K U element by element (the
/// blocks of identical consecutive elements stored once), or one sparse product when the element
/// blocks do not reassemble K.

#include <vector>

#include <beamimpact/model/Model.hpp>

namespace beamimpact::paper {

/// @brief Internal (elastic) force of the model.
class InternalForce {
 public:
  /// @brief corotational[b]: body b uses the corotational element (frame layout only).
  InternalForce(const Model& model, const std::vector<bool>& corotational);
  /// @brief f = f_int(U). No allocation.
  void apply(const Eigen::VectorXd& U, Eigen::VectorXd& f) const;
  /// @brief Strain energy (J) at U.
  double strain_energy(const Eigen::VectorXd& U) const;
  /// @brief True when some body is corotational.
  bool nonlinear() const { return !corot_elements_.empty(); }
  /// @brief Current chord direction (cos, sin) of element e at U (the corotational frame).
  Vec2 chord_direction(int e, const Eigen::VectorXd& U) const;
  /// @brief Elements that are corotational.
  const std::vector<int>& corotational_elements() const { return corot_elements_; }
  /// @brief True when apply() runs element by element (the blocks reassemble K).
  bool element_blocks() const { return use_blocks_; }
  /// @brief Stiffness of the linear part (all elements when nothing is corotational).
  const SparseMatrix& linear_stiffness() const { return *K_; }

 private:
  /// Local deformation (axial stretch, end rotations relative to the chord) and the B matrix rows.
  struct Local {
    double u, th1, th2, ln, c, s;
  };
  Local local(int e, const Eigen::VectorXd& U, Eigen::Matrix<int, 6, 1>& eq, double x[6]) const;
  /// One element of the block product: the equations of its two nodes (contiguous per node
  /// when fast), and its stiffness block.
  struct BlockElement {
    int eq[6];
    int block;
  };
  /// Builds the element blocks of K when nothing is corotational; keeps them only when they
  /// reassemble K (to roundoff): then apply() is element by element, as the hand kernel.
  void build_blocks();
  template <int W>
  void apply_blocks(const Eigen::VectorXd& U, Eigen::VectorXd& f) const;
  const Model& model_;
  const SparseMatrix* K_;
  std::vector<double> blocks_;  ///< distinct element blocks, W x W row-major each
  std::vector<BlockElement> block_elements_;
  bool use_blocks_ = false;
  SparseMatrix K_linear_;  ///< used only when some elements are corotational
  std::vector<int> corot_elements_;
};

}  // namespace beamimpact::paper
