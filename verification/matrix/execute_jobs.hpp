#pragma once
/// @file run_all.hpp
/// @brief Runs a set of independent runs in parallel worker threads, each as its own process,
/// with one progress line per finished run on stderr.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <beamimpact/verification/matrix/JobSpec.hpp>

namespace beamimpact::verification {

/// @brief How one run ended.
struct JobOutcome {
  /// @brief ok: complete run; failed: non-zero exit, time-out or no summary.json; skipped: tool missing.
  enum class Status { kOk, kFailed, kSkipped };
  JobSpec spec;
  std::filesystem::path dir;  ///< where history.csv and summary.json are (and run.log)
  Status status = Status::kFailed;
  std::string message;           ///< why it failed or was skipped
  double process_seconds = 0.0;  ///< s, wall time of the process (start-up and output included)
  double solver_seconds = 0.0;   ///< s, summary.json wall_seconds (the method's own time)
  long steps = 0;                ///< summary.json steps
  double dt = 0.0;               ///< s, summary.json dt (the step actually used)
};

/// @brief Name of a status: "ok", "failed", "skipped".
const char* status_name(JobOutcome::Status s);

/// @brief Runs every spec (keys must be unique) into out_dir/<key>/ with `jobs` workers; a run
/// is ok when its process exits 0 and left a summary.json. Returns outcomes by key.
std::map<std::string, JobOutcome> execute_jobs(const std::vector<JobSpec>& specs,
                                               const std::filesystem::path& out_dir, const Launcher& launcher,
                                               int jobs, double timeout_seconds);

}  // namespace beamimpact::verification
