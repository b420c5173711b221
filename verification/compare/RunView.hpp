#pragma once
/// @file RunView.hpp
/// @brief One run as compare_runs() and check_run() read it: the history's columns and the summary's numbers
/// it needs as typed fields, built once from a run in memory (from_result) or from a run directory
/// (StoredRun::view(), the files read and checked there).

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <solver/record/SimulationResult.hpp>
#include <solver/scene/Scene.hpp>

namespace beamimpact::verification {

/// @brief History columns by name ("t", "R", "ua_x", "R_2", ...).
using Columns = std::map<std::string, std::vector<double>>;

/// @brief What a run's summary says of one contact (summary.json contacts[k]); a field is empty
/// when the summary does not give it.
struct ContactFacts {
  std::optional<double> impulse_normal;                         ///< N s, the method's own total
  std::optional<std::vector<std::array<double, 2>>> intervals;  ///< s, [start, end] of each interval
  /// N s, the impulse of each interval; empty unless the summary lists a number for each.
  std::optional<std::vector<double>> interval_impulses;
  std::optional<double> friction;      ///< Coulomb mu of the contact
  std::optional<double> real_gap_min;  ///< m, the smallest real gap (negative: penetration)
  /// @brief Equal fields.
  bool operator==(const ContactFacts&) const = default;
};

/// @brief A run's columns and summary numbers. The columns may be shared with the StoredRun that
/// made the view: keep it alive while the view is used.
struct RunView {
  std::string label;                           ///< where it came from (the run directory), for messages
  std::shared_ptr<const Columns> columns;      ///< `t` (strictly increasing) and the others
  std::vector<ContactFacts> contacts_summary;  ///< summary.json contacts[], in order
  /// summary.json bodies.NAME.final_velocity (m/s) by body name (an entry empty when the body has
  /// none); empty when the summary has no bodies.
  std::optional<std::map<std::string, std::optional<std::array<double, 2>>>> final_velocity;
  std::string scene_sha256;                  ///< the summary's scene_sha256 ("" when it has none)
  std::optional<double> energy_initial;      ///< J, the initial conditions' energy
  std::optional<double> momentum_drift_max;  ///< N s, the largest change of the total momentum

  /// @brief The run a method returned, with the numbers write_outputs() would write (the files
  /// round-trip every double). Throws std::runtime_error for a non-finite value and InputError
  /// for a result without rows ([output] history = false).
  /// @param scene the scene the run solved; @param result its result; @param label for messages
  static RunView from_result(const Scene& scene, const SimulationResult& result, std::string label);

  /// @brief The summary's numbers of a summary.json object (the types checked: InputError naming
  /// `file` and the key for a wrong one).
  /// @param summary the parsed summary.json; @param file what messages name
  /// @param view receives contacts_summary, final_velocity and scene_sha256
  static void read_summary(const nlohmann::json& summary, const std::string& file, RunView& view);

  /// @brief Times of the rows (s).
  const std::vector<double>& t() const { return columns->at("t"); }
  /// @brief True when the column exists.
  /// @param name the column
  bool has(const std::string& name) const { return columns->count(name) > 0; }
  /// @brief The column; throws InputError naming label/history.csv and the column when absent.
  /// @param name the column
  const std::vector<double>& column(const std::string& name) const;
  /// @brief Number of contacts: 1 + the number of `R_k` columns (k = 2, 3, ...).
  int contacts() const { return contact_count(*columns); }
  /// @brief Median spacing of the rows (s): the output step.
  double output_step() const { return median_step(t()); }

  /// @brief 1 + the number of `R_k` columns when there is an `R` column, else 0.
  /// @param columns the history's columns
  static int contact_count(const Columns& columns);
  /// @brief Median spacing of increasing times (s), 0 for fewer than two.
  /// @param t the times
  static double median_step(const std::vector<double>& t);
};

}  // namespace beamimpact::verification
