#pragma once
/// @file finished_points.hpp
/// @brief Resuming an interrupted study with the same command: rank 0 records each finished
/// point in OUT/points/INDEX.json (atomically, after its result arrived) with the input it was
/// made from; a restart takes the points whose record names the same input and runs the rest
/// (verification/matrix/finished_runs.hpp: the same rule for verify's runs).

#include <cstddef>
#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include <verification/study/Study.hpp>
#include <verification/study/run_point.hpp>

namespace beamimpact::study {

/// @brief What every point of a study depends on: the program (version, methods files), the
/// study file's and the scene file's SHA-256, and keep_runs (a reused point's runs are kept
/// only if they were).
/// @param s the study
nlohmann::json study_input(const Study& s);

/// @brief Records point `index` (its values p, its result r) as finished in out/points/.
/// Throws std::runtime_error when the record cannot be written.
/// @param base study_input() of the study
void record_point(const std::filesystem::path& out, const nlohmann::json& base, std::size_t index,
                  const Point& p, const PointResult& r);

/// @brief The result of point `index` recorded in out/points/ with the same input (its rank
/// included); nullopt when there is none or it cannot be read.
/// @param base study_input() of the study
std::optional<PointResult> recorded_point(const std::filesystem::path& out, const nlohmann::json& base,
                                          std::size_t index, const Point& p);

/// @brief Before a study starts: removes out/points/ entirely (fresh), or only the half-written
/// records of an interrupted one (*.partial).
void prepare_point_records(const std::filesystem::path& out, bool fresh);

}  // namespace beamimpact::study
