#pragma once
/// @file output_lock.hpp
/// @brief The lock a subcommand takes on its output directory before it removes or writes
/// anything there (solver/util/OutputLock.hpp): a second writer exits 2 naming the holder.

#include <filesystem>

#include <solver/util/OutputLock.hpp>
#include <verification/jobs/task_farm.hpp>

namespace beamimpact {

/// @brief The lock of dir, taken by rank 0 only: the other ranks of an MPI job run cases but
/// write nothing into dir itself. Hold the result until the command ends.
inline OutputLock lock_output(const std::filesystem::path& dir) {
  return OutputLock(jobs::World::rank() == 0 ? dir : std::filesystem::path());
}

}  // namespace beamimpact
