#pragma once
/// @file gap_in_contact.hpp
/// @brief The gap while a contact carries a force: each step a pair has R > 0, the striker
/// node's signed distance from the deformed surface that pair's rows interpolate (the chords for
/// linear weights, chord plus beam cubic for a Hermite surface; model/deformed_geometry). The
/// paper's contact closes the gap along the normal, so under a force this gap is zero; the
/// summary's real_gap_min (least over the whole run) cannot show a penetration under force when
/// the run is deeper elsewhere or the beam cubic lies below the chord.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <solver/contact/ContactPair.hpp>
#include <solver/contact/ContactSolver.hpp>
#include <solver/model/deformed_geometry.hpp>
#include <solver/record/SimulationResult.hpp>

namespace beamimpact::paper {

/// @brief Tracks, per scene contact, the least gap of its pairs while they carry a force.
class GapInContact {
 public:
  /// @param model the beam model
  /// @param scene the scene run (its contacts, their law, the targets' lengths)
  /// @param pairs every contact pair of the integrator (indexed as its forces)
  /// @param surface the rows' interpolation of the target (which surface the gap is measured to)
  GapInContact(const Model& model, const Scene& scene, const std::vector<ContactPair>& pairs,
               SurfaceInterpolation surface);

  /// @brief One step: scene contact `contact` made of pairs `group`, their forces, U and t (s).
  /// Only pairs with R > 0 are measured (O(1) each: the closest-point search starts at the last
  /// element found).
  void track(std::size_t contact, const std::vector<int>& group, const std::vector<ContactForce>& forces,
             const Eigen::VectorXd& U, double t);

  /// @brief Writes contacts[c].extra's real_gap_in_contact_min (m), real_gap_in_contact_min_time
  /// (s) and real_gap_in_contact (what was measured), for contacts that carried a force, and a
  /// warning (result.extra["warnings"]) for each below -tolerance(c).
  void report(const Scene& scene, SimulationResult& result) const;

  /// @brief The penetration under force (m) beyond which contact c warns: 1e-9 of the target's
  /// length for the hard law on linear weights (the .cc says why); +inf (never) for a Hertz
  /// spring, compressed by design, and for a Hermite surface, whose rows' cubic (in the target's
  /// reference axes) differs from the measured one (about the deformed chord) by design.
  double tolerance(std::size_t c) const { return tol_[c]; }

 private:
  std::vector<DeformedSurface> surfaces_;         ///< per pair, the rows' surface
  std::vector<std::pair<double, double>> least_;  ///< per contact: least gap (m), its time (s)
  std::vector<double> tol_;                       ///< per contact, m
  std::string measured_;                          ///< the summary's description
};

}  // namespace beamimpact::paper
