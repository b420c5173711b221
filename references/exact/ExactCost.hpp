#pragma once
/// @file ExactCost.hpp
/// @brief The limit every exact solution's cost estimate is held to before it is computed, and
/// the one refusal they share (RodOnBeamCost.hpp, CoaxialRodsCost.hpp).

#include <string>

#include <solver/scene/Scene.hpp>

namespace beamimpact::exact {

/// @brief A solution beyond this many seconds of one core (or kOrdinaryBytes of memory) is far
/// beyond an ordinary run (run_cost.hpp: 1e11 DOF-steps, 8-18 minutes) and needs
/// time.allow_long_run = true.
inline constexpr double kOrdinaryExactSeconds = 600.0;

/// @brief Bytes of one output row held until it is written (RodOnBeamRow, HistoryRow).
inline constexpr double kBytesPerRow = 200.0;

/// @brief An exact solution's estimate, in the units the limits are stated in.
struct ExactCost {
  double seconds = 0.0;  ///< s of one core
  double bytes = 0.0;    ///< memory held at once
  std::string text;      ///< the estimate in words ("256 modes: 8.7e+04 integrator stops ...")
};

/// @brief Throws InputError on `key` when `cost` exceeds kOrdinaryExactSeconds or
/// kOrdinaryBytes and the scene does not set time.allow_long_run; the message states the
/// estimate, the limits, what lowers the cost and the setting that allows the run.
/// @param scene the scene (its file and time.allow_long_run)
/// @param key the key named by the refusal (the setting that drives the cost)
/// @param what the solution, e.g. "the rod-on-beam solution"
/// @param cost the estimate
/// @param remedy what lowers the cost, e.g. "set a shorter time.end, a larger exact.dt_out"
void refuse_extraordinary(const Scene& scene, const std::string& key, const std::string& what,
                          const ExactCost& cost, const std::string& remedy);

}  // namespace beamimpact::exact
