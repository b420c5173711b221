#pragma once
/// @file command_study.hpp
/// @brief `beamimpact study STUDY.toml --out DIR`: a parameter study (verification/study/).

#include <CLI/CLI.hpp>

namespace beamimpact {

/// @brief Registers the `study` subcommand on app. Exit codes: 0 the study ran (cases that
/// failed or diverged are recorded in its table), 2 bad input (study file, options).
void add_command_study(CLI::App& app);

}  // namespace beamimpact
