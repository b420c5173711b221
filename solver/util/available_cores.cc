#include <solver/util/available_cores.hpp>

#include <algorithm>
#include <thread>

#include <fmt/format.h>

#if defined(__linux__)
#include <sched.h>
#endif

namespace beamimpact {

AvailableCores available_cores() {
  const unsigned hw = std::thread::hardware_concurrency();  // 0: unknown
  AvailableCores c;
  c.count = std::max(1, static_cast<int>(hw));
  c.source = hw > 0 ? fmt::format("{} hardware threads", hw) : "hardware threads unknown";
#if defined(__linux__)
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) {
    const int allowed = CPU_COUNT(&set);
    c.source += fmt::format(", {} in the CPU affinity mask", allowed);
    if (allowed > 0) c.count = hw > 0 ? std::min(c.count, allowed) : allowed;
  }
#endif
  return c;
}

}  // namespace beamimpact
