#include <solver/record/ContactIntervals.hpp>

namespace beamimpact {

bool ContactIntervals::begin(double t) {
  // The merge rule: a gap shorter than merge_gap (from the last interval's end) is chatter.
  if (!intervals_.empty() && t - intervals_.back()[1] < merge_gap_) {
    intervals_.back()[1] = t;
    return false;
  }
  intervals_.push_back({t, t});
  return true;
}

}  // namespace beamimpact
