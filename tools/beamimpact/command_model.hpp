#pragma once
/// @file command_model.hpp
/// @brief `beamimpact model SCENE --out DIR [--set key=value ...]`: exports the scene's
/// semi-discrete model (matrices, DOF map, initial state, contact rows) for outside solvers.

#include <CLI/CLI.hpp>

namespace beamimpact {

/// @brief Registers the `model` subcommand on app.
void add_command_model(CLI::App& app);

}  // namespace beamimpact
