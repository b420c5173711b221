#pragma once
/// @file child_process.hpp
/// @brief Runs a program as a separate process with its output captured in a log file: each
/// verification run is a process so that runs stay independent and any tool can take part, and
/// an external method of the registry is started the same way.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace beamimpact {

/// @brief How a process ended.
struct ProcessResult {
  int exit_code = -1;         ///< exit status, or -1 when it did not exit normally
  bool timed_out = false;     ///< killed after the time limit
  std::string error;          ///< why it could not start / how it ended abnormally ("" if it exited)
  double wall_seconds = 0.0;  ///< s, from start to end
};

/// @brief Starts argv[0] (a path, not searched in PATH) with stdout and stderr appended to log,
/// waits at most timeout_seconds (then kills it) and returns how it ended. Thread-safe.
/// @param interrupted when given and non-zero (the signal that interrupted the caller), the
/// process gets SIGTERM, then SIGKILL after 2 s
/// @param own_group true: the process and its children form their own process group, ended
/// together; false: it stays in the caller's group, so that whoever ends the caller's group
/// (a time limit, Ctrl-C) ends it too
ProcessResult spawn_and_wait(const std::vector<std::string>& argv, const std::filesystem::path& log,
                             double timeout_seconds, const std::function<int()>& interrupted = {},
                             bool own_group = true);

}  // namespace beamimpact
