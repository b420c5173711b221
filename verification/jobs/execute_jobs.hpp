#pragma once
/// @file execute_jobs.hpp
/// @brief The one executor of a set of independent runs (verify, sweep, score): worker threads
/// of this process, or, under mpirun, the ranks of the MPI job (task_farm.hpp); each run in
/// this process or isolated as its own process (Launcher), with one progress line per finished
/// run on stderr, resume records (finished_runs.hpp) and interruption (interruption.hpp).

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <verification/jobs/JobOutcome.hpp>
#include <verification/jobs/JobSpec.hpp>

namespace beamimpact::jobs {

/// @brief Runs every spec (keys must be unique) into out_dir/<key>/, slow methods and small
/// steps first. One MPI rank: `jobs` worker threads of this process. N ranks: each run is taken
/// by whichever rank asks next, one at a time per rank, and the outcomes are gathered on rank 0
/// (out_dir must be on a file system every rank sees). Progress is silenced while runs go in
/// this process (their lines would interleave); each finished run prints its progress line.
/// @param specs the runs; @param out_dir their parent directory; @param launcher how they start
/// @param jobs worker threads (>= 1) when there is one rank
/// @param timeout_seconds each run's wall-time limit (s, > 0): an isolated run is killed, a run in
/// this process stops at its next check (RunLimit) and fails
/// @return outcomes by key on rank 0; nullopt on the other ranks of an MPI job
std::optional<std::map<std::string, JobOutcome>> execute_jobs(const std::vector<JobSpec>& specs,
                                                              const std::filesystem::path& out_dir,
                                                              const Launcher& launcher, int jobs,
                                                              double timeout_seconds);

/// @brief A note for a plan line on stderr: ", N MPI ranks" under mpirun with N > 1, else "".
std::string executor_note();

/// @brief The order runs are started in: methods the registry marks slow first, then small
/// steps, so that the tail of the queue is short.
std::vector<JobSpec> schedule_order(const std::vector<JobSpec>& specs);

/// @brief Runs one spec into dir (emptied first), in this process or isolated (launcher), and
/// reads its run; an ok or not-applicable run is then recorded as finished (finished_runs.hpp).
/// With launcher.reuse_finished, a run recorded in dir with the same input is taken instead.
/// @param why_not non-empty: the run is skipped with this reason (unavailable method, interrupted)
JobOutcome execute_job(const JobSpec& spec, const std::filesystem::path& dir, const Launcher& launcher,
                       const std::string& why_not, double timeout_seconds);

/// @brief The progress line of a finished run ("[3/10] s1_central paper dt=0.01: ok (0.21 s)").
std::string progress_line(std::size_t done, std::size_t total, const JobOutcome& o);

}  // namespace beamimpact::jobs
