#pragma once
/// @file test_scenes.hpp
/// @brief Test helper: loads one of the paper's scenes (verification/scenes/paper) with --set
/// style overrides, from the source tree named by BEAMIMPACT_SOURCE_DIR.

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene_io.hpp"

namespace beamimpact::testing {

/// @brief The scene `name` (without .toml) with overrides such as "time.end=1.5".
inline Scene paper_scene(const std::string& name, const std::vector<std::string>& overrides = {}) {
  const char* src = std::getenv("BEAMIMPACT_SOURCE_DIR");
  const std::filesystem::path root = src ? src : BEAMIMPACT_SOURCE_DIR_FALLBACK;
  return load_scene(root / "verification/scenes/paper" / (name + ".toml"), overrides);
}

}  // namespace beamimpact::testing
