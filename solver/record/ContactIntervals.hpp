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
