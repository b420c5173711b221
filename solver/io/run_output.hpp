#pragma once
/// @file run_output.hpp
/// @brief Writes one run's history.csv and summary.json (columns and keys of interface.md).

#include <filesystem>

#include <nlohmann/json.hpp>

#include "io/RunResult.hpp"

namespace beamimpact {

/// @brief The summary.json document of a run (scene identity, settings, defaults, results).
nlohmann::json summary_json(const Scene& scene, const RunResult& result);

/// @brief Writes dir/history.csv then dir/summary.json. summary.json is written last and
/// atomically: its presence marks a complete run. A stale summary.json in dir is removed first.
/// Throws std::runtime_error if the result holds a non-finite number (nothing complete is left).
void write_run(const Scene& scene, const RunResult& result, const std::filesystem::path& dir);

/// @brief Column names of history.csv for a scene with n contacts.
std::vector<std::string> history_columns(int n_contacts);

}  // namespace beamimpact
