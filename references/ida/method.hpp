#pragma once
/// @file method.hpp
/// @brief SUNDIALS IDA as a method of the registry (api/registry.hpp).

#include <solver/method/Method.hpp>

namespace beamimpact::ida {

/// @brief The registry entry of IDA: name "ida", options table [ida], what it accepts (all but a
/// contact search), its rank as a reference (converged: below an exact answer) and the settings
/// that converge it for that use.
Method method();

}  // namespace beamimpact::ida
