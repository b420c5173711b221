#pragma once
/// @file ContactStats.hpp
/// @brief Accumulates a contact's force samples into intervals, impulses and peaks, the same
/// way for every method, so that summaries of different methods are comparable.

#include <string>

#include <solver/record/ContactIntervals.hpp>
#include <solver/record/SimulationResult.hpp>

namespace beamimpact {

/// @brief Feed one sample per step (or per accepted adaptive step); read the summary at the end.
///
/// A step is "in contact" when R > 0; each run of contact steps is a phase of ContactIntervals
/// (which merges chatter), and the rule is written into the summary. A closure is the first
/// sample of a phase: its force counts in first_step_R (the first interval's) but not in
/// peak_R_excluding_closure, also when the phase joins an interval.
class ContactStats {
 public:
  /// @brief merge_gap: s, gaps shorter than this are merged; rule: the sentence written out.
  ContactStats(double merge_gap, std::string rule);
  /// @brief Adds a sample at time t carrying forces R, tau over a step of length dt (s).
  void add(double t, double R, double tau, double dt, ContactState state);
  /// @brief Fills intervals, impulses, peaks and stick/slip counts of s (names and kind untouched).
  void fill(ContactSummary& s) const;

 private:
  struct Peaks {
    double after_closure, closure_R;  ///< N, one per interval
    double impulse = 0.0;             ///< N s, sum of R dt over the interval's samples
  };
  ContactIntervals intervals_;
  std::string rule_;
  std::vector<Peaks> peaks_;
  bool in_contact_ = false;
  double impulse_n_ = 0.0, impulse_t_ = 0.0, peak_ = 0.0;
  long stick_ = 0, slip_ = 0;
};

}  // namespace beamimpact
