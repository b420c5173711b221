#include <solver/util/heap_policy.hpp>

#include <climits>
#include <cstdlib>
#include <cstring>
#include <mutex>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace beamimpact {
namespace {

constexpr int kLargestHeapBlock = 32 << 20;  ///< glibc's upper bound for M_MMAP_THRESHOLD (64-bit)
constexpr int kKeptFreeTop = INT_MAX;        ///< M_TRIM_THRESHOLD (an int): 2 GB of free top kept
constexpr int kHeapGrowth = 64 << 20;        ///< M_TOP_PAD: the heap grows in 64 MB steps

bool released_by_environment() {
  const char* v = std::getenv("BEAMIMPACT_RELEASE_MEMORY");
  return v != nullptr && std::strcmp(v, "1") == 0;
}

}  // namespace

void keep_freed_memory() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (released_by_environment()) return;
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock);
    mallopt(M_TRIM_THRESHOLD, kKeptFreeTop);
    mallopt(M_TOP_PAD, kHeapGrowth);
#endif
  });
}

}  // namespace beamimpact
