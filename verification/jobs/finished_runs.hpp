#pragma once
/// @file finished_runs.hpp
/// @brief Resuming an interrupted `verify` or `study` with the same command: each finished piece
/// of work (a run of verify, a point of a study) leaves a record, written atomically and after
/// everything else of it, naming the input it was made from (the program's version and the
/// SHA-256 of its bytes, its methods files, the scene file's SHA-256, the piece's own settings).
/// A restart reuses exactly the pieces whose record names the same input and does the rest
/// again; a record of another build, version, scene or setting, or one that cannot be read, is
/// ignored.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <verification/jobs/execute_jobs.hpp>

namespace beamimpact::jobs {

/// @brief What every result depends on: {"version": `beamimpact --version`, "program_sha256":
/// the SHA-256 of the program's own bytes (program_id.hpp: the build, not only its version
/// string, which is the same for every build of an edited tree), "methods_files": [{"file",
/// "sha256"}, ...]} of the methods files this process loaded. `beamimpact score` keys its
/// reference cache on it too.
nlohmann::json program_input();

/// @brief Writes {"input": input, "result": result} to file, atomically (write_file_atomic).
/// Throws std::runtime_error when it cannot be written.
void write_record(const std::filesystem::path& file, const nlohmann::json& input,
                  const nlohmann::json& result);

/// @brief The result stored in file when its input equals `input`; nullopt when the file is
/// missing, unreadable, not a record, or of another input.
std::optional<nlohmann::json> read_record(const std::filesystem::path& file, const nlohmann::json& input);

/// @brief The record of a finished run, in its run directory.
inline constexpr const char* kRunRecord = "finished.json";

/// @brief What a run's result depends on: program_input(), the spec's fields and the scene
/// file's SHA-256.
nlohmann::json run_input(const JobSpec& spec);

/// @brief Records a finished run in o.dir/finished.json: only ok and not-applicable outcomes (a
/// failure may be the machine's, a skip its setup: they run again). Never throws: a record that
/// cannot be written is reported on stderr, and that run is done again on a restart.
/// @param o the outcome
/// @param input run_input() of its spec, taken before the run started
void record_run(const JobOutcome& o, const nlohmann::json& input);

/// @brief The outcome of a run recorded as finished in dir with spec's input (its files still
/// there; the run is read when evaluated, stored_run()); nullopt otherwise.
std::optional<JobOutcome> recorded_run(const JobSpec& spec, const std::filesystem::path& dir);

/// @brief How many of specs have a run recorded_run() takes, in runs_dir/KEY.
std::size_t count_recorded(const std::vector<JobSpec>& specs, const std::filesystem::path& runs_dir);

}  // namespace beamimpact::jobs
