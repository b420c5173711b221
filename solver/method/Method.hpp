#pragma once
/// @file Method.hpp
/// @brief What a method is, as its registry entry (api/registry.hpp) holds it: its name, what it
/// accepts, its options table, its thread limit, its rank and converged settings as a reference,
/// and how it runs. Each method writes its own entry beside its code (the paper's in
/// solver/paper/method.cc, a reference's in references/NAME/method.cc, an external program's in
/// its methods file); everything else reads these fields and never compares a method's name.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <solver/record/SimulationResult.hpp>

namespace beamimpact {

/// @brief A method's standing as the reference of a scene (`beamimpact score`, its benchmark
/// card's reference). Higher is better: a scene's best reference is its highest-ranked method
/// that solves it (verification/cards.toml names it per scene).
enum class ReferenceRank {
  kNone = 0,       ///< not a scorecard reference
  kConverged = 1,  ///< a numerical solution, converged beyond its defaults by AsReference's settings
  kExact = 2,      ///< an exact answer (no discretisation error): a method is scored by a ladder's limit
};

/// @brief How a method serves as a reference (its registry facts; verification/matrix/scorecard.cc
/// reads them).
struct AsReference {
  ReferenceRank rank = ReferenceRank::kNone;
  /// Settings ("key=value") that converge it beyond its defaults, each added to a card's
  /// reference unless the card sets that key.
  std::vector<std::string> converged;
  /// Settings ("key=value") that stiffen it beyond the card's (a penalty), added unless the card
  /// sets one of stiffness_keys; the converged run without them is the reference's own
  /// uncertainty check.
  std::vector<std::string> stiffer;
  std::vector<std::string> stiffness_keys;  ///< keys by which a card sets its own stiffness
  std::string converged_words;              ///< the converged reference in words (scorecard page)
};

/// @brief One method: an in-process solver, or an external program that writes the same
/// run directory (history.csv, summary.json; docs/protocol.md).
struct Method {
  /// @brief What a method can take from a scene or a run request. api::run refuses (exit 2, "not
  /// applicable" in the suite) a run that asks for more (see refusal() in api/accepts.hpp).
  struct Accepts {
    bool dt = true;           ///< a time step asked for (--dt, time.dt / time.fraction overrides)
    bool mesh_factor = true;  ///< --mesh is an element multiplier (else a preset name of its own)
    /// Coulomb friction (a contact with friction > 0) at a contact where a body deforms, and
    /// between rigid bodies.
    bool friction = true;
    /// Coulomb friction at a contact of two rigid bodies only (all a method with friction = false
    /// and rigid_friction = true takes: the exact rigid-rod solution).
    bool rigid_friction = true;
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
  /// @brief The most threads its step takes (RunOptions::threads, `--threads`); 0: it runs on one
  /// and ignores the count. The largest over the registry bounds `--threads` (thread_limit()).
  int max_threads = 0;
  AsReference as_reference;
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

/// @brief One capability of Method::Accepts: its key (methods files' [accepts] table, `beamimpact
/// methods` with '-' for '_') and its field.
struct AcceptsKey {
  const char* key;
  bool Method::Accepts::*field;
};

/// @brief Every capability of Method::Accepts, in the order `beamimpact methods` lists them: the
/// one list of keys, so that no key can land in another's field.
inline const std::vector<AcceptsKey>& accepts_keys() {
  static const std::vector<AcceptsKey> keys = {
      {"dt", &Method::Accepts::dt},
      {"mesh_factor", &Method::Accepts::mesh_factor},
      {"friction", &Method::Accepts::friction},
      {"rigid_friction", &Method::Accepts::rigid_friction},
      {"rotation", &Method::Accepts::rotation},
      {"rigid", &Method::Accepts::rigid},
      {"search", &Method::Accepts::search},
      {"several_contacts", &Method::Accepts::several_contacts},
      {"timoshenko", &Method::Accepts::timoshenko},
      {"hertz", &Method::Accepts::hertz},
      {"bending", &Method::Accepts::bending},
      {"node_to_surface", &Method::Accepts::node_to_surface},
      {"loads", &Method::Accepts::loads},
  };
  return keys;
}

}  // namespace beamimpact
