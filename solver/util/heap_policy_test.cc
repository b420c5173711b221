// keep_freed_memory(): freed blocks of 16 MB (a state vector of 2e6 doubles, a model of about
// 2e6 DOFs) stay in the process as free heap, so that the next run reuses its pages instead of
// faulting new ones in. glibc's mallinfo2() says where the block came from and what is kept;
// with glibc's defaults each block is mapped on its own (blocks over 128 kB) and unmapped when
// freed, and without the trim threshold all but 64 MB of free heap would go back.
#include <solver/util/heap_policy.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace beamimpact {
namespace {

/// The VmFlags line of the mapping that holds address `a` (/proc/self/smaps), "" when none does.
std::string mapping_flags(const void* a) {
  const std::uintptr_t x = reinterpret_cast<std::uintptr_t>(a);
  std::ifstream smaps("/proc/self/smaps");
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-' && line.find(':') > line.find(' ')) {
      inside = lo <= x && x < hi;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return line + " ";
  }
  return "";
}

TEST(HeapPolicy, FreedLargeBlockStaysInTheProcess) {
  if (!glibc_heap())
    GTEST_SKIP() << "not glibc's allocator (a sanitizer's or another C library's): the policy does nothing";
#if defined(__GLIBC__)
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
    static_cast<volatile char*>(p)[0] = 1;  // used: the allocation is not optimised away
  }
  const struct mallinfo2 held = mallinfo2();
  EXPECT_LT(held.hblkhd, kBlock) << "the blocks were mapped on their own: they would be unmapped when freed";
  for (char* p : blocks) std::free(p);
  const struct mallinfo2 freed = mallinfo2();
  EXPECT_GE(freed.fordblks, kBlocks * kBlock) << "the freed blocks were given back to the system";
#endif
}

// reserve_heap(): the heap grows by the reservation at once (free heap, nothing mapped on its
// own), a second call of the same size does not grow it again, and a block allocated from
// it lies in memory advised for transparent huge pages (VmFlags "hg" in /proc/self/smaps).
TEST(HeapPolicy, ReservationIsFreeHeapAdvisedForHugePages) {
  if (!glibc_heap())
    GTEST_SKIP() << "not glibc's allocator (a sanitizer's or another C library's): the policy does nothing";
#if defined(__GLIBC__)
  constexpr std::size_t kReserve = std::size_t{256} << 20;
  reserve_heap(static_cast<double>(kReserve));
  const struct mallinfo2 reserved = mallinfo2();
  EXPECT_GE(reserved.fordblks, kReserve) << "the heap's free memory is less than the reservation";
  EXPECT_LT(reserved.hblkhd, kReserve) << "the reservation was mapped on its own";
  reserve_heap(static_cast<double>(kReserve));
  EXPECT_EQ(mallinfo2().arena, reserved.arena) << "a second reservation of the same size grew the heap";
  char* volatile p = static_cast<char*>(std::malloc(std::size_t{16} << 20));
  ASSERT_NE(p, nullptr);
  p[0] = 1;
  EXPECT_NE(mapping_flags(p + (std::size_t{8} << 20)).find(" hg "), std::string::npos)
      << "not advised for huge pages: " << mapping_flags(p);
  std::free(p);
#endif
}

}  // namespace
}  // namespace beamimpact
