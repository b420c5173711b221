#pragma once
/// @file RunSpec.hpp
/// @brief One run the verification suite needs: scene x method x settings, and how to launch it
/// as an independent process (`beamimpact run ...` or the FEniCSx script).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace beamimpact {

/// @brief What to run. Two specs with the same key() are the same run (run once, shared).
struct RunSpec {
  std::filesystem::path scene;      ///< scene file (absolute or relative to the working directory)
  std::string method = "paper";     ///< paper | exact | ida | fenicsx
  std::optional<double> dt;         ///< s, sets time.dt (beam methods)
  std::string mesh;                 ///< beam methods: element multiplier ("2"); fenicsx: preset ("coarse")
  std::vector<std::string> set;     ///< extra --set key=value overrides (beam methods)
  std::vector<std::string> args;    ///< extra arguments passed verbatim (fenicsx options)

  /// @brief Scene name: the file stem ("s1_central").
  std::string scene_name() const;
  /// @brief Human label without the scene: "paper dt=0.005 mesh=2".
  std::string settings_label() const;
  /// @brief Scene and settings: "s1_central paper dt=0.005".
  std::string label() const { return scene_name() + " " + settings_label(); }
  /// @brief Unique, file-system-safe key ("s1_central.paper.dt0.005.mesh2").
  std::string key() const;
};

/// @brief How to start the methods.
struct Launcher {
  std::filesystem::path exe;                 ///< the beamimpact executable
  std::vector<std::string> fenicsx;          ///< command prefix, e.g. {"/usr/bin/python3", ".../run.py"}
  std::vector<std::string> builtin_methods;  ///< methods the executable has ("paper", "exact", ...)

  /// @brief Reason the spec cannot run here ("" when it can): a method not built in, or the
  /// FEniCSx interpreter, script or dolfinx missing (checked once per launcher).
  std::string unavailable(const RunSpec& spec) const;
  /// @brief The argument vector writing the run to out_dir. Throws SceneError for settings the
  /// method does not take (dt or --set for fenicsx, a non-integer mesh for beam methods).
  std::vector<std::string> argv(const RunSpec& spec, const std::filesystem::path& out_dir) const;

 private:
  mutable std::optional<std::string> fenicsx_reason_;
};

/// @brief The --set overrides that multiply every body's element count of the scene by m.
std::vector<std::string> mesh_overrides(const std::filesystem::path& scene, int m);

}  // namespace beamimpact
