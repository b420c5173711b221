#pragma once
/// @file compare_runs.hpp
/// @brief Error norms between a run and a reference run (`beamimpact compare`).

#include <verification/compare/Comparison.hpp>
#include <verification/compare/RunView.hpp>

namespace beamimpact::verification {

/// @brief Settings of a comparison; zero means "derive from the histories" (written in the output).
struct CompareOptions {
  double grid_step = 0.0;  ///< s; default: the finer of the two output steps
  double window = 0.0;     ///< s; default: 10 x the coarser output step
  double merge_gap =
      0.0;  ///< s; default: default_merge_gap() of the coarser output step (ContactIntervals.hpp)
  double threshold = 1e-6;  ///< R > threshold x max R of the reference counts as contact
  /// @brief Read the run (a) from its history.csv only: its impulse is the last value of its
  /// `impulse` column, else the trapezoid integral of R over its rows; its contact intervals are
  /// its rows with R above the threshold, merged by merge_gap (ContactIntervals' rule); its
  /// interval impulses the running impulse's rise over each interval. Its summary.json is then
  /// used only for what a history cannot show (bodies' final velocities). false: summary.json's
  /// impulse_normal, intervals and interval_impulses when it has them. `beamimpact score` sets it
  /// for the scored run: a summary that disagrees with its own rows cannot improve a score.
  bool run_from_history = false;
  /// @brief The same for the reference (b); false keeps a built-in reference's event-accurate
  /// summary (exact event times, IDA's quadrature).
  bool reference_from_history = false;
};

/// @brief Compares run `a` with reference `b`: relative L2 and L-infinity norms over time of the
/// contact force, its running impulse, its window average, the displacements and velocities of
/// both contact points (every contact), and scalar errors (impulse, contact start and end,
/// number of impacts, peak force excluding closure samples, final velocities, final energy).
/// Both histories are resampled onto one uniform grid over their common time span.
/// Impulse, intervals and interval impulses of each side come from its summary.json unless
/// options.run_from_history / reference_from_history say to read that side from its history.csv.
/// Throws InputError when the histories do not overlap in time.
/// A run directory is compared through StoredRun::read(dir).view(), a run in memory through
/// RunView::from_result().
Comparison compare_runs(const RunView& a, const RunView& b, const CompareOptions& options = {});

/// @brief True when compare_runs produces a norm of this name for some number of contacts
/// ("R.rel_l2", "impulse_2", "final_velocity", ...): lets a matrix reject a misspelt metric.
bool known_norm(const std::string& name);

}  // namespace beamimpact::verification
