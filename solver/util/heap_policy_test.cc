// keep_freed_memory(): freed blocks of 16 MB (a state vector of 2e6 doubles, a model of about
// 2e6 DOFs) stay in the process as free heap, so that the next run reuses its pages instead of
// faulting new ones in. glibc's mallinfo2() says where the block came from and what is kept;
// with glibc's defaults each block is mapped on its own (blocks over 128 kB) and unmapped when
// freed, and without the trim threshold all but 64 MB of free heap would go back.
#include <solver/util/heap_policy.hpp>

#include <cstddef>
#include <cstdlib>

#include <gtest/gtest.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#if defined(__SANITIZE_ADDRESS__)
#define BEAMIMPACT_OWN_ALLOCATOR 1  // GCC's AddressSanitizer: its allocator, not glibc's
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BEAMIMPACT_OWN_ALLOCATOR 1  // clang's
#endif
#endif

namespace beamimpact {
namespace {

TEST(HeapPolicy, FreedLargeBlockStaysInTheProcess) {
#if !defined(__GLIBC__) || defined(BEAMIMPACT_OWN_ALLOCATOR)
  GTEST_SKIP() << "not glibc's allocator (a sanitizer's or another C library's): mallopt has no effect";
#else
  keep_freed_memory();
  keep_freed_memory();  // idempotent
  // Six blocks of 16 MB, 96 MB in all: more than the 64 MB the heap grows by, which a trim
  // would keep.
  constexpr std::size_t kBlock = std::size_t{16} << 20;
  constexpr int kBlocks = 6;
  char* blocks[kBlocks];
  for (char*& p : blocks) {
    p = static_cast<char*>(std::malloc(kBlock));
    ASSERT_NE(p, nullptr);
    static_cast<char* volatile>(p)[0] = 1;  // used: the allocation is not optimised away
  }
  const struct mallinfo2 held = mallinfo2();
  EXPECT_LT(held.hblkhd, kBlock) << "the blocks were mapped on their own: they would be unmapped when freed";
  for (char* p : blocks) std::free(p);
  const struct mallinfo2 freed = mallinfo2();
  EXPECT_GE(freed.fordblks, kBlocks * kBlock) << "the freed blocks were given back to the system";
#endif
}

}  // namespace
}  // namespace beamimpact
