#include <solver/record/ResultRecorder.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace beamimpact {

ResultRecorder::ResultRecorder(const Scene& scene, std::string method, ContactSampling sampling)
    : scene_(scene),
      real_gap_(scene.contacts.size(), {std::numeric_limits<double>::infinity(), 0.0}),
      wall0_(std::chrono::steady_clock::now()) {
  r_.method = std::move(method);
  r_.contact_sampling = describe(sampling);
}

const char* ResultRecorder::describe(ContactSampling s) {
  switch (s) {
    case ContactSampling::kFixedSteps:
      return "fixed steps: contact statistics from every time step; energies and momentum at the output rows";
    case ContactSampling::kAdaptiveSteps:
      return "adaptive steps: contact statistics and momentum from every accepted step; contact "
             "intervals and impulses from the located switching events";
    default:
      return "exact events: intervals, impulse and peak force from the exact solution's event times; "
             "the *_on_output_grid keys give the same quantities sampled on the output rows";
  }
}

void ResultRecorder::set_merge_rule(double merge_gap, const std::string& rule) {
  stats_.assign(scene_.contacts.size(), ContactStats(merge_gap, rule));
}

void ResultRecorder::track_momentum(const Vec2& p, double t) {
  if (!momentum_started_) {
    p0_ = p;
    t0_ = t;
    momentum_started_ = true;
  }
  const double dx = p[0] - p0_[0] - load_force_[0] * (t - t0_),
               dy = p[1] - p0_[1] - load_force_[1] * (t - t0_);
  r_.momentum_drift_max = std::max(r_.momentum_drift_max, std::hypot(dx, dy));
}

void ResultRecorder::add_row(HistoryRow row) {
  const double E = row.kinetic + row.strain;
  if (rows_++ == 0 && !initial_energy_set_) r_.energy_initial = E;
  r_.end_time = row.t;
  r_.energy_final = E;
  load_work_final_ = row.load_work;
  if (scene_.output.history) r_.history.push_back(std::move(row));
}

SimulationResult ResultRecorder::finish(const std::vector<ContactKind>& kinds) {
  if (kinds.size() != scene_.contacts.size() || stats_.size() != scene_.contacts.size())
    throw std::logic_error("ResultRecorder::finish: one kind and one merge rule per scene contact");
  r_.contacts.clear();
  for (std::size_t c = 0; c < scene_.contacts.size(); ++c) {
    ContactSummary s;
    s.striker = scene_.bodies[scene_.contacts[c].striker].name;
    s.target = scene_.bodies[scene_.contacts[c].target].name;
    s.kind = kinds[c];
    s.friction = scene_.contacts[c].friction;
    stats_[c].fill(s);
    if (std::isfinite(real_gap_[c].first)) std::tie(s.real_gap_min, s.real_gap_min_time) = real_gap_[c];
    r_.contacts.push_back(std::move(s));
  }
  if (scene_.loads.any()) {
    nlohmann::json points = nlohmann::json::array();
    for (const PointLoad& p : scene_.loads.point)
      points.push_back({{"body", scene_.bodies[p.body].name}, {"node", p.node}, {"force", p.force}});
    r_.extra["loads"] = {{"gravity", scene_.loads.gravity},
                         {"point", points},
                         {"work_final", load_work_final_},
                         {"energy_account",
                          "kinetic + strain + dissipated - load_work = energy_initial (history.csv columns; "
                          "load_work: the work of the constant loads since t = 0)"}};
  }
  r_.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count();
  return std::move(r_);
}

}  // namespace beamimpact
