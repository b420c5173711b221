#include <references/ida/step_mean_rows.hpp>

#include <algorithm>
#include <utility>

namespace beamimpact::ida {

StepMeanRows::StepMeanRows(ResultRecorder& rec, std::vector<double> closure_windows)
    : rec_(rec),
      windows_(std::move(closure_windows)),
      touched_(windows_.size(), 0),
      peaks_(windows_.size()) {}

void StepMeanRows::add(HistoryRow row, const std::vector<std::array<double, 2>>& impulses,
                       const std::vector<std::vector<double>>& onsets) {
  if (pending_) {
    const double h = row.t - pending_->t;
    for (std::size_t i = 0; i < windows_.size(); ++i) {
      ContactSample& c = pending_->contacts[i];
      // Open over the whole step: no force. Else the impulse of the step over its length; the
      // quadrature of a force >= 0 can only fall by its roundoff, which is not a force.
      c.R = touched_[i] ? std::max(0.0, (impulses[i][0] - impulses_[i][0]) / h) : 0.0;
      c.tau = touched_[i] ? (impulses[i][1] - impulses_[i][1]) / h : 0.0;
    }
    hand_over(row.t, onsets);
  }
  for (std::size_t i = 0; i < windows_.size(); ++i)
    touched_[i] = row.contacts[i].state != ContactState::kOpen;
  pending_ = std::move(row);
  impulses_ = impulses;
}

void StepMeanRows::finish(const std::vector<std::vector<double>>& onsets) {
  if (pending_) hand_over(pending_->t, onsets);
}

void StepMeanRows::hand_over(double t_next, const std::vector<std::vector<double>>& onsets) {
  const double t = pending_->t;
  for (std::size_t i = 0; i < windows_.size(); ++i) {
    const double R = pending_->contacts[i].R;
    RowPeaks& p = peaks_[i];
    if (R > 0.0 && p.all == 0.0) p.first_closure = R;
    p.all = std::max(p.all, R);
    // The row's step [t, t_next] meets the window [o, o + w] of an onset o (the last row: its time).
    const bool meets = std::any_of(onsets[i].begin(), onsets[i].end(),
                                   [&](double o) { return (o < t_next || o <= t) && o + windows_[i] >= t; });
    if (!meets) p.outside_closure = std::max(p.outside_closure, R);
  }
  rec_.add_row(std::move(*pending_));
  pending_.reset();
}

}  // namespace beamimpact::ida
