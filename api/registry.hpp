#pragma once
/// @file registry.hpp
/// @brief The method registry: every method beamimpact can run, by name, in one table (in the
/// style of Ceres' LinearSolver::Create). The CLI, verify, sweep, study and the C++ API reach
/// methods only through it. In-process methods are compiled in (registry.cc); external programs
/// are declared in methods files (TOML, api/methods_file.hpp, docs/protocol.md) with no C++ edit.

#include <deque>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <solver/record/SimulationResult.hpp>

namespace beamimpact {

/// @brief One method: an in-process solver, or an external program that writes the same
/// run directory (history.csv, summary.json; docs/protocol.md).
struct Method {
  /// @brief What a method can take from a scene or a run request. api::run refuses (exit 2, "not
  /// applicable" in the suite) a run that asks for more (see refusal() in api/accepts.hpp).
  struct Accepts {
    bool dt = true;                ///< a time step asked for (--dt, time.dt / time.fraction overrides)
    bool mesh_factor = true;       ///< --mesh is an element multiplier (else a preset name of its own)
    bool friction = true;          ///< Coulomb friction (a contact with friction > 0)
    bool rotation = true;          ///< large rotation (model.kinematics = "corotational")
    bool rigid = true;             ///< rigid bodies (rigid = true)
    bool search = true;            ///< contact search (node = "all")
    bool several_contacts = true;  ///< more than one [[contacts]] table
    bool timoshenko = true;        ///< Timoshenko beams (a body with theory = "timoshenko")
    bool hertz = true;             ///< the Hertz contact law (a contact with law = "hertz")
    /// Bending: the scene is built of frame elements (derive_effects().bending: its bodies are
    /// not all on one line, or [effects] bending = true). False: rods only (axial motion).
    bool bending = true;
    /// A contact whose striker node meets the target's surface inside an element (between two
    /// nodes), as ContactKind::kNodeToSurface; end-to-end and node-to-node contacts need no more.
    bool node_to_surface = true;
    bool loads = true;  ///< gravity or point loads ([loads] with a non-zero entry)
  };

  /// @brief What a run passes to an in-process solver besides the scene.
  struct Request {
    /// @brief The run directory that receives VTK fields ([output] fields = true); empty: none.
    std::filesystem::path fields_dir;
    /// @brief RunOptions::threads (`--threads`), 0 when not asked; a solver without threads ignores it.
    int threads = 0;
  };

  std::string name;           ///< registry key and `--method` value
  std::string summary;        ///< one line for `beamimpact methods`
  std::string origin;         ///< "built-in" or the methods file that declared it
  std::string options_table;  ///< the scene table holding its options ("paper"), "" for none
  Accepts accepts;
  bool slow = false;  ///< typically seconds or more per run: scheduled first, never timed in tests
  /// @brief In-process solver; empty for an external program.
  std::function<SimulationResult(const Scene&, const Request&)> solve;
  /// @brief Whether the in-process solver writes VTK fields ([output] fields = true) into
  /// Request::fields_dir.
  bool writes_fields = false;
  /// @brief External program: its argument list with placeholders ({scene}, {out}, {dt},
  /// {mesh}, {end}); {here} and {beamimpact} are already expanded.
  std::vector<std::string> command;
  /// @brief External program: a command (same expansion) that exits 0 when it can run here.
  std::vector<std::string> check;
  /// @brief s, the check's time limit (methods file `check_timeout`, > 0 and at most 3600): a
  /// check still running then is ended with its process group and the method is unavailable.
  double check_timeout = 10.0;

  /// @brief True for an in-process solver.
  bool in_process() const { return static_cast<bool>(solve); }
};

/// @brief Every method: the built-in ones (paper first), then those of the methods files in the
/// order read. The first call reads the default methods files (methods_file.hpp); a bad file
/// throws InputError naming it and the key.
const std::deque<Method>& methods();

/// @brief Adds a method declared in a methods file. Throws InputError(file, key) when its name is
/// already taken.
/// @param m the method; @param file the methods file, for messages; @param key its table's key
void add_method(Method m, const std::string& file, const std::string& key);

/// @brief The method with this name, or nullptr.
const Method* find_method(std::string_view name);

/// @brief The method with this name. Throws InputError naming `file` and `key` and listing the
/// known names when there is none.
const Method& method(std::string_view name, const std::string& file, const std::string& key);

/// @brief "paper, exact, ida, ...": the names, for messages and help texts.
std::string method_names();

/// @brief Why the method cannot run on this machine ("" when it can): an external program's
/// check command failing or missing (run once per method and remembered).
std::string unavailable(const Method& m);

}  // namespace beamimpact
