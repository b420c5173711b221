#pragma once
/// @file output_schema.hpp
/// @brief The one owner of the output schema of a run directory (docs/scene-format.md):
/// the history.csv column names, the per-contact suffix rule, and the string (or integer) form
/// of every enum that reaches an output. The writer (record/output_files), the reader
/// (verification/compare/StoredRun), every method and the FEniCSx script follow it; the
/// `beamimpact schema` command prints it as JSON so that programs in other languages can check
/// themselves against it.

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace beamimpact {

/// @brief Contact state of one step (history column `state`: 0 open, 1 stick, 2 slip,
/// 3 closed without friction).
enum class ContactState { kOpen = 0, kStick = 1, kSlip = 2, kClosed = 3 };

/// @brief "open" | "stick" | "slip" | "closed" (the meaning of the integer in column `state`).
const char* to_string(ContactState s);

/// @brief Kind of a contact, found at t = 0 from the scene's geometry.
enum class ContactKind {
  kEndToEnd,       ///< collinear bodies, the striker node against the target's end node
  kNodeToNode,     ///< the striker node faces a node of the target's surface
  kNodeToSurface,  ///< the striker node faces a point inside a target element
};

/// @brief "end_to_end" | "node_to_node" | "node_to_surface" (summary.json `contacts[].kind`).
const char* to_string(ContactKind k);

/// @brief The per-contact columns of history.csv, in file order, without suffix.
const std::vector<std::string>& contact_columns();

/// @brief The whole-model columns of history.csv after the contact columns, in file order.
const std::vector<std::string>& model_columns();

/// @brief Column name of contact k (1-based): `base` for k = 1, `base_k` for k >= 2
/// ("R", "R_2", "vb_y_3").
std::string contact_column(std::string_view base, int k);

/// @brief Every column of history.csv for n_contacts contacts: t, the contact columns of each
/// contact (suffixed by contact_column), then the model columns.
std::vector<std::string> history_columns(int n_contacts);

/// @brief The keys every method's summary.json has at its top level (methods add their own:
/// "critical_step", "ida", "exact", "fenicsx", ...).
const std::vector<std::string>& summary_keys();

/// @brief summary.json's "units" object: the unit of each quantity family (t: s, R: N, u: m,
/// v: m/s, energy: J, momentum and impulse: N s); every method writes it as given here.
const nlohmann::json& summary_units();

/// @brief Keys of summary.json's "critical_step" object (methods that step explicitly).
namespace critical_step_key {
inline constexpr const char* kMethod = "method";                    ///< how omega_max was estimated
inline constexpr const char* kBound = "bound";                      ///< "element" | "subdomain" | "none"
inline constexpr const char* kOmegaMax = "omega_max";               ///< rad/s, the proven upper bound used
inline constexpr const char* kElementBoundDt = "element_bound_dt";  ///< s, the proven step
inline constexpr const char* kOmegaLower = "omega_lower";  ///< rad/s, a proven lower bound of omega_max
inline constexpr const char* kMargin =
    "margin";  ///< omega_max / omega_lower - 1: dt at most this far below the limit
inline constexpr const char* kDtOverCritical = "dt_over_critical";
}  // namespace critical_step_key

/// @brief Every key of summary.json's "critical_step" object, in file order.
const std::vector<std::string>& critical_step_keys();

/// @brief The keys every entry of summary.json's "contacts" array has.
const std::vector<std::string>& contact_summary_keys();

/// @brief The schema as JSON: columns, suffix rule, units and enum forms (`beamimpact schema`).
nlohmann::json schema_json();

}  // namespace beamimpact
