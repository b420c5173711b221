#pragma once
/// @file command_verification.hpp
/// @brief The `compare`, `verify` and `sweep` subcommands of `beamimpact`.

#include <CLI/CLI.hpp>

#include <verification/matrix/JobSpec.hpp>

namespace beamimpact {

/// @brief Registers compare, verify and sweep on app. Exit codes (via CommandExit / InputError):
/// 0 all gates pass, 1 a gate failed, 2 bad input (matrix, run directory, options).
void add_verification_commands(CLI::App& app);

/// @brief Starts runs as `beamimpact run` with this very program, passing on every methods file
/// read (--methods), so that each run sees the same registry.
verification::Launcher launcher();

}  // namespace beamimpact
