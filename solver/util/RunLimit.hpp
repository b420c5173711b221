#pragma once
/// @file RunLimit.hpp
/// @brief The limit of the runs a thread starts: a wall-time budget and an interruption. A job
/// executor that runs methods in its own process sets one around each run; the methods' step
/// loops check it through Progress::update() (every 256 steps), and an external method's
/// program gets what is left of the budget as its time limit. Without a RunLimit, runs are
/// unlimited.

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace beamimpact {

/// @brief Thrown by RunLimit::check() in the run's thread when its budget is spent or it was
/// interrupted: the run failed (not a refusal), with the reason as what().
class RunStopped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// @brief Limits the runs of the calling thread while it lives (nested limits: the inner one
/// counts, the outer one is restored after it).
class RunLimit {
 public:
  /// @brief A budget of `seconds` of wall time from now (> 0; infinity: no time limit) and an
  /// interruption: `interrupted` returns the signal that interrupted the caller, or 0.
  RunLimit(double seconds, std::function<int()> interrupted);
  ~RunLimit();
  RunLimit(const RunLimit&) = delete;
  RunLimit& operator=(const RunLimit&) = delete;

  /// @brief Throws RunStopped ("time limit of 900 s reached", "interrupted by signal 2") when
  /// this thread's limit is reached; returns at once without a limit.
  static void check();
  /// @brief s, the budget this thread has left (infinity without a limit; 0 when spent).
  static double seconds_left();
  /// @brief The interruption of this thread's limit (an empty function without one).
  static std::function<int()> interruption();

 private:
  const RunLimit* outer_;
  double deadline_;  // s on the steady clock
  double seconds_;
  std::function<int()> interrupted_;
};

}  // namespace beamimpact
