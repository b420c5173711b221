#pragma once
/// @file command_run.hpp
/// @brief `beamimpact run SCENE --out DIR [--method M] [--dt S] [--mesh M] [--set key=value ...]`.

#include <CLI/CLI.hpp>

namespace beamimpact {

/// @brief Registers the `run` subcommand on app.
void add_command_run(CLI::App& app);

}  // namespace beamimpact
