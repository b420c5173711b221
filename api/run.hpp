#pragma once
/// @file run.hpp
/// @brief The one-call C++ API: load a scene, run it with a method from the registry, optionally
/// write its run directory. What `beamimpact run` does, for programs that link beamimpact.
///
/// @code
///   #include <api/run.hpp>
///   const beamimpact::SimulationResult r = beamimpact::run("s1_central.toml", "paper");
///   std::printf("impulse %g N s\n", r.contacts[0].impulse_normal);
/// @endcode

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <solver/record/SimulationResult.hpp>

namespace beamimpact {

/// @brief What a run takes besides the scene and the method.
struct RunOptions {
  /// @brief Scene overrides as on the command line ("time.dt=0.005", "bodies.B.elements=20").
  std::vector<std::string> set;
  /// @brief When given, history.csv and summary.json are written into this directory (a stale
  /// summary.json there is removed before the run starts, so that it never vouches for it).
  std::optional<std::filesystem::path> out;
};

/// @brief Runs a scene file with an in-process method of the registry.
/// @param scene_file the scene (TOML, shared/spec/interface.md)
/// @param method a registry name: "paper", "exact", "ida"
/// @param options overrides and output directory
/// @return the result; throws SceneError for bad input (file, key, expectation; the CLI's exit
/// code 2) and std::runtime_error when the run fails (exit code 3).
SimulationResult run(const std::filesystem::path& scene_file, std::string_view method,
                     const RunOptions& options = {});

/// @brief Runs a scene already loaded (options.set must be empty: overrides are applied by
/// load_scene()).
SimulationResult run(const Scene& scene, std::string_view method, const RunOptions& options = {});

}  // namespace beamimpact
