#pragma once
/// @file JobSpec.hpp
/// @brief One run the verification suite needs: scene x method x settings, and how to launch it
/// as an independent process (`beamimpact run ...` or the FEniCSx script).

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
  std::vector<std::string> set;   ///< extra --set key=value overrides (methods that accept them)
  std::vector<std::string> args;  ///< extra arguments passed verbatim (external programs' options)

  /// @brief Scene name: the file stem ("s1_central").
  std::string scene_name() const;
  /// @brief Human label without the scene: "paper dt=0.005 mesh=2".
  std::string settings_label() const;
  /// @brief Scene and settings: "s1_central paper dt=0.005".
  std::string label() const { return scene_name() + " " + settings_label(); }
  /// @brief Unique, file-system-safe key ("s1_central.paper.dt0.005.mesh2").
  std::string key() const;
};

/// @brief How to start the methods of the registry: in-process methods as `beamimpact run`,
/// external programs by their registered command.
struct Launcher {
  std::filesystem::path exe;   ///< the beamimpact executable
  std::filesystem::path root;  ///< the source root: external commands' relative paths resolve here

  /// @brief Reason the spec cannot run here ("" when it can): a method not in the registry, or
  /// an external program's interpreter, script or check failing (checked once per method).
  std::string unavailable(const JobSpec& spec) const;
  /// @brief The argument vector writing the run to out_dir. Throws InputError for settings the
  /// method does not take (dt or --set for a method that picks its own, a mesh preset for a
  /// method that takes an element multiplier and the reverse).
  std::vector<std::string> argv(const JobSpec& spec, const std::filesystem::path& out_dir) const;

 private:
  std::vector<std::string> resolve(const std::vector<std::string>& command) const;
  mutable std::map<std::string, std::string> reasons_;  ///< external method -> why not ("" = ok)
};

/// @brief The source root for `start` (a scene or matrix path): the first folder upwards that
/// holds every relative path of every external method's command, else the working directory.
std::filesystem::path find_source_root(const std::filesystem::path& start);

/// @brief The --set overrides that multiply every body's element count of the scene by m.
std::vector<std::string> mesh_overrides(const std::filesystem::path& scene, int m);

}  // namespace beamimpact::verification
