#pragma once
/// @file interruption.hpp
/// @brief Clean interruption of studies (verify, sweep): SIGINT / SIGTERM / SIGHUP are caught
/// and recorded (catch_interruptions, api/child_process.hpp); the child runs (each in its own
/// process group) are then ended by the handler and spawn_and_wait,
/// no new run starts, and the command writes its report marked incomplete and exits non-zero.

namespace beamimpact::jobs {

/// @brief Installs the SIGINT, SIGTERM and SIGHUP handlers (they end the children and record the
/// signal). Call once, before the first child starts.
void forward_interruptions();

/// @brief The signal that interrupted this process (SIGINT, SIGTERM, SIGHUP), or 0.
int interruption();

/// @brief The exit code of an interrupted command: 128 + the signal (130 for SIGINT), the
/// shell's convention.
inline int interrupted_exit_code() { return 128 + interruption(); }

}  // namespace beamimpact::jobs
