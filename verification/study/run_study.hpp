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

#include <nlohmann/json.hpp>

#include <verification/study/Study.hpp>
#include <verification/study/run_point.hpp>

namespace beamimpact::study {

/// @brief What to run: a study file, where its tables go, and how.
struct StudyOptions {
  std::filesystem::path file;  ///< the study (TOML, verification/studies/)
  std::filesystem::path out;   ///< the tables; the points' records under out/points
  bool keep_runs = false;      ///< keep every run's files under out/runs (besides the file's own keep_runs)
  bool fresh = false;          ///< run every point again (default: an interrupted study's points are taken)
};

/// @brief The results of a study, in design order.
struct StudyResult {
  Study study;          ///< the study as loaded (keep_runs as run)
  std::string command;  ///< the command line that makes it (study.md)
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

/// @brief `beamimpact study` as a library call: removes the tables of an earlier study in o.out (before
/// anything can refuse), loads o.file (InputError naming the file and key) and runs it
/// (execute_study()). Returns nullopt on an MPI rank other than 0.
std::optional<StudyResult> run_study(const StudyOptions& o);

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

/// @brief study.json's document of run_study()'s result: the study's definition and every case
/// (no timing field; the same on every run and rank count).
/// @param r the result, its `study` set (run_study())
/// @param version `beamimpact --version`
nlohmann::json study_json(const StudyResult& r, const std::string& version);

/// @brief The tables of run_study()'s result in o.out (write_study() with its study, command and
/// this build's version).
StudyCounts write_study_reports(const StudyOptions& o, const StudyResult& r);

}  // namespace beamimpact::study
