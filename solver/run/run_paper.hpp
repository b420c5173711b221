#pragma once
/// @file run_paper.hpp
/// @brief `beamimpact run --method paper`: the Pu & Chi (2011) explicit dynamic-contact integrator.

#include "io/RunResult.hpp"

namespace beamimpact {

/// @brief Runs the scene with the paper's integrator. Throws SceneError for bad settings
/// (dt above the critical step) and std::runtime_error if the run diverges.
RunResult run_paper(const Scene& scene);

}  // namespace beamimpact
