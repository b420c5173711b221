#pragma once
/// @file output_times.hpp
/// @brief The output grid of the exact solutions: k dt_out, k = 0, 1, ... while <= t_end.

#include <vector>

namespace beamimpact::exact {

/// @brief Output times k dt_out (s), k = 0, 1, ... while <= t_end (1e-12 relative slack; the
/// last one clamped to t_end).
std::vector<double> output_times(double dt_out, double t_end);

/// @brief How many output_times(dt_out, t_end) there are, without building them (a cost
/// estimate's rows).
double output_row_count(double dt_out, double t_end);

}  // namespace beamimpact::exact
