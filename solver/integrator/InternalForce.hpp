#pragma once
/// @file InternalForce.hpp
/// @brief f_int(U) and the strain energy: K U for linear bodies, and the 2D corotational beam
/// (element frame rebuilt from the current chord every call) for bodies that rotate. Only bodies
/// listed as corotational pay for the rebuild; with none, this is K U element by element (the
/// blocks of identical consecutive elements stored once), or one sparse product when the element
/// blocks do not reassemble K.

#include <array>
#include <vector>

#include <solver/model/Model.hpp>
#include <solver/util/ThreadTeam.hpp>

namespace beamimpact::paper {

/// @brief Internal (elastic) force of the model.
class InternalForce {
 public:
  /// @brief corotational[b]: body b uses the corotational element (frame layout only); the
  /// product split into `parts` parts when it can be (set_parts(parts), checked on the same
  /// vector as the element blocks).
  InternalForce(const Model& model, const std::vector<bool>& corotational, int parts = 1);
  /// @brief f = f_int(U). No allocation.
  void apply(const Eigen::VectorXd& U, Eigen::VectorXd& f) const;
  /// @brief f = f_int(U) as apply() (the same operations on every entry, so the same bits),
  /// calling done(lo, hi) for each range of equations as soon as f is final there: every
  /// equation exactly once, in about increasing order, so that the caller's per-equation work
  /// reads f while it is still in cache (one sweep over memory per step instead of two).
  /// Defined in InternalForce_impl.hpp. No allocation.
  /// @param U displacement
  /// @param f the force (size of U), overwritten
  /// @param done callable (int lo, int hi): f[lo, hi) is final
  template <class Done>
  void apply_streamed(const Eigen::VectorXd& U, Eigen::VectorXd& f, Done&& done) const;
  /// @brief Splits apply_streamed() into `parts` parts that may run at the same time, one per
  /// consecutive range of elements, with the same bits as apply_streamed(): an equation that
  /// elements of two parts touch (a node at a range boundary) is summed in element order, the
  /// later parts' terms kept apart and added after all parts (finish_parts). Needs
  /// element_blocks(); otherwise, or with fewer than 2 elements a part, nothing is split.
  /// @param parts the number of parts asked for
  /// @return the number of parts made (1: apply_part(0, ...) is apply_streamed())
  int set_parts(int parts);
  /// @brief The number of parts (set_parts; 1 unless split).
  int parts() const { return parts_.empty() ? 1 : static_cast<int>(parts_.size()); }
  /// @brief Part t of f = f_int(U): writes f on the equations only its elements touch (and the
  /// first part's sums of the boundary equations), calling done(lo, hi) on those it finishes.
  /// Parts may run concurrently; then finish_parts(). No allocation.
  template <class Done>
  void apply_part(int t, const Eigen::VectorXd& U, Eigen::VectorXd& f, Done&& done) const;
  /// @brief After every part: adds the later parts' terms of the boundary equations in element
  /// order and calls done(lo, hi) on them. No allocation.
  template <class Done>
  void finish_parts(Eigen::VectorXd& f, Done&& done) const;
  /// @brief End forces of element e at U in its own frame: axial force N (N, tension > 0) and
  /// the end moments M1, M2 (N m) the element exerts on its nodes' rotations, the same ones
  /// apply() assembles: the corotational element's for corotational bodies, the linear
  /// element's otherwise (rods: M = 0; rigid elements: all 0).
  /// @param e element index
  /// @param U displacement
  std::array<double, 3> end_forces(int e, const Eigen::VectorXd& U) const;
  /// @brief end_forces(e, U) of every element, in element order (the field output's input).
  /// @param U displacement
  /// @param out resized to the number of elements and overwritten
  /// @param team threads for the work (the elements split in one range per thread), or null for
  ///        this thread alone; the values do not depend on it
  void end_forces(const Eigen::VectorXd& U, std::vector<std::array<double, 3>>& out,
                  ThreadTeam* team = nullptr) const;
  /// @brief Strain energy (J) at U: 1/2 U^T K U summed column by column of K in fixed chunks
  /// (ordered_sum) on this thread, plus the corotational elements' energy. Only the runs that
  /// step on one thread ask for it (a threaded step is linear and fused, and takes the energy
  /// from its own force). The chunks' sums go into a scratch kept between calls (a history row
  /// allocates nothing): calls on one object must not run concurrently.
  /// @param U displacement
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
  /// Consecutive elements whose equations advance by one node's DOFs per element and share a
  /// stiffness block: element k of the span has equations eq[i] + k * stride (eq[i] = -1 stays
  /// -1, a fixed DOF), zeroes f on [zero_lo, zero_hi) + k * stride before adding its rows (the
  /// equations it touches first) and finishes [done_lo, done_hi) + k * stride (those it touches
  /// last). A chain of identical elements is one span, stepped like the hand kernel.
  struct Span {
    int count, block;
    int eq[6];
    int zero_lo, zero_hi, done_lo, done_hi;
    /// A chain's interior: eq[i] = eq[0] + i (one block of memory), and each element starts
    /// its second node (zero range) and finishes its first (done range).
    bool chain;
    /// Only in a part (set_parts), a single element whose rows i with bit i set are summed
    /// into the part's side values from side_at on, in row order, instead of into f.
    unsigned apart = 0;
    int side_at = 0;
  };
  /// One part of the split product: its pieces of spans in element order, and the values it
  /// keeps apart (side_eq: their equations, in the order the pieces make them).
  struct Part {
    std::vector<Span> pieces;
    std::vector<int> side_eq;
    mutable std::vector<double> side;  ///< this call's values, written by apply_part only
  };
  /// Builds the element blocks of K when nothing is corotational; keeps them only when they
  /// reassemble K (to roundoff): then apply() is element by element, as the hand kernel.
  void build_blocks(int parts);
  /// Groups the elastic elements (in order; the block of each element group given, w equations
  /// each) into spans_; false when some element's first- or last-touched equations are not one
  /// range (then no spans).
  bool build_spans(const std::vector<int>& block_of_group, int w);
  /// The span product for W = 2 x DOFs per node (apply_streamed without the fallback).
  template <int W, class Done>
  void apply_spans(const Eigen::VectorXd& U, Eigen::VectorXd& f, Done&& done) const;
  /// The product over pieces [begin, end) (zeroing and finishing `untouched` first), with the
  /// rows kept apart written to side. apply_spans and apply_part.
  template <int W, class Done>
  void sweep_pieces(const Span* begin, const Span* end, const std::vector<std::array<int, 2>>& untouched,
                    const double* u, double* out, double* side, Done&& done) const;
  /// The parts of elements [k0, k1) for every range; false when some piece cannot be made.
  bool build_parts(int parts);
  /// set_parts() given a vector with no special structure and its apply_streamed() product.
  int split(int parts, const Eigen::VectorXd& x, const Eigen::VectorXd& whole);
  const Model& model_;
  const SparseMatrix* K_;
  std::vector<double> blocks_;  ///< distinct element blocks, W x W row-major each
  std::vector<Span> spans_;
  std::vector<std::array<int, 2>> untouched_;  ///< equation ranges no element touches (f = 0)
  std::vector<Part> parts_;                    ///< empty unless split (set_parts)
  std::vector<std::array<int, 2>> boundary_;   ///< equations touched by two parts, as ranges
  static const std::vector<std::array<int, 2>> kNone;
  bool use_blocks_ = false;
  SparseMatrix K_linear_;  ///< used only when some elements are corotational
  std::vector<int> corot_elements_;
  mutable std::vector<double> energy_chunks_;  ///< strain_energy's chunk sums (ordered_sum)
};

}  // namespace beamimpact::paper

#include <solver/integrator/InternalForce_impl.hpp>
