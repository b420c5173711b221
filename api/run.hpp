#pragma once
/// @file run.hpp
/// @brief The one-call C++ API: load a scene, run it with a method from the registry, optionally
/// write its run directory. What `beamimpact run` does, for programs that link beamimpact.
///
/// @code
///   #include <beamimpact/api/run.hpp>   // installed (inside the repository: <api/run.hpp>)
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
  /// An external method needs one.
  std::optional<std::filesystem::path> out;
  /// @brief s, the time step asked for (as time.dt; refused by a method that picks its own).
  std::optional<double> dt = std::nullopt;
  /// @brief The mesh asked for: an element multiplier ("2") for a method with
  /// accepts.mesh_factor, else the method's own preset name ("coarse"); "" for the scene's.
  std::string mesh = {};
  /// @brief Threads of the paper integrator's step (as [paper] threads; >= 1): unset, the
  /// machine's hardware threads, 1 for a model below kThreadsMinDofs equations. The results
  /// are the same bits at any count; summary.json says how many were used ("threads").
  std::optional<int> threads = std::nullopt;
  /// @brief The heap policy (solver/util/heap_policy.hpp), process-wide: true keeps freed blocks in
  /// the process for the next run (glibc mallopt) and grows the heap by the run's estimated memory
  /// in huge pages before an in-process method's set-up. False (the default): the library leaves
  /// the process's allocator as it is. `beamimpact` turns it on for its runs; a program that
  /// embeds the library (the Python module) decides for itself. An external method ignores it.
  bool tune_heap = false;
};

/// @brief Runs a scene file with a method of the registry (in-process, or an external program
/// through its methods-file command). What the method does not accept is refused here, the one
/// place every run passes (api/accepts.hpp).
/// @param scene_file the scene (TOML, docs/scene-format.md)
/// @param method a registry name: "paper", "exact", "ida", or an external method's
/// @param options overrides, step, mesh and output directory
/// @return the result (of an external method: its summary's keys; the run directory holds the
/// rest); throws InputError for bad input or a run the method does not take (file, key,
/// expectation; the CLI's exit code 2) and std::runtime_error when the run fails (exit code 3).
/// With options.out, the run holds that directory's OutputLock from before it removes an earlier
/// run's outputs until it returns: a second writer is refused (InputError) and touches nothing.
SimulationResult run(const std::filesystem::path& scene_file, std::string_view method,
                     const RunOptions& options = {});

/// @brief Runs a scene already loaded (options.set, dt and mesh must be empty: overrides are
/// applied by load_scene(); options.threads is taken).
SimulationResult run(const Scene& scene, std::string_view method, const RunOptions& options = {});

}  // namespace beamimpact
