#pragma once
/// @file CommandExit.hpp
/// @brief Thrown by a subcommand to end `beamimpact` with a given exit code after it has printed
/// its own message (e.g. verify: 1 when a gate fails). InputError exits 2, other errors 3.

namespace beamimpact {

/// @brief Exit request carrying the process exit code.
struct CommandExit {
  int code;
};

}  // namespace beamimpact
