#pragma once
/// @file scene_io.hpp
/// @brief Reads and validates a scene TOML file (docs/scene-format.md).

#include <filesystem>
#include <string>
#include <vector>

#include <solver/scene/Scene.hpp>

namespace beamimpact {

/// @brief Loads `path`, applies `overrides` ("time.dt=0.005", "bodies.B.elements=20",
/// "bodies[1].elements=20", "contacts[0].friction=0.3"; values are TOML, bare words are strings)
/// and validates everything. Throws InputError naming the file, the key and what was expected.
Scene load_scene(const std::filesystem::path& path, const std::vector<std::string>& overrides = {});

/// @brief As load_scene(), from TOML text already in memory (the Python module's
/// Scene.from_dict). `label` stands for the file name in messages and in summary.json;
/// scene_sha256 is that of `text`.
/// @param text the scene as TOML
/// @param label what messages name as the file ("<dict>")
/// @param overrides as for load_scene()
Scene load_scene_text(const std::string& text, const std::string& label,
                      const std::vector<std::string>& overrides = {});

/// @brief The scene's file with its --set overrides applied, as TOML text: the scene an external
/// method reads (it has no --set of its own). Throws InputError when the file cannot be read.
std::string scene_toml(const Scene& scene);

}  // namespace beamimpact
