#pragma once
/// @file scene_io.hpp
/// @brief Reads and validates a scene TOML file (docs/scene-format.md).

#include <filesystem>
#include <string>
#include <vector>

#include <solver/scene/Override.hpp>
#include <solver/scene/Scene.hpp>

namespace beamimpact {

/// @brief Loads `path`, applies `overrides` ("time.dt=0.005", "bodies.B.elements=20",
/// "bodies[1].elements=20", "contacts[0].friction=0.3"; values are TOML, bare words are strings)
/// and validates everything. Throws InputError naming the file, the key and what was expected.
/// Each assignment is parsed once (parse_override) and applied as load_scene_with() applies it.
Scene load_scene(const std::filesystem::path& path, const std::vector<std::string>& overrides = {});

/// @brief As load_scene(), with overrides already typed (a run's step or mesh): each is put into
/// the parsed file in order before anything is read, and recorded in Scene::overrides by its key
/// and text, as a --set of that text would be.
/// @param path the scene file; @param overrides applied in order (a later one wins)
Scene load_scene_with(const std::filesystem::path& path, const std::vector<Override>& overrides);

/// @brief As load_scene(), from TOML text already in memory (the Python module's
/// Scene.from_dict). `label` stands for the file name in messages and in summary.json;
/// scene_sha256 is that of `text`.
/// @param text the scene as TOML
/// @param label what messages name as the file ("<dict>")
/// @param overrides as for load_scene()
Scene load_scene_text(const std::string& text, const std::string& label,
                      const std::vector<std::string>& overrides = {});

/// @brief As load_scene_with(), from a scene already parsed (the Python module's
/// Scene.from_dict builds the table from the dict). `label` stands for the file name in messages
/// and in summary.json; scene_sha256 is that of the table written as a TOML file.
/// @param root the scene's tables
/// @param label what messages name as the file ("<dict>")
/// @param overrides as for load_scene_with()
Scene load_scene_table(toml::table root, const std::string& label,
                       const std::vector<Override>& overrides = {});

/// @brief The scene's file with its --set overrides applied, as TOML text: the scene an external
/// method reads (it has no --set of its own). Throws InputError when the file cannot be read.
std::string scene_toml(const Scene& scene);

}  // namespace beamimpact
