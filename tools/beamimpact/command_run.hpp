#pragma once
/// @file command_run.hpp
/// @brief `beamimpact run SCENE --out DIR [--method M] [--set key=value ...]`, and the
/// `methods` and `schema` commands that list what `run` can do and write.

#include <CLI/CLI.hpp>

namespace beamimpact {

/// @brief Registers the `run` subcommand on app.
void add_command_run(CLI::App& app);

/// @brief Registers `methods` (the method registry as a table) and `schema` (the output schema
/// as JSON) on app.
void add_command_methods(CLI::App& app);

}  // namespace beamimpact
