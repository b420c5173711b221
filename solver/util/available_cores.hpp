#pragma once
/// @file available_cores.hpp
/// @brief How many cores this process may run on: the hardware threads, and fewer when the
/// process's CPU affinity (Linux sched_getaffinity: taskset, a container's cpuset) allows fewer.

#include <string>

namespace beamimpact {

/// @brief The cores a run's threads can use at once.
struct AvailableCores {
  int count = 1;       ///< min(hardware threads, CPUs in the affinity mask), at least 1
  std::string source;  ///< how count was found, e.g. "2 hardware threads, 2 in the CPU affinity mask"
};

/// @brief The cores available to this process now (std::thread::hardware_concurrency, and
/// sched_getaffinity where the system has it and it answers).
AvailableCores available_cores();

}  // namespace beamimpact
