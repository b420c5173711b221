#include <references/exact/finish_summary.hpp>

namespace beamimpact::exact {
namespace {

const char* kMergeRule =
    "exact event times: an interval runs from the first to the last instant of positive force; "
    "a zero-force phase with the gap still closed is not a separation (no merging of real gaps)";

}  // namespace

SimulationResult finish_summary(ResultRecorder& rec, std::vector<HistoryRow> rows,
                                const std::vector<std::array<double, 2>>& intervals, double impulse,
                                double peak, double first, ContactKind kind, nlohmann::json contact_extra) {
  rec.set_merge_rule(0.0, kMergeRule);
  const double dt = rec.result().dt;
  for (HistoryRow& row : rows) {
    rec.sample(0, row.t, row.contacts[0].R, 0.0, dt, row.contacts[0].state);
    rec.track_real_gap(0, row.t, row.contacts[0].gap);  // the exact solution's gap is the real one
    rec.track_momentum(row.momentum);
    rec.add_row(std::move(row));
  }
  SimulationResult r = rec.finish({kind});
  ContactSummary& s = r.contacts[0];
  contact_extra["intervals_on_output_grid"] = s.intervals;
  contact_extra["impulse_on_output_grid"] = s.impulse_normal;
  s.intervals = intervals;
  s.interval_impulses.clear();  // known exactly only where the solution says (rods, wall)
  s.impulse_normal = impulse;
  s.peak_R = peak;
  s.first_step_R = first;
  s.extra = std::move(contact_extra);
  return r;
}

}  // namespace beamimpact::exact
