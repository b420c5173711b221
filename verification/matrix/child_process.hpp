#pragma once
/// @file subprocess.hpp
/// @brief Runs a program as a separate process with its output captured in a log file; each
/// verification run is a process so that runs stay independent and any tool can take part.

#include <filesystem>
#include <string>
#include <vector>

namespace beamimpact::verification {

/// @brief How a process ended.
struct ProcessResult {
  int exit_code = -1;         ///< exit status, or -1 when it did not exit normally
  bool timed_out = false;     ///< killed after the time limit
  std::string error;          ///< why it could not start / how it ended abnormally ("" if it exited)
  double wall_seconds = 0.0;  ///< s, from start to end
};

/// @brief Starts argv[0] (a path, not searched in PATH) with stdout and stderr appended to log,
/// waits at most timeout_seconds (then kills it) and returns how it ended. Thread-safe.
ProcessResult spawn_and_wait(const std::vector<std::string>& argv, const std::filesystem::path& log,
                             double timeout_seconds);

}  // namespace beamimpact::verification
