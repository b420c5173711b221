#pragma once
/// @file output_files.hpp
/// @brief Writes one run's history.csv and summary.json (columns and keys of docs/scene-format.md).

#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include <solver/record/SimulationResult.hpp>

namespace beamimpact {

/// @brief One history.csv row as numbers, in the order of history_columns() (state as its code).
std::vector<double> history_values(const HistoryRow& row);

/// @brief The summary.json document of a run (scene identity, settings, defaults, results).
nlohmann::json summary_json(const Scene& scene, const SimulationResult& result);

/// @brief Throws std::runtime_error naming the first non-finite summary value or history cell
/// (column and time) of a result: a run that diverged has no outputs, on disk or in memory.
void check_outputs_finite(const Scene& scene, const SimulationResult& result);

/// @brief Writes dir/history.csv (not with [output] history = false) then dir/summary.json. summary.json is
/// written last and atomically: its presence marks a complete run. A stale summary.json in dir is removed
/// first. Throws std::runtime_error if the result holds a non-finite number (nothing complete is left).
void write_outputs(const Scene& scene, const SimulationResult& result, const std::filesystem::path& dir);

}  // namespace beamimpact
