#pragma once
/// @file Scene.hpp
/// @brief A collision scene as read from TOML (see docs/scene-format.md): plain data, SI units.

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace beamimpact {

/// @brief A 2D point or vector (m, m/s, ...).
using Vec2 = std::array<double, 2>;

/// @brief Time stepping: [time] table.
struct TimeSettings {
  std::optional<double> dt;           ///< s; empty means "auto" (fraction x critical step)
  double fraction = 0.5;              ///< of the critical step, used when dt is "auto"
  double end = 0.0;                   ///< s, end time
  int output_every = 1;               ///< write every n-th step to history.csv
  bool allow_above_critical = false;  ///< accept dt above the stability limit
  bool allow_long_run = false;        ///< accept a run beyond the ordinary cost (run_cost.hpp)
};

/// @brief How the field files store their numbers: VTK's appended raw binary (little-endian,
/// UInt64 block headers; the default: compact and fast) or ASCII text (shortest round-trip
/// decimals). Both read back bit for bit.
enum class FieldFormat { kBinary, kAscii };

/// @brief Precision of the real numbers in the field files: single (Float32, the default: half
/// the bytes of double, and what a viewer draws with; each value the double rounded to nearest)
/// or double (Float64: the solver's numbers bit for bit). Node indices are Int32 either way.
enum class FieldPrecision { kSingle, kDouble };

/// @brief What a run writes besides summary.json: [output] table.
struct OutputSettings {
  /// history.csv rows kept and written (false: only the first and last rows' energies reach the
  /// summary; memory no longer grows with the number of steps).
  bool history = true;
  /// VTK XML fields (one .vtu per output row and a .pvd collection) in the run directory's
  /// fields/ folder, for ParaView (record/FieldWriter.hpp).
  bool fields = false;
  /// Encoding of the field files (output.field_format = "binary" | "ascii").
  FieldFormat field_format = FieldFormat::kBinary;
  /// Precision of their real numbers (output.field_precision = "single" | "double").
  FieldPrecision field_precision = FieldPrecision::kSingle;
};

/// @brief Mass lumping choice for the element mass matrix.
enum class MassKind { kLumped, kConsistent };
/// @brief Lumped rotary inertia: HRZ (m le^2/78) or section (rho I le/2).
enum class RotaryInertia { kHrz, kSection };
/// @brief Linear (fixed global matrices) or corotational (element frames rebuilt every step).
enum class Kinematics { kLinear, kCorotational };
/// @brief Beam theory of a body's elements: Euler-Bernoulli (the paper's) or Timoshenko (shear
/// deformation and rotary inertia).
enum class BeamTheory { kEulerBernoulli, kTimoshenko };

/// @brief The string form of a model choice, as written in scene files and summary.json
/// ("lumped", "consistent", "hrz", "section", "linear", "corotational").
const char* to_string(MassKind m);
const char* to_string(RotaryInertia r);
const char* to_string(Kinematics k);
const char* to_string(FieldFormat f);
const char* to_string(FieldPrecision p);
/// @brief "euler-bernoulli" | "timoshenko".
const char* to_string(BeamTheory t);

/// @brief Model choices: [model] table.
struct ModelSettings {
  MassKind mass = MassKind::kLumped;
  RotaryInertia rotary_inertia = RotaryInertia::kHrz;
  Kinematics kinematics = Kinematics::kLinear;
  double rayleigh_mass = 0.0;       ///< 1/s, C = rayleigh_mass M + rayleigh_stiffness K
  double rayleigh_stiffness = 0.0;  ///< s
};

/// @brief A support at one node of a body: the listed displacement components are held at zero,
/// in global axes (x, y, theta) or in the body's own axes (axial: along start -> end; normal: the
/// axial direction turned +90 degrees, counter-clockwise). support_axes.hpp combines them.
struct Support {
  int node = 0;  ///< node index in the body (0 = start)
  bool fix_x = false, fix_y = false, fix_theta = false;
  bool fix_axial = false, fix_normal = false;
};

/// @brief One straight beam, uniformly meshed from start to end.
struct Body {
  std::string name;
  Vec2 start{}, end{};  ///< m, first and last node
  int elements = 1;
  double E = 0.0;        ///< N/m^2
  double rho = 0.0;      ///< kg/m^3
  double area = 0.0;     ///< m^2
  double inertia = 0.0;  ///< m^4 (0 when not given: only valid for axial scenes)
  Vec2 velocity{};       ///< m/s, initial rigid velocity
  std::vector<Support> supports;
  /// rigid = true: the body moves as a rigid body (x, y and rotation of its centre; mass
  /// rho A L, inertia m L^2 / 12; small rotations). `elements` only places its nodes; no
  /// supports (free) or one fixing x, y and theta (immovable).
  bool rigid = false;
  /// Beam theory of the elements (bending layout only); a Timoshenko body's shear modulus is
  /// G = E / (2 (1 + poisson)) and its shear area shear_coefficient x area.
  BeamTheory theory = BeamTheory::kEulerBernoulli;
  double shear_coefficient = 5.0 / 6.0;  ///< kappa (-), 5/6: a rectangular section
  double poisson = 0.3;                  ///< nu (-)

  /// @brief Length (m).
  double length() const;
  /// @brief Unit vector from start to end (the body's axial direction).
  Vec2 axis() const;
  /// @brief The axial direction turned +90 degrees (counter-clockwise): the body's normal.
  Vec2 normal() const;
  /// @brief Number of nodes (elements + 1).
  int nodes() const { return elements + 1; }
  /// @brief Reference position of node i (m).
  Vec2 node_position(int i) const;
};

/// @brief Contact law: "hard" (the paper's displacement compatibility, g = 0 while closed) or
/// "hertz" (a local Hertz spring between the bodies, R = k delta^(3/2) with delta = -g).
enum class ContactLaw { kHard, kHertz };
/// @brief "hard" | "hertz".
const char* to_string(ContactLaw l);

/// @brief One contact pair: a node of the striker against the surface (or end) of the target.
struct Contact {
  int striker = 0;        ///< index into Scene::bodies
  int node = 0;           ///< striker node index (resolved from "start"/"end"/index)
  int target = 0;         ///< index into Scene::bodies
  double friction = 0.0;  ///< Coulomb mu
  /// node = "all" (contact search): every striker node is checked against the target's surface
  /// and the target's end nodes against the striker's; `node` is then the striker node nearest
  /// the target at t = 0 (the one whose motion the history reports while nothing touches).
  bool search = false;
  ContactLaw law = ContactLaw::kHard;
  double hertz_stiffness = 0.0;  ///< N/m^1.5, k of the Hertz law (0 for the hard law)
};

/// @brief A constant force (N, global axes) on one node of a body, for the whole run.
struct PointLoad {
  int body = 0;  ///< index into Scene::bodies
  int node = 0;  ///< node index in the body
  Vec2 force{};  ///< N
};

/// @brief External loads: the optional [loads] table (F^P of the paper's Eq. 3). Constant in
/// time; a scene without them builds no load vector and its step loop does no load work.
struct Loads {
  Vec2 gravity{};                ///< m/s^2, acceleration of gravity on every body's mass
  std::vector<PointLoad> point;  ///< [[loads.point]] entries

  /// @brief True when some load is not zero.
  bool any() const { return gravity[0] != 0.0 || gravity[1] != 0.0 || !point.empty(); }
};

/// @brief Forced effects from the optional [effects] table (empty = derived from the scene).
struct EffectOverrides {
  std::optional<bool> bending, friction, damping;
};

/// @brief A whole scene, validated. Method-specific tables ([ida], [exact], ...) are kept as
/// parsed TOML tables so that each method validates its own keys (see TableReader).
struct Scene {
  std::string file;    ///< path it was read from
  std::string sha256;  ///< of the file's bytes (before --set overrides)
  std::string name, description;
  TimeSettings time;
  ModelSettings model;
  OutputSettings output;
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
  Loads loads;
  EffectOverrides effects;
  /// @brief Keys the file did not give, with the default used ("model.mass" -> "lumped").
  std::map<std::string, std::string> assumed;
  /// @brief --set overrides applied, as given ("time.dt" -> "0.005").
  std::map<std::string, std::string> overrides;
  /// @brief Legal input that is likely not what was meant, one sentence each naming the file and
  /// the key (a run lists them in summary.json "warnings" and on stderr).
  std::vector<std::string> warnings;
  /// @brief Method tables ("ida", "exact", "paper", "fenicsx") as the file gives them (with the
  /// overrides applied), unread: each method reads its own (MethodOptions).
  std::map<std::string, toml::table> method_tables;

  /// @brief Index of the body with this name, or -1.
  int body_index(const std::string& name) const;
};

}  // namespace beamimpact
