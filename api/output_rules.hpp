#pragma once
/// @file output_rules.hpp
/// @brief The one set of rules an external method's run directory must keep (docs/protocol.md,
/// "Output rules"): files present, `complete: true`, every value finite, times strictly
/// increasing, the summary's required keys, its units in values, the scene's sha256, and
/// summary.json consistent with history.csv within the rows' own resolution. `beamimpact run
/// --method NAME` (run_external) and `beamimpact conform` call check_outputs(); nothing else
/// states these rules.

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace beamimpact {

/// @brief One rule's verdict on one file of a run directory.
struct OutputVerdict {
  std::string rule;     ///< the rule's name (output_rules())
  std::string file;     ///< the file it is about (history.csv, summary.json, or the directory)
  bool passed = false;  ///< true when the rule holds
  std::string message;  ///< what was found and what was expected (empty when passed)
};

/// @brief What the rules compare a run with: the scene it was given.
struct OutputExpectation {
  std::filesystem::path scene_file;  ///< the scene file the program read ({scene}): its sha256
  std::size_t contacts = 0;          ///< the scene's [[contacts]]: one summary entry and R column each
  double end_time = 0.0;             ///< s, the scene's time.end
};

/// @brief The rules, in the order checked, with one line each: outputs, complete, finite, times,
/// summary keys, units, scene sha256, consistency.
const std::vector<std::pair<std::string, std::string>>& output_rules();

/// @brief history.csv as numbers: the header's names and one column per name (a cell that is
/// not a number reads as NaN, and `finite` names it).
struct HistoryTable {
  std::vector<std::string> names;
  std::map<std::string, std::vector<double>> columns;
  std::string problem;  ///< the first cell that is not a finite number ("" when none)
};

/// @brief Reads a history.csv (header, comma-separated rows). Throws std::runtime_error when the
/// file cannot be read or a row has the wrong number of cells.
HistoryTable read_history_table(const std::filesystem::path& csv);

/// @brief Checks every output rule on the run directory `dir`; a rule whose input is missing
/// (no file, an unreadable summary) is reported once and the rules after it that need it are
/// not checked.
/// @param dir the run directory; @param expected the scene it ran
std::vector<OutputVerdict> check_outputs(const std::filesystem::path& dir, const OutputExpectation& expected);

/// @brief The first broken rule of check_outputs() as one line ("rule 'consistency': file:
/// ..."), or "" when every rule holds.
std::string first_broken_rule(const std::vector<OutputVerdict>& verdicts);

}  // namespace beamimpact
