#pragma once
/// @file JobOutcome.hpp
/// @brief How one run of a set ended, typed: ok, failed, skipped, or not applicable (the method
/// refused it, with the refusal's file and key), and its words in the JSON outputs.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include <verification/compare/StoredRun.hpp>
#include <verification/jobs/JobSpec.hpp>

namespace beamimpact::jobs {

/// @brief A method's refusal of a run: the InputError it raised (file, key and what() whole).
struct Refusal {
  std::string file;     ///< the file the refusal is about (the scene, an option)
  std::string key;      ///< the key ("" the whole file)
  std::string message;  ///< the error's whole message (file, key and what was expected)
};

/// @brief How one run ended.
struct JobOutcome {
  /// @brief ok: complete run; failed: an error other than a refusal (a run that failed, a time
  /// limit, a crash of an isolated run, no summary.json); skipped: method unavailable here or
  /// the set interrupted before it started; not applicable: the method refused the scene
  /// (`refusal` says why).
  enum class Status { kOk, kFailed, kSkipped, kNotApplicable };
  JobSpec spec;
  std::filesystem::path dir;  ///< where history.csv and summary.json are (and run.log)
  Status status = Status::kFailed;
  std::string message;           ///< why it failed, was skipped or refused
  double process_seconds = 0.0;  ///< s, wall time of the run (of its process when isolated; output included)
  double solver_seconds = 0.0;   ///< s, summary.json wall_seconds (the method's own time)
  long steps = 0;                ///< summary.json steps
  double dt = 0.0;               ///< s, summary.json dt (the step actually used)
  /// @brief The finished run (history.csv and summary.json), read once when it finished; null
  /// when not ok or when the outcome came from another MPI rank (stored_run() reads it then).
  std::shared_ptr<const verification::StoredRun> run;
  bool resumed = false;            ///< finished by an earlier, interrupted command (its times are that run's)
  std::optional<Refusal> refusal;  ///< set when not applicable
};

/// @brief The outcome's run: JobOutcome::run, or read from its directory when the outcome has none.
std::shared_ptr<const verification::StoredRun> stored_run(const JobOutcome& o);

/// @brief A run outcome's word (scorecard.json, sweep.json, the progress lines, a finished run's
/// record): "ok", "failed", "skipped", "not applicable".
const char* to_string(JobOutcome::Status s);

/// @brief The run outcome whose word (to_string) is `text`. Throws InputError(file, key, the
/// words allowed) for any other text.
/// @param text the word; @param file the file it was read from; @param key its key there
JobOutcome::Status parse_run_status(std::string_view text, const std::string& file, const std::string& key);

/// @brief An outcome as JSON, without its spec, directory and run (between MPI ranks, in a
/// finished run's record): status (its word), message, process_seconds, solver_seconds, steps,
/// dt, resumed, and refusal ({file, key, message}) when refused.
nlohmann::json outcome_json(const JobOutcome& o);

/// @brief The inverse of outcome_json() (a status given as its number, as records written before
/// the word was, is read too); the run is not read (stored_run() reads it).
JobOutcome outcome_from_json(const JobSpec& spec, const std::filesystem::path& dir, const nlohmann::json& j);

}  // namespace beamimpact::jobs
