#pragma once
/// @file command_scenes.hpp
/// @brief `beamimpact scenes` (the shipped scenes, by name, with their files) and the transform
/// every scene argument goes through (api/shipped_scenes.hpp: a shipped scene's name, or a path
/// under the data root, works from any folder).

#include <CLI/CLI.hpp>

namespace beamimpact {

/// @brief Registers `scenes` on app.
void add_command_scenes(CLI::App& app);

/// @brief The transform of a scene argument (run, sweep, model): resolve_scene(); a name that
/// matches several shipped scenes is refused (exit 2).
CLI::Validator scene_argument();

}  // namespace beamimpact
