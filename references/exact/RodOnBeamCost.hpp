#pragma once
/// @file RodOnBeamCost.hpp
/// @brief What the rod-on-beam solution (RodOnBeam.hpp) will cost, estimated from its setup
/// before any mode is integrated: the integrator stops at every reflection-memory sample, a
/// quarter radian of the highest mode apart (samples grow as modes^2, work as modes^3), and the
/// rod's energy split reads the memory at every output row.

#include <string>
#include <vector>

#include <references/exact/ExactCost.hpp>
#include <references/exact/RodOnBeam.hpp>

namespace beamimpact::exact {

/// @brief The estimate for one solution or a mode study (every run of it).
struct RodOnBeamCost {
  int modes = 0;              ///< modes of the largest run
  double sample_dt = 0.0;     ///< s, memory sample spacing of the largest run
  double samples = 0.0;       ///< memory samples (integrator stops) of the largest run
  double state_steps = 0.0;   ///< sum over the runs of samples x (2 modes + 3) states
  double rows = 0.0;          ///< output rows
  double field_points = 0.0;  ///< memory evaluations of the rod's energy split, largest run
  double bytes = 0.0;         ///< reflection memory and rows of the largest run
  /// @brief Seconds of one core at the measured rates (RodOnBeamCost.cc).
  double seconds() const;
  /// @brief "256 modes: 8.7e+04 integrator stops 3.3e-05 s apart, ...".
  std::string to_string() const;
  /// @brief The estimate as the limits read it (ExactCost.hpp).
  ExactCost total() const { return {seconds(), bytes, to_string()}; }
};

/// @brief The cost of solving `setup` with each mode count in turn (a mode study runs them all
/// when it does not converge earlier: the estimate is its worst case).
/// @param setup problem data (setup.modes is ignored)
/// @param mode_counts the runs, each >= 1
RodOnBeamCost estimate_rod_on_beam_cost(const RodOnBeamSetup& setup, const std::vector<int>& mode_counts);

}  // namespace beamimpact::exact
