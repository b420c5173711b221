#pragma once
/// @file SceneError.hpp
/// @brief SceneError, the earlier name of InputError (solver/util/InputError.hpp), kept for a
/// deprecation period: new code names InputError.

#include <solver/util/InputError.hpp>

namespace beamimpact {

/// @brief Deprecated name of InputError (the same type: a catch of either catches both).
using SceneError = InputError;

}  // namespace beamimpact
