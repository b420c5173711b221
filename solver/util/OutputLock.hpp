#pragma once
/// @file OutputLock.hpp
/// @brief One writer per output directory: a command holds DIR/.beamimpact.lock (an advisory
/// flock) from before it removes or writes anything in DIR until it ends. The kernel releases the
/// lock when the process ends in any way (exit, crash, kill), so a lock is never left stale.

#include <filesystem>
#include <string>

namespace beamimpact {

/// @brief Holds the lock of one output directory for its lifetime.
class OutputLock {
 public:
  /// @brief Makes dir (with its parents) and takes its lock. Throws InputError naming dir and the
  /// process that holds it (its pid) when another writer has it; nothing in dir is touched then.
  /// @param dir the output directory; empty: nothing is locked (no output is written)
  explicit OutputLock(const std::filesystem::path& dir);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  /// @brief The lock file of dir (left in place: removing it would let two writers lock two files).
  static std::filesystem::path file(const std::filesystem::path& dir) { return dir / ".beamimpact.lock"; }

 private:
  int fd_ = -1;  // the open lock file; closing it releases the lock
};

}  // namespace beamimpact
