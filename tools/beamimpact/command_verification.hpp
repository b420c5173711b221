#pragma once
/// @file command_verification.hpp
/// @brief The `compare`, `verify` and `sweep` subcommands of `beamimpact`.

#include <CLI/CLI.hpp>

#include <filesystem>

namespace beamimpact {

/// @brief Registers compare, verify and sweep on app. Exit codes (via CommandExit / InputError):
/// 0 all gates pass, 1 a gate failed, 2 bad input (matrix, run directory, options).
void add_verification_commands(CLI::App& app);

/// @brief Adds --isolate to a command that runs a set of runs: each run is then a `beamimpact
/// run` process of this very program (`exe` is set to it) instead of a call in this process.
/// @param sub the command; @param exe its options' exe field
void add_isolate_flag(CLI::App* sub, std::filesystem::path& exe);

}  // namespace beamimpact
