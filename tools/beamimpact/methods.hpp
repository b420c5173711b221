#pragma once
/// @file methods.hpp
/// @brief The methods `beamimpact run --method NAME` can run, by name.

#include <functional>
#include <map>
#include <string>

#include "io/RunResult.hpp"

namespace beamimpact {

/// @brief A method: runs a validated scene, returns what write_run() writes.
using MethodFn = std::function<RunResult(const Scene&)>;

/// @brief All methods built into this binary ("paper", and "exact", "ida" when built).
const std::map<std::string, MethodFn>& methods();

}  // namespace beamimpact
