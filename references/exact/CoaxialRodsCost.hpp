#pragma once
/// @file CoaxialRodsCost.hpp
/// @brief What the coaxial-rod solution (CoaxialRods.hpp) will cost, estimated before it is
/// solved: its pieces start at the first touch t0 and at every t0 + a T_A + b T_B (a, b >= 0)
/// inside the run, two closer than the solver's merging distance counted once (round trips in
/// a ratio p / q: the multiples of T_A / p that a p + b q reaches); every output row reads the
/// stored waves of the pieces of one round trip in each rod. A re-contact starts a family of
/// breakpoints of its own, not known beforehand and not counted.

#include <string>

#include <references/exact/ExactCost.hpp>
#include <references/exact/Rod.hpp>

namespace beamimpact::exact {

/// @brief The estimate for one solution.
struct CoaxialRodsCost {
  double pieces = 0.0;      ///< pieces of the solution (the approach included): its stops
  double rows = 0.0;        ///< output rows
  double wave_reads = 0.0;  ///< binary searches of the stored waves: 2 per piece, and per row 2
                            ///< per interval of each rod's wave field
  double bytes = 0.0;       ///< pieces and rows held at once
  /// @brief Seconds of one core at the measured rates (CoaxialRodsCost.cc).
  double seconds() const;
  /// @brief "2.5e+03 pieces (breakpoints 0.4 s apart), 2e+04 rows x 28 wave reads; about ...".
  std::string to_string() const;
  /// @brief The estimate as the limits read it (ExactCost.hpp).
  ExactCost total() const { return {seconds(), bytes, to_string()}; }
};

/// @brief Distinct sums a T_A + b T_B (a, b >= 0) below span (s), two within merge (s) of each
/// other counted once when the round trips are commensurate to that accuracy.
/// @param TA, TB round trips (s, > 0)
/// @param span the time after the first touch (s)
/// @param merge the solver's merging distance (s)
double breakpoint_sums(double TA, double TB, double span, double merge);

/// @brief The cost of CoaxialRods(a, b, v0, gap, t_end, far) read at rows dt_out (s) apart.
CoaxialRodsCost estimate_coaxial_rods_cost(const Rod& a, const Rod& b, double v0, double gap, double t_end,
                                           double dt_out);

}  // namespace beamimpact::exact
