#pragma once
/// @file method.hpp
/// @brief The exact solutions as a method of the registry (api/registry.hpp).

#include <solver/method/Method.hpp>

namespace beamimpact::exact {

/// @brief The registry entry of the exact solutions: name "exact", options table [exact], what
/// they accept (no mesh; friction between rigid bodies only; no rotation, search or second
/// contact), the best reference rank (an exact answer).
Method method();

}  // namespace beamimpact::exact
