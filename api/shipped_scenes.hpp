#pragma once
/// @file shipped_scenes.hpp
/// @brief The scenes shipped with beamimpact (data_root()/verification/scenes) and the one rule
/// that turns a scene argument (a path or a shipped scene's name) into a file: every command
/// that takes a scene, and the Python module, resolve it here.
///
/// The rule, first match wins:
///  1. the argument names an existing file (absolute, or relative to the working directory);
///  2. a relative argument names a file under the data root (`verification/scenes/paper/s1_central.toml`);
///  3. a relative argument names a file under the data root's verification/scenes (`paper/s1_central.toml`);
///  4. an argument without '/' is a shipped scene's name, with or without `.toml` (`s1_central`);
///  5. otherwise the argument is returned as given (the scene loader then says the file is missing).

#include <filesystem>
#include <string>
#include <vector>

namespace beamimpact {

/// @brief A shipped scene: its name (the file stem) and its file.
struct ShippedScene {
  std::string name;            ///< "s1_central"
  std::filesystem::path file;  ///< data_root()/verification/scenes/paper/s1_central.toml
};

/// @brief Every *.toml file under data_root()/verification/scenes, sorted by path (empty when
/// no data root is found).
std::vector<ShippedScene> shipped_scenes();

/// @brief The file a scene argument names, by the rule of this file. Throws InputError when a
/// name matches several shipped scenes.
/// @param arg a path or a shipped scene's name, as the user typed it
std::filesystem::path resolve_scene(const std::string& arg);

/// @brief A data file argument (a matrix): as given when it exists, else data_root()/arg when
/// that is a file (`verification/matrix.toml` from any folder), else as given.
/// @param arg a path, absolute or relative
std::filesystem::path resolve_data_file(const std::string& arg);

}  // namespace beamimpact
