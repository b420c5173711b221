#pragma once
/// @file run_point.hpp
/// @brief One point of a study, run in-process: the reference once, then every method, each
/// compared with the reference through verification/compare and checked for stability (energy
/// created, divergence). A run that throws is recorded in the result, never thrown on.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <verification/study/Study.hpp>

namespace beamimpact::study {

/// @brief One method at one point.
struct CaseResult {
  std::string method;
  /// @brief "ok"; "energy": energy created above the study's bound; "diverged": the run failed
  /// (non-finite state, solver failure); "error": the point's scene was refused (bad input, dt
  /// above the stability limit); "no_reference": ok but the reference run failed.
  std::string status = "error";
  std::string message;
  long steps = 0;
  double dt = 0.0;                           ///< s, the step used
  std::vector<std::optional<double>> norms;  ///< one per Study::norms, in order; empty: n/a
  std::optional<double> energy_growth;       ///< check_run's energy_growth
  double seconds = 0.0;                      ///< s, wall time of this run (timing field)
};

/// @brief A value that may be missing as JSON: the number, or null.
inline nlohmann::json json_or_null(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

/// @brief Everything one point produced.
struct PointResult {
  std::string reference_status = "error", reference_message;
  double reference_seconds = 0.0;  ///< s (timing field)
  std::vector<CaseResult> cases;   ///< one per Study::methods
  int rank = 0;                    ///< the MPI rank that ran it (timing field; set by the receiver)

  /// @brief Lossless JSON (doubles round-trip), for sending between ranks.
  nlohmann::json to_json() const;
  /// @brief The inverse of to_json().
  static PointResult from_json(const nlohmann::json& j);
};

/// @brief Runs point `index` with the reference and every method and compares the runs in
/// memory; run directories runs_dir/INDEX.METHOD are written only when the study keeps its runs
/// (keep_runs) or the scene writes fields (removed after the comparison unless kept).
/// @param s the study
/// @param p the point's parameter values
/// @param index the point's index in the design (names its run directories)
/// @param runs_dir where the run directories go
PointResult run_point(const Study& s, const Point& p, std::size_t index,
                      const std::filesystem::path& runs_dir);

/// @brief Work estimate of a point for scheduling (longest first): estimate_run_cost()'s work
/// (max(steps, wave steps) x degrees of freedom), summed over the reference and the methods. 0
/// when the scene cannot be loaded.
/// @param s the study
/// @param p the point
double point_cost(const Study& s, const Point& p);

}  // namespace beamimpact::study
