#pragma once
/// @file run_ida.hpp
/// @brief `beamimpact run --method ida`: the SUNDIALS IDA penalty-contact reference on the same
/// beam model (solver/model) as the paper's integrator, with its own contact geometry and time
/// integration (variable-order BDF, events located by root finding).

#include "io/RunResult.hpp"

namespace beamimpact {

/// @brief Runs the scene with the IDA reference. Options come from the scene's [ida] table
/// (see ida_options.hpp). Throws SceneError for bad options, std::runtime_error if IDA fails.
RunResult run_ida(const Scene& scene);

}  // namespace beamimpact
