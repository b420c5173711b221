#include <solver/util/heap_policy.hpp>

#include <algorithm>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <vector>

// glibc's allocator is the one in use: not with another C library, nor under a sanitizer (its
// own allocator, where mallinfo2 says nothing of its heap and a reservation would only fill its
// quarantine).
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define BEAMIMPACT_GLIBC_HEAP 1
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#undef BEAMIMPACT_GLIBC_HEAP
#endif
#endif
#endif

#if defined(BEAMIMPACT_GLIBC_HEAP)
#include <malloc.h>
#include <sys/mman.h>
#endif

namespace beamimpact {
namespace {

constexpr int kHeapGrowth = 64 << 20;  ///< M_TOP_PAD: the heap grows in 64 MB steps
#if defined(BEAMIMPACT_GLIBC_HEAP)
constexpr int kLargestHeapBlock = 32 << 20;    ///< glibc's upper bound for M_MMAP_THRESHOLD (64-bit)
constexpr int kKeptFreeTop = INT_MAX;          ///< M_TRIM_THRESHOLD (an int): 2 GB of free top kept
constexpr std::uintptr_t kHugePage = 2 << 20;  ///< a transparent huge page (x86-64, arm64 with 4 kB pages)
#endif

bool released_by_environment() {
  const char* v = std::getenv("BEAMIMPACT_RELEASE_MEMORY");
  return v != nullptr && std::strcmp(v, "1") == 0;
}

}  // namespace

bool glibc_heap() {
#if defined(BEAMIMPACT_GLIBC_HEAP)
  return true;
#else
  return false;
#endif
}

void keep_freed_memory() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (released_by_environment()) return;
#if defined(BEAMIMPACT_GLIBC_HEAP)
    mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock);
    mallopt(M_TRIM_THRESHOLD, kKeptFreeTop);
    mallopt(M_TOP_PAD, kHeapGrowth);
#endif
  });
}

void reserve_heap(double bytes) {
  keep_freed_memory();
  if (released_by_environment() || !(bytes > kHeapGrowth)) return;
#if defined(BEAMIMPACT_GLIBC_HEAP)
  static std::mutex mutex;
  const std::lock_guard<std::mutex> lock(mutex);
  const std::size_t want = static_cast<std::size_t>(std::min(bytes, static_cast<double>(kKeptFreeTop) / 2));
  if (mallinfo2().fordblks >= want) return;  // free in the heap already (and marked when this made it)
  // Blocks just under the mmap threshold come from the heap's top, one after the other.
  constexpr std::size_t kBlock = kLargestHeapBlock - (std::size_t{1} << 20);
  std::vector<void*> blocks;
  for (std::size_t got = 0; got < want; got += kBlock) {
    void* p = std::malloc(kBlock);
    if (p == nullptr) break;
    blocks.push_back(p);
  }
  for (void* p : blocks) {
    const std::uintptr_t a = (reinterpret_cast<std::uintptr_t>(p) + kHugePage - 1) / kHugePage * kHugePage;
    const std::uintptr_t b = (reinterpret_cast<std::uintptr_t>(p) + kBlock) / kHugePage * kHugePage;
    if (b > a) madvise(reinterpret_cast<void*>(a), b - a, MADV_HUGEPAGE);  // a hint: failure is harmless
  }
  for (auto it = blocks.rbegin(); it != blocks.rend(); ++it) std::free(*it);
#endif
}

}  // namespace beamimpact
