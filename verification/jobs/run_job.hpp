#pragma once
/// @file run_job.hpp
/// @brief One run, done one of two ways: a call of beamimpact::run in this process (the
/// default), or a `beamimpact run` process (Launcher::exe: isolation). Both leave the same run
/// directory and the same typed outcome: a refusal is the method's InputError, raised in this
/// process or written by the isolated process to kRefusalFile, never a line read from a log.

#include <filesystem>

#include <verification/jobs/JobOutcome.hpp>
#include <verification/jobs/JobSpec.hpp>

namespace beamimpact::jobs {

/// @brief Runs spec into dir (emptied first; run.log says how the run was made and, when
/// isolated, holds the process's output) and reads the finished run. Never throws.
/// @param timeout_seconds wall-time limit of the run (s, > 0)
JobOutcome run_job(const JobSpec& spec, const std::filesystem::path& dir, const Launcher& launcher,
                   double timeout_seconds);

}  // namespace beamimpact::jobs
