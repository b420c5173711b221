#pragma once
/// @file run_study.hpp
/// @brief Runs a whole study (every point, on every rank of the MPI job or in this process) and
/// writes its table: study.csv and study.json (identical between runs and rank counts), the
/// timing fields apart in timing.csv and timing.json (the only outputs with times, ranks and
/// rates), and study.md listing where the method
/// broke (failed, diverged, created energy, or a norm above one of the study's `breaks` bounds).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <verification/study/Study.hpp>
#include <verification/study/run_point.hpp>

namespace beamimpact::study {

/// @brief The results of a study, in design order.
struct StudyResult {
  std::vector<Point> points;
  std::vector<PointResult> results;  ///< results[i] belongs to points[i]
  double wall_seconds = 0.0;         ///< s, the whole study (timing field)
  int ranks = 1;
  std::size_t resumed = 0;  ///< points finished by an earlier, interrupted study (their times are that one's)
};

/// @brief Runs every point (longest first, over the MPI ranks when there are several), with one
/// progress line per point on stderr (rank 0). Each finished point is recorded in out/points/;
/// the points an interrupted study recorded with the same input are taken, not run again
/// (finished_points.hpp), and stderr says how many. Returns the results on rank 0, nullopt on
/// the other ranks (they write nothing).
/// @param s the study
/// @param out the output directory (runs go to out/runs while they are compared)
/// @param fresh run every point (the records of earlier points removed first)
std::optional<StudyResult> execute_study(const Study& s, const std::filesystem::path& out,
                                         bool fresh = false);

/// @brief What the written tables count.
struct StudyCounts {
  std::size_t cases = 0;          ///< points x methods
  std::size_t broken = 0;         ///< cases where the method broke (study.md)
  double cases_per_second = 0.0;  ///< cases run by this command / wall_seconds (timing.json)
};

/// @brief Writes out/study.csv, study.json, study.md, timing.csv and timing.json.
/// @param s the study
/// @param r its results
/// @param out the output directory
/// @param command how the study was started (for study.md)
/// @param version `beamimpact --version`
/// @return the counts the tables state
StudyCounts write_study(const Study& s, const StudyResult& r, const std::filesystem::path& out,
                        const std::string& command, const std::string& version);

}  // namespace beamimpact::study
