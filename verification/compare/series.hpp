#pragma once
/// @file series.hpp
/// @brief Operations on sampled time series: resampling onto a common grid, integrals, norms,
/// contact intervals. A series is a list of components sampled at the same times
/// (one component for a force, two for a displacement vector).

#include <vector>

namespace beamimpact::verification {

/// @brief Components of one (possibly vector-valued) quantity at common times.
using Series = std::vector<std::vector<double>>;

/// @brief n + 1 equally spaced times from t0 to t1 with spacing at most h (s).
std::vector<double> uniform_grid(double t0, double t1, double h);

/// @brief Piecewise-linear interpolation of (t, y) at `at` (values outside [t0, tN] are clamped
/// to the end values; the comparison only asks inside the overlap of both runs).
std::vector<double> interpolate(const std::vector<double>& t, const std::vector<double>& y,
                                const std::vector<double>& at);

/// @brief Cumulative trapezoid integral I(t_i) = int_{t_0}^{t_i} y dt, I(t_0) = 0.
/// For a pulse that starts and ends at zero the total equals the rectangle sum sum(y_i dt).
std::vector<double> running_integral(const std::vector<double>& t, const std::vector<double>& y);

/// @brief sqrt(int |s|^2 dt) by the trapezoid rule on grid t (|.| is the Euclidean norm of the
/// components).
double l2_norm(const std::vector<double>& t, const Series& s);

/// @brief max over samples of |s|.
double linf_norm(const Series& s);

/// @brief a - b, component by component (same sizes).
Series difference(const Series& a, const Series& b);

/// @brief Window average (1/W) int_{t-W/2}^{t+W/2} y dt at the times of `at`, from the running
/// integral I of y on its own grid t: (I(t+W/2) - I(t-W/2)) / W, with I held constant beyond the
/// ends of the record (y treated as zero outside).
std::vector<double> window_average(const std::vector<double>& t, const std::vector<double>& I, double W,
                                   const std::vector<double>& at);

/// @brief One contact interval [start, end] (s) and the row index of its first sample.
struct Interval {
  double start = 0.0, end = 0.0;
  std::size_t first = 0, last = 0;  ///< row indices of the first and last sample in contact
};

/// @brief Intervals where R > threshold: each run of such samples is a phase, merged by
/// ContactIntervals' rule (a gap shorter than merge_gap s, from the last contact sample to the
/// next, is chatter).
std::vector<Interval> contact_intervals(const std::vector<double>& t, const std::vector<double>& R,
                                        double threshold, double merge_gap);

}  // namespace beamimpact::verification
