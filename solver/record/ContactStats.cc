#include <solver/record/ContactStats.hpp>

#include <algorithm>

namespace beamimpact {

ContactStats::ContactStats(double merge_gap, std::string rule)
    : intervals_(merge_gap), rule_(std::move(rule)) {}

void ContactStats::add(double t, double R, double tau, double dt, ContactState state) {
  if (!(R > 0.0)) {
    in_contact_ = false;
    return;
  }
  impulse_n_ += R * dt;
  impulse_t_ += tau * dt;
  peak_ = std::max(peak_, R);
  if (state == ContactState::kStick) ++stick_;
  if (state == ContactState::kSlip) ++slip_;
  if (!in_contact_) {
    // A (re-)closure: the first sample of a contact phase carries the closure impulse.
    if (intervals_.begin(t)) peaks_.push_back({0.0, R});
    in_contact_ = true;
  } else {
    peaks_.back().after_closure = std::max(peaks_.back().after_closure, R);
  }
  intervals_.extend(t);
  peaks_.back().impulse += R * dt;
}

void ContactStats::fill(ContactSummary& s) const {
  s.intervals = intervals_.intervals();
  s.interval_impulses.clear();
  s.peak_R_excluding_closure = 0.0;
  for (const Peaks& p : peaks_) {
    s.peak_R_excluding_closure = std::max(s.peak_R_excluding_closure, p.after_closure);
    s.interval_impulses.push_back(p.impulse);
  }
  s.merge_rule = rule_;
  s.impulse_normal = impulse_n_;
  s.impulse_tangential = impulse_t_;
  s.peak_R = peak_;
  s.first_step_R = peaks_.empty() ? 0.0 : peaks_.front().closure_R;
  s.stick_steps = stick_;
  s.slip_steps = slip_;
}

}  // namespace beamimpact
