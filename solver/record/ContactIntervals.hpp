#pragma once
/// @file ContactIntervals.hpp
/// @brief The one rule that turns a contact's phases into contact intervals, used by every
/// method (the paper's steps, IDA's located events, the exact solutions' records) and by
/// `compare`: a phase that begins less than merge_gap seconds after the last interval's end
/// joins that interval (chatter); otherwise it opens a new one.

#include <array>
#include <cstddef>
#include <vector>

namespace beamimpact {

/// @brief The default merge gap in open steps: contact phases separated by fewer open samples
/// than this are one interval (chatter), for every method (the paper's [paper] merge_steps, IDA's
/// [ida] merge_gap, `compare`'s --merge; the Python references' references/common/contact_intervals.py).
inline constexpr long kMergeSteps = 3;

/// @brief s, the merge gap of samples `step` s apart that merges fewer than `open_steps` open
/// samples: (open_steps + 0.5) steps. Two phases n open samples apart are (n + 1) steps apart, so
/// the half step keeps round-off in the sample times from deciding the count.
/// @param open_steps the open samples that still separate two intervals; @param step s
inline double merge_gap_of(long open_steps, double step) {
  return (static_cast<double>(open_steps) + 0.5) * step;
}

/// @brief s, the default merge gap of samples `step` s apart: merge_gap_of(kMergeSteps, step).
/// @param step s, the time step or the spacing of the rows
inline double default_merge_gap(double step) { return merge_gap_of(kMergeSteps, step); }

/// @brief Contact intervals [start, end] (s), built phase by phase in time order.
///
/// A phase is a run of contact: begin(t) at its first instant (a step's sample, an onset event,
/// an interval read back from a summary), then extend(t) as it lasts. The interval's end is the
/// phase's last instant, so a gap is measured from the last contact instant to the next closure.
class ContactIntervals {
 public:
  /// @brief merge_gap: s, a phase beginning less than this after the last interval's end joins it
  /// (0 merges nothing).
  explicit ContactIntervals(double merge_gap) : merge_gap_(merge_gap) {}

  /// @brief A contact phase begins at t (s), not before the last interval's end. Returns true when
  /// it opens a new interval, false when it joins the last one (whose end becomes t).
  bool begin(double t);

  /// @brief The current phase lasts until at least t (s): the last interval's end becomes t.
  /// Requires a begin() before.
  void extend(double t) { intervals_.back()[1] = t; }

  /// @brief The intervals [start, end] (s), in time order.
  const std::vector<std::array<double, 2>>& intervals() const { return intervals_; }

  /// @brief The number of intervals so far.
  std::size_t size() const { return intervals_.size(); }

 private:
  double merge_gap_;
  std::vector<std::array<double, 2>> intervals_;
};

}  // namespace beamimpact
