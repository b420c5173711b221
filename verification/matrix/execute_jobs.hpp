#pragma once
/// @file execute_jobs.hpp
/// @brief Runs a set of independent runs in parallel worker threads, each as its own process,
/// with one progress line per finished run on stderr.

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include <verification/compare/StoredRun.hpp>
#include <verification/matrix/JobSpec.hpp>

namespace beamimpact::verification {

/// @brief How one run ended.
struct JobOutcome {
  /// @brief ok: complete run; failed: non-zero exit other than 2, time-out or no summary.json;
  /// skipped: tool missing; not applicable: exit 2 on a scene the suite checked, the method's
  /// refusal (it does not model friction, ...) with its one line of reason.
  enum class Status { kOk, kFailed, kSkipped, kNotApplicable };
  JobSpec spec;
  std::filesystem::path dir;  ///< where history.csv and summary.json are (and run.log)
  Status status = Status::kFailed;
  std::string message;           ///< why it failed or was skipped
  double process_seconds = 0.0;  ///< s, wall time of the process (start-up and output included)
  double solver_seconds = 0.0;   ///< s, summary.json wall_seconds (the method's own time)
  long steps = 0;                ///< summary.json steps
  double dt = 0.0;               ///< s, summary.json dt (the step actually used)
  /// @brief The finished run (history.csv and summary.json), read once by execute_job; null when
  /// not ok or when the outcome came from another MPI rank (stored_run() reads it then).
  std::shared_ptr<const StoredRun> run;
  bool resumed = false;  ///< finished by an earlier, interrupted command (its times are that run's)
};

/// @brief The outcome's run: JobOutcome::run, or read from its directory when the outcome has none.
std::shared_ptr<const StoredRun> stored_run(const JobOutcome& o);

/// @brief A run outcome's word (scorecard.json, sweep.json, the progress lines, a finished run's
/// record): "ok", "failed", "skipped", "not applicable".
const char* to_string(JobOutcome::Status s);

/// @brief The run outcome whose word (to_string) is `text`. Throws InputError(file, key, the
/// words allowed) for any other text.
/// @param text the word; @param file the file it was read from; @param key its key there
JobOutcome::Status parse_run_status(std::string_view text, const std::string& file, const std::string& key);

/// @brief Runs every spec (keys must be unique) into out_dir/<key>/ with `jobs` workers; a run
/// is ok when its process exits 0 and left a summary.json. Returns outcomes by key.
std::map<std::string, JobOutcome> execute_jobs(const std::vector<JobSpec>& specs,
                                               const std::filesystem::path& out_dir, const Launcher& launcher,
                                               int jobs, double timeout_seconds);

/// @brief Where a set of runs is executed: execute_jobs (threads of this process) or spread over
/// MPI ranks (study/distributed_jobs.hpp). Same arguments as execute_jobs; returns nullopt on a
/// rank that is not rank 0 of an MPI job (its outcomes went to rank 0, which writes the outputs).
using JobExecutor = std::function<std::optional<std::map<std::string, JobOutcome>>(
    const std::vector<JobSpec>&, const std::filesystem::path&, const Launcher&, int, double)>;

/// @brief The order runs are started in: methods the registry marks slow first, then small
/// steps, so that the tail of the queue is short.
std::vector<JobSpec> schedule_order(const std::vector<JobSpec>& specs);

/// @brief Runs one spec into dir (emptied first) as its own process and reads its summary.json;
/// an ok or not-applicable run is then recorded as finished (finished_runs.hpp). With
/// launcher.reuse_finished, a run recorded in dir with the same input is taken instead.
/// @param why_not non-empty: the run is skipped with this reason (unavailable method, interrupted)
JobOutcome execute_job(const JobSpec& spec, const std::filesystem::path& dir, const Launcher& launcher,
                       const std::string& why_not, double timeout_seconds);

/// @brief An outcome as JSON, without its spec, directory and run (between MPI ranks, in a
/// finished run's record): status (its word), message, process_seconds, solver_seconds, steps, dt.
nlohmann::json outcome_json(const JobOutcome& o);

/// @brief The inverse of outcome_json() (a status given as its number, as records written before
/// the word was, is read too); the run is not read (stored_run() reads it).
JobOutcome outcome_from_json(const JobSpec& spec, const std::filesystem::path& dir, const nlohmann::json& j);

/// @brief The progress line of a finished run ("[3/10] s1_central paper dt=0.01: ok (0.21 s)").
std::string progress_line(std::size_t done, std::size_t total, const JobOutcome& o);

}  // namespace beamimpact::verification
