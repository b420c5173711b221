#pragma once
/// @file exact::solve.hpp
/// @brief `beamimpact run SCENE --method exact`: exact references that no discretisation of
/// ours can bias (references.md sections 1-2): free coaxial rods (d'Alembert, exact) and a rod
/// end-on onto a simply supported Euler-Bernoulli beam (exact rod waves + converged modal sum).

#include <solver/record/SimulationResult.hpp>

namespace beamimpact::exact {

/// @brief Runs the exact solution of the scene. Throws InputError (exit 2) when the scene has
/// no exact counterpart, naming the condition that failed, or for a bad [exact] table.
///
/// [exact] options (all optional): dt_out (s, output interval; default time.dt x
/// output_every, or end/2000 when dt = "auto"); for the rod-on-beam: modes (fixed count, no
/// convergence study), modes_min (16), modes_max (512), mode_tolerance (1e-3, relative change
/// of impulse and contact times per doubling), rtol (1e-10, rk8pd tolerance).
SimulationResult solve(const Scene& scene);

}  // namespace beamimpact::exact
