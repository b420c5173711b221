#pragma once
/// @file child_process.hpp
/// @brief Runs a program as a separate process with its output captured in a log file: each
/// verification run is a process so that runs stay independent and any tool can take part, and
/// an external method of the registry is started the same way.
///
/// Children end with their parent: every child runs in its own process group, registered while
/// it lives. On SIGTERM, SIGINT or SIGHUP (handlers installed at the first spawn where the signal
/// still has its default action) and on exit() the registered groups get SIGTERM, then SIGKILL
/// after 2 s, and the handler returns only when they are gone; it then ends beamimpact by the
/// same signal, unless the caller asked to carry on (catch_interruptions). A process that holds
/// an output lock therefore holds it until its children are gone.

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
/// process gets SIGTERM, then SIGKILL after 2 s; a signal caught here (catch_interruptions) does
/// the same, and no child starts after one
/// @param own_group kept for the callers' sake: every child has its own process group, which
/// the handlers above end with beamimpact
ProcessResult spawn_and_wait(const std::vector<std::string>& argv, const std::filesystem::path& log,
                             double timeout_seconds, const std::function<int()>& interrupted = {},
                             bool own_group = true);

/// @brief Installs the handlers of SIGINT, SIGTERM and SIGHUP in their recording form: they end
/// the children (as above) and record the signal, and the program carries on to write what it
/// has (a study's report marked incomplete). Call once, before the first child starts.
void catch_interruptions();

/// @brief The signal recorded by the handlers (SIGINT, SIGTERM, SIGHUP), or 0.
int caught_signal();

}  // namespace beamimpact
