#pragma once
/// @file JobSpec.hpp
/// @brief One run the verification suite needs (scene x method x settings) and how runs start:
/// in this process through beamimpact::run (the default), or each as a `beamimpact run` process
/// where isolation is asked for.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <api/run.hpp>

namespace beamimpact::jobs {

/// @brief What to run. Two specs with the same key() are the same run (run once, shared).
struct JobSpec {
  std::filesystem::path scene;   ///< scene file (absolute or relative to the working directory)
  std::string method = "paper";  ///< a registry name (api/registry.hpp)
  std::optional<double> dt;      ///< s, sets time.dt (methods that accept a dt)
  std::string mesh;              ///< element multiplier ("2"), or a method's named preset ("coarse")
  std::vector<std::string> set;  ///< extra --set key=value overrides

  /// @brief Scene name: the file stem ("s1_central").
  std::string scene_name() const;
  /// @brief Human label without the scene: "paper dt=0.005 mesh=2".
  std::string settings_label() const;
  /// @brief Scene and settings: "s1_central paper dt=0.005".
  std::string label() const { return scene_name() + " " + settings_label(); }
  /// @brief Unique, file-system-safe key ("s1_central.paper.dt0.005.mesh2").
  std::string key() const;
};

/// @brief How the runs start. By default each goes through beamimpact::run in this process,
/// which refuses (InputError) what the method does not accept and starts an external method's
/// program as its own process. With `exe`, each run is instead a `beamimpact run` process of
/// that program (isolation: a crash ends only that run), whose refusal comes back as a file.
struct Launcher {
  /// @brief The beamimpact executable of isolated runs; empty: every run in this process.
  std::filesystem::path exe;
  /// @brief Isolated runs: passed on as --methods FILE (in this process the registry already
  /// holds them).
  std::vector<std::filesystem::path> methods_files;
  /// @brief Take a run recorded as finished in its directory with the same input instead of
  /// running it again (finished_runs.hpp: resuming an interrupted verify).
  bool reuse_finished = false;
  /// @brief Threads of the runs of in-process methods (RunOptions::threads, --threads N of an
  /// isolated run; 0: each run takes its default).
  int threads = 0;

  /// @brief Whether the runs are processes of `exe` (isolated) rather than calls in this process.
  bool isolated() const { return !exe.empty(); }

  /// @brief Reason the spec cannot run here ("" when it can): a method not in the registry, or
  /// an external program's check failing (api/registry.hpp unavailable()).
  std::string unavailable(const JobSpec& spec) const;
  /// @brief Checks the spec before anything runs: InputError for a method not in the registry or
  /// a mesh that is no element multiplier 1..64 for a method that takes one.
  void check(const JobSpec& spec) const;
  /// @brief The argument vector of an isolated run writing to out_dir (refusal: the file
  /// kRefusalFile there). Throws InputError for a method not in the registry or a mesh that is
  /// no element multiplier 1..64 for a method that takes one.
  std::vector<std::string> argv(const JobSpec& spec, const std::filesystem::path& out_dir) const;
  /// @brief The options of the same run in this process, writing to out_dir.
  RunOptions run_options(const JobSpec& spec, const std::filesystem::path& out_dir) const;
};

/// @brief The launcher of a command's runs: in this process when exe is empty, else isolated as
/// processes of exe with the methods files this process loaded (each run sees the same registry).
/// @param exe the beamimpact program of isolated runs ("" none); @param threads Launcher::threads
Launcher launcher_for(const std::filesystem::path& exe, int threads);

/// @brief Where an isolated run writes its refusal (`beamimpact run --refusal FILE`): JSON
/// {"file", "key", "message"} of the InputError, in its run directory.
inline constexpr const char* kRefusalFile = "refusal.json";

/// @brief The --set overrides that multiply every body's element count of the scene by m.
std::vector<std::string> mesh_overrides(const std::filesystem::path& scene, int m);

}  // namespace beamimpact::jobs
