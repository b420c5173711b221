#pragma once
/// @file method.hpp
/// @brief The paper's integrator as a method of the registry (api/registry.hpp).

#include <solver/method/Method.hpp>

namespace beamimpact::paper {

/// @brief The registry entry of the paper's integrator: its name "paper", what it accepts
/// (everything), its options table [paper], its thread limit (kMaxThreads); no reference rank
/// (the method every scorecard scores, never the reference of a card).
Method method();

}  // namespace beamimpact::paper
