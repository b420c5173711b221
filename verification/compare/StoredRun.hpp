#pragma once
/// @file StoredRun.hpp
/// @brief One finished run as the comparison layer sees it: the columns of history.csv and the
/// parsed summary.json (docs/scene-format.md); view() is what compare_runs() reads of them.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <verification/compare/RunView.hpp>

namespace beamimpact::verification {

/// @brief The history of one run, column by column, plus its summary.
///
/// Only `t` and the first contact's `R` are required; every other column is optional here and a
/// norm that needs a missing column reports itself unavailable with the reason (see compare_runs).
class StoredRun {
 public:
  /// @brief Reads dir/history.csv and dir/summary.json. Throws InputError (file, column, what was
  /// expected) for a missing file, a missing `t` or `R` column, a short row, a non-number, a
  /// non-finite value or times that do not increase.
  static StoredRun read(const std::filesystem::path& dir);

  /// @brief Builds a history from columns in memory (tests, perturbations); `t` must be present.
  static StoredRun from_columns(std::map<std::string, std::vector<double>> columns,
                                nlohmann::json summary = nlohmann::json::object(),
                                std::string label = "memory");

  /// @brief Times of the rows (s), strictly increasing.
  const std::vector<double>& t() const { return columns_.at("t"); }
  /// @brief True when the column exists.
  bool has(const std::string& name) const { return columns_.count(name) > 0; }
  /// @brief The column; throws InputError naming the file and the column when it is absent.
  const std::vector<double>& column(const std::string& name) const;
  /// @brief All columns by name.
  const std::map<std::string, std::vector<double>>& columns() const { return columns_; }
  /// @brief Mutable columns, for building perturbed copies in tests.
  std::map<std::string, std::vector<double>>& columns() { return columns_; }
  /// @brief Number of contacts: 1 + the number of `R_k` columns (k = 2, 3, ...).
  int contacts() const;
  /// @brief summary.json (empty object when built in memory without one).
  const nlohmann::json& summary() const { return summary_; }
  /// @brief Where it came from (the run directory), for messages.
  const std::string& label() const { return label_; }
  /// @brief Median spacing of the rows (s): the output step.
  double output_step() const;
  /// @brief The run as compare_runs() reads it: the summary's numbers typed once, the columns
  /// shared with this run (keep it alive while the view is used).
  RunView view() const;

 private:
  std::map<std::string, std::vector<double>> columns_;
  nlohmann::json summary_ = nlohmann::json::object();
  std::string label_;
};

}  // namespace beamimpact::verification
