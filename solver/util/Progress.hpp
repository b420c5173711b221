#pragma once
/// @file Progress.hpp
/// @brief Progress line on stderr for long runs: silent for the first second, then at most a few
/// updates per second; never on stdout (which carries results).

#include <chrono>
#include <functional>
#include <string>

#include <solver/util/RunLimit.hpp>

namespace beamimpact {

/// @brief Reports "label: 45% (t = 1.8 of 4 s)" while a run is long.
class Progress {
 public:
  /// @brief label: shown first; total: the value that means 100% (e.g. end time in s).
  Progress(std::string label, double total);
  /// @brief Call often; cheap (checks the clock every 256 calls). Also where a run meets its
  /// thread's RunLimit: throws RunStopped when the limit is reached.
  void update(double value) {
    ++updates_;
    if ((++calls_ & 255u) == 0) {
      RunLimit::check();
      report(value);
    }
  }
  /// @brief The line also shows the wall time per DOF-step so far (ns), counting one step per
  /// update() call: for loops that call update() once per time step of a `dofs`-DOF model.
  void set_dofs_per_update(long dofs) { dofs_ = dofs; }
  /// @brief Ends the line if anything was printed.
  ~Progress();
  /// @brief Silences every Progress of this process (the CLI's --quiet); on by default.
  static void set_enabled(bool enabled);
  /// @brief Whether Progress lines are shown (set_enabled).
  static bool enabled();
  /// @brief Silences every Progress while it lives, then restores the setting it found.
  class Silence {
   public:
    Silence() : was_(enabled()) { set_enabled(false); }
    ~Silence() { set_enabled(was_); }
    Silence(const Silence&) = delete;
    Silence& operator=(const Silence&) = delete;

   private:
    bool was_;
  };
  /// @brief Sends the updates to `listener` (label, value, total) instead of stderr (the Python
  /// module shows them in a notebook); an empty function restores stderr. Set before a run.
  static void set_listener(std::function<void(const std::string&, double, double)> listener);

 private:
  void report(double value);
  std::string label_;
  double total_;
  unsigned calls_ = 0;
  unsigned long updates_ = 0;  // update() calls, for the cost per DOF-step
  long dofs_ = 0;
  bool printed_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace beamimpact
