#pragma once
/// @file run_command.hpp
/// @brief `beamimpact run SCENE --out DIR [--method M] [--set key=value ...]`.

#include <CLI/CLI.hpp>

namespace beamimpact {

/// @brief Registers the `run` subcommand on app.
void add_run_command(CLI::App& app);

}  // namespace beamimpact
