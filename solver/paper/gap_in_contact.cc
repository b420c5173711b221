#include <solver/paper/gap_in_contact.hpp>

#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace beamimpact::paper {

// The warning's tolerance, 1e-9 of the target's length: the closure along the normal is exact to
// roundoff in the coordinates (1e-16 of them) and the multi-contact sweep's 1e-13 of R, far
// below it; above it stays what the method leaves by design, a striker slipping along the target
// during the step's correction (S4-45 with friction: 3.3e-10 m on its 10 m target, 1/30 of it).
// Relocating the struck point off the striker's line along the normal left 4e-4 m (4e-5 of the
// target) under force on the first element next to a pin.
constexpr double kWarnPerLength = 1e-9;

GapInContact::GapInContact(const Model& model, const Scene& scene, const std::vector<ContactPair>& pairs,
                           SurfaceInterpolation surface)
    : least_(scene.contacts.size(), {std::numeric_limits<double>::infinity(), 0.0}) {
  const bool chords = surface == SurfaceInterpolation::kLinear;
  for (const ContactPair& pair : pairs)
    surfaces_.emplace_back(model, pair.target_body(), pair.striker_node(),
                           chords ? Centreline::kChord : Centreline::kBeam);
  for (const Contact& k : scene.contacts)
    tol_.push_back(chords && k.law == ContactLaw::kHard ? kWarnPerLength * scene.bodies[k.target].length()
                                                        : std::numeric_limits<double>::infinity());
  measured_ = fmt::format(
      "least signed distance (m) of the striker node from the target's deformed {} over the steps "
      "with R > 0, and when (s): the hard law closes the gap along the normal, so it stays at "
      "roundoff unless the striker slips along the target during a step's correction (warning "
      "below -{:g} x the target's length); a Hertz spring's is its compression",
      chords ? "chords (the surface the contact rows' linear weights interpolate)"
             : "centreline (chord plus beam cubic; the Hermite rows' cubic is in the reference axes)",
      kWarnPerLength);
}

void GapInContact::track(std::size_t contact, const std::vector<int>& group,
                         const std::vector<ContactForce>& forces, const Eigen::VectorXd& U, double t) {
  for (int q : group) {
    if (!(forces[q].R > 0.0)) continue;
    const double g = surfaces_[q].gap(U).gap;
    if (g < least_[contact].first) least_[contact] = {g, t};
  }
}

void GapInContact::report(const Scene& scene, SimulationResult& result) const {
  for (std::size_t c = 0; c < least_.size(); ++c) {
    const auto [gap, t] = least_[c];
    if (!std::isfinite(gap)) continue;  // never carried a force
    nlohmann::json& extra = result.contacts[c].extra;
    extra["real_gap_in_contact_min"] = gap;
    extra["real_gap_in_contact_min_time"] = t;
    extra["real_gap_in_contact"] = measured_;
    if (gap >= -tol_[c]) continue;
    const Contact& k = scene.contacts[c];
    result.extra["warnings"].push_back(
        fmt::format("contact {} -> {}: the striker node was {:.3g} m inside the target's deformed surface at "
                    "t = {:.6g} s while the contact carried a force (tolerance {:.3g} m); the contact closes "
                    "the gap along the normal, so the striker moved along the target during the step's "
                    "correction (slip, a turning striker): a smaller time.dt reduces it",
                    scene.bodies[k.striker].name, scene.bodies[k.target].name, -gap, t, tol_[c]));
  }
}

}  // namespace beamimpact::paper
