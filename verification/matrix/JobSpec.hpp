#pragma once
/// @file JobSpec.hpp
/// @brief One run the verification suite needs: scene x method x settings, and how to launch it
/// as an independent process (`beamimpact run ...`, for in-process and external methods alike).

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace beamimpact::verification {

/// @brief What to run. Two specs with the same key() are the same run (run once, shared).
struct JobSpec {
  std::filesystem::path scene;    ///< scene file (absolute or relative to the working directory)
  std::string method = "paper";   ///< a registry name (api/registry.hpp)
  std::optional<double> dt;       ///< s, sets time.dt (methods that accept a dt)
  std::string mesh;               ///< element multiplier ("2"), or a method's named preset ("coarse")
  std::vector<std::string> set;   ///< extra --set key=value overrides
  std::vector<std::string> args;  ///< extra arguments of `beamimpact run`, passed verbatim

  /// @brief Scene name: the file stem ("s1_central").
  std::string scene_name() const;
  /// @brief Human label without the scene: "paper dt=0.005 mesh=2".
  std::string settings_label() const;
  /// @brief Scene and settings: "s1_central paper dt=0.005".
  std::string label() const { return scene_name() + " " + settings_label(); }
  /// @brief Unique, file-system-safe key ("s1_central.paper.dt0.005.mesh2").
  std::string key() const;
};

/// @brief How to start the methods of the registry: every run as `beamimpact run`, which
/// refuses (exit 2) what the method does not accept and starts an external method's program.
struct Launcher {
  std::filesystem::path exe;                         ///< the beamimpact executable
  std::vector<std::filesystem::path> methods_files;  ///< passed on as --methods FILE
  /// @brief Take a run recorded as finished in its directory with the same input instead of
  /// running it again (finished_runs.hpp: resuming an interrupted verify).
  bool reuse_finished = false;
  /// @brief Passed on as --threads N to the runs of in-process methods (0: not passed, each run
  /// takes its default).
  int threads = 0;

  /// @brief Reason the spec cannot run here ("" when it can): a method not in the registry, or
  /// an external program's check failing (api/registry.hpp unavailable()).
  std::string unavailable(const JobSpec& spec) const;
  /// @brief The argument vector writing the run to out_dir. Throws InputError for a method not
  /// in the registry or a mesh that is no element multiplier 1..64 for a method that takes one.
  std::vector<std::string> argv(const JobSpec& spec, const std::filesystem::path& out_dir) const;
};

/// @brief The --set overrides that multiply every body's element count of the scene by m.
std::vector<std::string> mesh_overrides(const std::filesystem::path& scene, int m);

}  // namespace beamimpact::verification
