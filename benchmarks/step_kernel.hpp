#pragma once
/// @file step_kernel.hpp
/// @brief The yardstick of the benchmarks: a hand-written central-difference step for a chain of
/// identical lumped-mass elements (axial rod, 1 DOF per node, or Euler-Bernoulli frame, 3 DOFs
/// per node), one fused sweep per step, element blocks applied on the fly. No contact, no
/// friction, no damping: the least work any explicit step of this model can do. Benchmarks
/// report the integrator's time per DOF-step as a ratio to this kernel's in the same run.

#include <cstddef>
#include <vector>

namespace beamimpact::bench {

/// @brief A free-free chain of n identical elements (steel, 1 m long, 0.01 m square section),
/// stepped by u_{k+1} = 2 u_k - u_{k-1} + dt^2 M^-1 (-K u_k) at half the element bound.
class StepKernel {
 public:
  /// @param elements number of elements (>= 1)
  /// @param frame true: frame element (u, v, theta per node); false: axial rod (u per node)
  StepKernel(std::size_t elements, bool frame);

  /// @brief One time step (one sweep over the nodes; allocation-free).
  void step();

  /// @brief Degrees of freedom of the chain.
  std::size_t dofs() const { return u_.size(); }

  /// @brief Current displacement (for DoNotOptimize and sanity checks).
  const std::vector<double>& displacement() const { return u_; }

 private:
  bool frame_;
  std::size_t nodes_;
  double k_[36] = {};             ///< element stiffness (6x6 frame, or 2x2 rod in k_[0..3]), row-major
  std::vector<double> minv_dt2_;  ///< dt^2 / m per DOF
  std::vector<double> u_, u_prev_, f_;
};

}  // namespace beamimpact::bench
