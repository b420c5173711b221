#pragma once
/// @file solve.hpp
/// @brief The method "ida": the SUNDIALS IDA penalty-contact reference on the same beam model
/// (solver/model) as the paper's integrator, with its own contact geometry and time integration
/// (variable-order BDF, events located by root finding).

#include <solver/record/SimulationResult.hpp>

namespace beamimpact::ida {

/// @brief Runs the scene with the IDA reference. Options come from the scene's [ida] table
/// (see ida_options.hpp). Throws InputError for bad options, std::runtime_error if IDA fails.
/// A contact search (node = "all") is the registry's to refuse (Method::Accepts, checked by
/// api::run): here each contact is its declared node.
SimulationResult solve(const Scene& scene);

}  // namespace beamimpact::ida
