#pragma once
/// @file distributed_jobs.hpp
/// @brief The JobExecutor of `verify` and `sweep` under mpirun: each run (a process, as in the
/// serial suite) is started by whichever rank asks for work next, slow methods and small steps
/// first; the outcomes are gathered on rank 0. One rank: execute_jobs with its threads.
/// The output directory must be on a file system every rank sees (one machine, or NFS/Lustre).

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <verification/matrix/execute_jobs.hpp>

namespace beamimpact::study {

/// @brief Runs the specs over the ranks of the MPI job (see verification::JobExecutor).
/// @param jobs threads per rank when there is one rank (more ranks: one run per rank at a time)
std::optional<std::map<std::string, verification::JobOutcome>> distributed_jobs(
    const std::vector<verification::JobSpec>& specs, const std::filesystem::path& out_dir,
    const verification::Launcher& launcher, int jobs, double timeout_seconds);

}  // namespace beamimpact::study
