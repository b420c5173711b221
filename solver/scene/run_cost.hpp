#pragma once
/// @file run_cost.hpp
/// @brief What a run will cost, estimated from the scene before anything is allocated: steps,
/// degrees of freedom, work (DOF-steps) and memory. A run far beyond the ordinary is refused
/// (bad input, exit 2) unless the scene asks for it with time.allow_long_run = true; a step
/// count that does not fit a 64-bit counter or the double time axis is always refused.

#include <string>

#include <solver/scene/Scene.hpp>

namespace beamimpact {

/// @brief The estimate for one scene and step.
struct RunCost {
  double steps = 0.0;        ///< ceil(end / dt)
  double wave_steps = 0.0;   ///< end / (smallest axial element transit time): what resolving the
                             ///< fastest wave takes (IDA's and the exact method's own steps)
  double dofs = 0.0;         ///< 3 per node (u_x, u_y, theta), all bodies
  double work = 0.0;         ///< max(steps, wave_steps) x dofs (DOF-steps)
  double bytes = 0.0;        ///< model + recorded history, estimated
  double field_bytes = 0.0;  ///< the field files of output.fields (0 without), estimated
  /// @brief "4e+05 steps x 66 DOFs = 2.6e+07 DOF-steps, about 0.01 GB".
  std::string to_string() const;
};

/// @brief Limits of an ordinary run: 1e11 DOF-steps is 8-18 minutes of one core at the measured
/// 0.9-2.2e8 DOF-steps/s (README, Benchmarks), far more with contact search or IDA; 4 GB is what
/// a CI machine or a laptop has. Above either, time.allow_long_run = true is needed.
inline constexpr double kOrdinaryWork = 1e11;  ///< DOF-steps
inline constexpr double kOrdinaryBytes = 4e9;  ///< bytes
/// @brief Field files (output.fields) above this many bytes need time.allow_long_run = true or a
/// larger time.output_every: a disk fills silently otherwise (one .vtu per output row).
inline constexpr double kOrdinaryFieldBytes = 1e9;
/// @brief Above this many steps a run is refused outright: t + dt == t in double precision near
/// t = end once end / dt exceeds 2^52 (4.5e15), and the step counter must not overflow.
inline constexpr double kMostSteps = 1e15;

/// @brief The estimate for `scene` run with step `dt` (s). dt <= 0 or not finite gives infinite
/// steps.
RunCost estimate_run_cost(const Scene& scene, double dt);

/// @brief An upper estimate of the critical step (s) before the model is built: the smallest
/// axial element transit time le sqrt(rho / E) (bending and contact only lower it), times
/// time.fraction. Used for dt = "auto".
double estimate_auto_dt(const Scene& scene);

/// @brief The step (s) a run of `scene` is checked with before its model exists: time.dt, or
/// estimate_auto_dt() for dt = "auto".
inline double planned_dt(const Scene& scene) {
  return scene.time.dt ? *scene.time.dt : estimate_auto_dt(scene);
}

/// @brief Throws InputError (key time.dt or time.allow_long_run) when `scene` at step `dt` (s)
/// has more than kMostSteps steps, or exceeds kOrdinaryWork / kOrdinaryBytes without
/// time.allow_long_run; key output.fields when the field files exceed kOrdinaryFieldBytes
/// without it. The message states the estimate and the setting that allows the run.
/// @return the estimate it checked (estimate_run_cost(scene, dt)).
RunCost check_run_cost(const Scene& scene, double dt);

/// @brief Throws InputError (key time.allow_long_run) when the assembled model of `scene` alone
/// (estimate_run_cost's model part, no history) exceeds kOrdinaryBytes without
/// time.allow_long_run: `beamimpact model` refuses what `run` would refuse for its model.
/// @return the estimated bytes of the model
double check_model_cost(const Scene& scene);

/// @brief The number of steps ceil(end / dt - 1e-9) as a long, after the check against
/// kMostSteps (InputError on key time.dt otherwise).
long step_count(const Scene& scene, double dt);

}  // namespace beamimpact
