#pragma once
/// @file run_checks.hpp
/// @brief Health metrics of ONE run, without a reference: what a hard case must keep whatever its
/// accuracy (energy bookkeeping, no tension, the friction cone, no real penetration, momentum).
/// Each is a Norm whose value is >= 0 and 0 when perfect, so a matrix gate "value <= tol" reads
/// as for the comparison norms (the `[[check]]` entries of matrix.toml).

#include <string>
#include <vector>

#include <verification/compare/Comparison.hpp>
#include <verification/compare/RunView.hpp>

namespace beamimpact::verification {

/// @brief The health metrics of a run: energy_band, energy_growth, dissipated_decrease, tension,
/// friction_cone, penetration, momentum_drift (definitions in each Norm). A metric the run cannot give (no
/// dissipated column, no friction coefficient in the summary, ...) is unavailable with the reason.
/// @param run the run (a run directory: StoredRun::read(dir).view())
Comparison check_run(const RunView& run);

/// @brief The names check_run() produces.
const std::vector<std::string>& check_names();

/// @brief True for a name check_run() produces.
bool known_check(const std::string& name);

}  // namespace beamimpact::verification
