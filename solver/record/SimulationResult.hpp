#pragma once
/// @file SimulationResult.hpp
/// @brief What every method (paper, ida, exact) hands to the writers of history.csv and
/// summary.json. Methods fill it; write_outputs() (run_output.hpp) turns it into files.

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <solver/scene/Scene.hpp>
#include <solver/schema/output_schema.hpp>

namespace beamimpact {

/// @brief One contact's columns of one history row (SI units, global axes).
struct ContactSample {
  double R = 0.0;    ///< N, normal force, >= 0 compressive
  double tau = 0.0;  ///< N, tangential force on the striker along the target tangent
  double gap = 0.0;  ///< m, normal gap (after the step R acts on, for the paper's scheme)
  Vec2 ua{}, va{};   ///< striker contact node displacement (m) and velocity (m/s)
  Vec2 ub{}, vb{};   ///< struck point on the target: displacement (m) and velocity (m/s)
  ContactState state = ContactState::kOpen;
};

/// @brief One row of history.csv.
struct HistoryRow {
  double t = 0.0;                       ///< s
  std::vector<ContactSample> contacts;  ///< one per scene contact, in scene order
  double kinetic = 0.0, strain = 0.0;   ///< J, totals over all bodies (strain: with Hertz contact springs)
  double dissipated = 0.0;              ///< J, cumulative: closures, friction, damping
  /// J, work of the external loads ([loads]) since t = 0: the energy account is
  /// kinetic + strain + dissipated - load_work = its value at t = 0
  double load_work = 0.0;
  Vec2 momentum{};  ///< N s, total linear momentum
};

/// @brief Per-contact scalars of summary.json ("contacts" array).
struct ContactSummary {
  std::string striker, target;
  ContactKind kind = ContactKind::kEndToEnd;
  double friction = 0.0;                         ///< Coulomb mu the method applied
  std::vector<std::array<double, 2>> intervals;  ///< s, [start, end] of each contact interval
  std::vector<double> interval_impulses;         ///< N s, normal impulse of each interval
  std::string merge_rule;                        ///< how chatter was merged into intervals
  double impulse_normal = 0.0;                   ///< N s
  double impulse_tangential = 0.0;               ///< N s
  double peak_R = 0.0;                           ///< N, including closure steps
  double peak_R_excluding_closure = 0.0;         ///< N, first step of each interval left out
  double first_step_R = 0.0;                     ///< N, the closure step of the first interval
  long stick_steps = 0, slip_steps = 0;
  double real_gap_min = 0.0;       ///< m, smallest real gap (deformed geometry; < 0: penetration)
  double real_gap_min_time = 0.0;  ///< s, when it occurred
  nlohmann::json extra = nlohmann::json::object();  ///< method-specific keys
};

/// @brief Everything one run produced.
struct SimulationResult {
  std::string method;            ///< the registry name: "paper" | "ida" | "exact"
  std::string contact_sampling;  ///< how contacts were sampled (ResultRecorder::describe)
  double dt = 0.0;               ///< s, the step (nominal output step for adaptive methods)
  double critical_dt = 0.0;      ///< s, 0 when not applicable
  long steps = 0;                ///< time steps taken
  /// @brief s, the time of the last row: a fixed step's ceil(end / dt) dt, at time.end or up to
  /// one step past it (0: not recorded, summary.json then states time.end)
  double end_time = 0.0;
  long dofs = 0;  ///< DOFs of the discrete beam model (0: none, e.g. a modal solution)
  double wall_seconds = 0.0;
  std::vector<std::string> effects;            ///< e.g. {"axial"} or {"axial", "bending", "friction"}
  std::map<std::string, std::string> assumed;  ///< method-level defaults (merged with the scene's)
  /// @brief The kinematics the method ran ("linear" or "corotational"), when it is not the scene's
  /// (summary.json settings.model.kinematics states it); empty: the scene's.
  std::string kinematics;
  std::vector<HistoryRow> history;  ///< rows to write, already thinned by output_every
  std::vector<ContactSummary> contacts;
  std::map<std::string, Vec2> final_velocity;       ///< body name -> centre-of-mass velocity, m/s
  double energy_initial = 0.0, energy_final = 0.0;  ///< J, kinetic + strain
  double momentum_drift_max =
      0.0;  ///< N s, max |p(t) - p(0) - F t|, F the loads' net force (meaningful for free bodies)
  nlohmann::json extra = nlohmann::json::object();  ///< method-specific top-level keys
  nlohmann::json settings =
      nlohmann::json::object();  ///< method-specific run settings (summary.json "settings")
};

}  // namespace beamimpact
