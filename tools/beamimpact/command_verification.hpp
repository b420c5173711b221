#pragma once
/// @file commands.hpp
/// @brief The `compare`, `verify` and `sweep` subcommands of `beamimpact`.

#include <CLI/CLI.hpp>

namespace beamimpact {

/// @brief Registers compare, verify and sweep on app. Exit codes (via CommandExit / InputError):
/// 0 all gates pass, 1 a gate failed, 2 bad input (matrix, run directory, options).
void add_verification_commands(CLI::App& app);

}  // namespace beamimpact
