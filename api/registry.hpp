#pragma once
/// @file registry.hpp
/// @brief The method registry: every method beamimpact can run, by name, in one table (in the
/// style of Ceres' LinearSolver::Create). The CLI, verify, sweep and the C++ API reach methods
/// only through it. Adding a method touches this table (registry.cc) and the method's own folder.

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <solver/record/SimulationResult.hpp>

namespace beamimpact {

/// @brief One method: an in-process solver, or an external program that writes the same
/// run directory (history.csv, summary.json).
struct Method {
  /// @brief What a method can take from a scene or a study.
  struct Accepts {
    bool dt = true;           ///< a time step (time.dt / --dt); false: the method picks its own
    bool overrides = true;    ///< --set KEY=VALUE scene overrides
    bool mesh_factor = true;  ///< mesh refinement as an element multiplier (else a named preset)
    bool friction = true;     ///< Coulomb friction
    bool rotation = true;     ///< large rotation (corotational kinematics)
  };

  std::string name;           ///< registry key and `--method` value
  std::string summary;        ///< one line for `beamimpact methods`
  std::string options_table;  ///< the scene table holding its options ("paper"), "" for none
  Accepts accepts;
  bool slow = false;  ///< typically seconds or more per run: scheduled first, never timed in tests
  /// @brief In-process solver; empty for an external program.
  std::function<SimulationResult(const Scene&)> solve;
  /// @brief In-process solver that also writes VTK fields ([output] fields = true) into the run
  /// directory given; empty for a method without field output.
  std::function<SimulationResult(const Scene&, const std::filesystem::path&)> solve_with_fields;
  /// @brief External program: argv prefix, paths relative to the source root (or the installed
  /// share/beamimpact); it is run as PREFIX SCENE --out DIR --quiet [ARGS].
  std::vector<std::string> command;
  /// @brief External program: a command (same rules) that exits 0 when the method can run here.
  std::vector<std::string> check;
  /// @brief External program: the option taking a named mesh preset, and an output step (s).
  std::string mesh_option, output_step_option;

  /// @brief True for an in-process solver.
  bool in_process() const { return static_cast<bool>(solve); }
};

/// @brief Every method of this build, in a fixed order (paper first).
const std::vector<Method>& methods();

/// @brief The method with this name, or nullptr.
const Method* find_method(std::string_view name);

/// @brief The method with this name. Throws SceneError naming `file` and `key` and listing the
/// known names when there is none.
const Method& method(std::string_view name, const std::string& file, const std::string& key);

/// @brief "paper, exact, ida, fenicsx": the names, for messages and help texts.
std::string method_names();

}  // namespace beamimpact
