// beamimpact::run leaves the process's allocator as it is unless RunOptions::tune_heap asks for
// the heap policy (solver/util/heap_policy.hpp): a library call must not change glibc's malloc
// parameters in the process that calls it (a Python interpreter, a user's program). With glibc's
// defaults a 24 MB block is mapped on its own (above the mmap threshold, which glibc raises only
// when such a block is freed, up to 32 MB); under the policy (threshold 32 MB) it would come from
// the heap. One test in this program: the policy, once set, holds for the whole process.
#include <cstddef>
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include <api/run.hpp>
#include <solver/util/heap_policy.hpp>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace beamimpact {
namespace {

TEST(HeapOption, ARunLeavesTheAllocatorAloneByDefault) {
  if (!glibc_heap())
    GTEST_SKIP() << "not glibc's allocator (a sanitizer's or another C library's): no policy to see";
#if defined(__GLIBC__)
  const RunOptions defaults;
  EXPECT_FALSE(defaults.tune_heap);
  // S1 meshed 100 times finer (the estimate above the 64 MB a reservation starts at, were it asked).
  RunOptions o;
  o.set = {"bodies.A.elements=1000", "bodies.B.elements=1000", "time.dt=\"auto\"", "time.end=0.01"};
  (void)run(std::filesystem::path(BEAMIMPACT_SOURCE) / "verification/scenes/paper/s1_central.toml", "paper",
            o);
  constexpr std::size_t kBlock = std::size_t{24} << 20;
  const std::size_t mapped_before = mallinfo2().hblkhd;
  char* p = static_cast<char*>(std::malloc(kBlock));
  ASSERT_NE(p, nullptr);
  static_cast<volatile char*>(p)[0] = 1;  // used: the allocation is not optimised away
  EXPECT_GE(mallinfo2().hblkhd, mapped_before + kBlock)
      << "a 24 MB block came from the heap: the run changed glibc's mmap threshold";
  std::free(p);
#endif
}

}  // namespace
}  // namespace beamimpact
