// The thread team: every part of every job runs exactly once, parts run at the same time on
// different threads, and run() returns only when all parts have returned (the barrier), also
// after the workers have gone to sleep.
#include <solver/util/ThreadTeam.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace beamimpact {
namespace {

using Clock = std::chrono::steady_clock;

/// Busy for about `us` microseconds (a part that is still running when the others are done).
void busy(int us) {
  const auto until = Clock::now() + std::chrono::microseconds(us);
  while (Clock::now() < until) {
  }
}

/// Waits (busy) until `flag` is set or 5 s have passed (a machine too loaded to schedule the
/// worker at all): true when it was set.
bool wait_for(const std::atomic<bool>& flag) {
  const auto until = Clock::now() + std::chrono::seconds(5);
  while (!flag.load() && Clock::now() < until) {
  }
  return flag.load();
}

TEST(ThreadTeam, EveryPartRunsOncePerJob) {
  for (int size : {1, 2, 3}) {
    ThreadTeam team(size);
    EXPECT_EQ(team.size(), size);
    std::vector<long> runs(size, 0);
    auto job = [&](int t) { ++runs[t]; };  // each part writes only its own entry
    for (int j = 0; j < 2000; ++j) team.run(job);
    for (int t = 0; t < size; ++t) EXPECT_EQ(runs[t], 2000) << "part " << t << " of " << size;
  }
}

TEST(ThreadTeam, PartsRunAtTheSameTimeOnDifferentThreads) {
  // Part 0 holds its thread until part 1 has started, so part 1 can only start on the other
  // thread, whichever of the caller and the worker claims part 0 (either may be first).
  ThreadTeam team(2);
  std::atomic<bool> started{false};
  std::thread::id part0, part1;
  bool seen = false;
  auto job = [&](int t) {
    if (t == 0) {
      part0 = std::this_thread::get_id();
      seen = wait_for(started);
    } else {
      part1 = std::this_thread::get_id();
      started = true;
    }
  };
  team.run(job);
  EXPECT_TRUE(seen) << "part 1 did not start while part 0 ran";
  EXPECT_NE(part0, part1);
}

TEST(ThreadTeam, RunReturnsOnlyWhenEveryPartHasReturned) {
  // Part 1 (on a worker: part 0 waits until it has started) takes 300 us after part 0 is done:
  // without the barrier, run() returns before its result is there.
  ThreadTeam team(2);
  for (int j = 1; j <= 20; ++j) {
    std::atomic<bool> started{false};
    int done = 0;
    auto job = [&](int t) {
      if (t == 0) {
        (void)wait_for(started);
        return;
      }
      started = true;
      busy(300);
      done = j;
    };
    team.run(job);
    EXPECT_EQ(done, j);
  }
}

TEST(ThreadTeam, SleepingWorkersWakeForTheNextJob) {
  // After an idle pause far beyond the spin (the workers sleep in a futex), the next jobs still
  // run every part on a worker, and return after them.
  ThreadTeam team(3);
  for (int j = 1; j <= 3; ++j) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::atomic<int> started{0};
    std::vector<int> done(3, 0);
    auto job = [&](int t) {
      ++started;
      const auto until = Clock::now() + std::chrono::seconds(5);
      while (started.load() < 3 && Clock::now() < until) {  // all three parts at once
      }
      busy(100);
      done[t] = j;
    };
    team.run(job);
    EXPECT_EQ(started.load(), 3);
    for (int t = 0; t < 3; ++t) EXPECT_EQ(done[t], j) << "part " << t;
  }
}

TEST(ThreadTeam, RangesCoverEveryIndexOnceInNearlyEqualParts) {
  // 7 indices on 3 parts: [0, 2), [2, 4), [4, 7) (part t from n t / 3 rounded down); 2 indices
  // leave one range empty; without a team the one range is [0, n).
  ThreadTeam team(3);
  for (const int n : {7, 2}) {
    std::mutex mutex;
    std::vector<std::pair<long long, long long>> ranges;
    run_ranges(&team, n, [&](long long first, long long last) {
      const std::lock_guard<std::mutex> lock(mutex);
      ranges.emplace_back(first, last);
    });
    std::sort(ranges.begin(), ranges.end());
    using R = std::vector<std::pair<long long, long long>>;
    const R expected = n == 7 ? R{{0, 2}, {2, 4}, {4, 7}} : R{{0, 0}, {0, 1}, {1, 2}};
    EXPECT_EQ(ranges, expected) << n;
  }
  long long first = -1, last = -1;
  run_ranges(nullptr, 5, [&](long long a, long long b) { first = a, last = b; });
  EXPECT_EQ(first, 0);
  EXPECT_EQ(last, 5);
}

// ordered_sum's bits depend on the length only: without a team and on teams of 2 and 3 threads
// (parts taking the chunks in different orders) the same bits, for lengths inside one chunk, at
// a chunk's edge and over several; and the sum is the sum (against a long double sum of the
// same terms: roundoff of 1e5 terms of order 1, 1e-11).
TEST(ThreadTeam, OrderedSumHasTheSameBitsOnEveryTeam) {
  std::vector<double> x(5 * kSumChunk + 17);
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = std::sin(0.37 * static_cast<double>(i)) + 1e-3 * static_cast<double>(i);
  ThreadTeam two(2), three(3);
  std::vector<double> scratch;
  for (const long long n : {100LL, kSumChunk, kSumChunk + 1, static_cast<long long>(x.size())}) {
    auto sum = [&](long long first, long long last) {
      double s = 0.0;
      for (long long i = first; i < last; ++i) s += x[i];
      return s;
    };
    const double alone = ordered_sum(nullptr, n, scratch, sum);
    EXPECT_EQ(ordered_sum(&two, n, scratch, sum), alone) << n;
    EXPECT_EQ(ordered_sum(&three, n, scratch, sum), alone) << n;
    long double exact = 0.0L;
    for (long long i = 0; i < n; ++i) exact += x[i];
    EXPECT_NEAR(alone, static_cast<double>(exact), 1e-11 * std::abs(static_cast<double>(exact))) << n;
  }
}

// Three sums in one pass (an output row's kinetic energy, strain energy and momentum) give each
// the bits of its own ordered_sum, on every team: one pass changes the hand-overs, not the numbers.
TEST(ThreadTeam, OrderedSumsGiveEachSumTheBitsOfItsOwnOrderedSum) {
  std::vector<double> x(4 * kSumChunk + 5);
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = std::cos(0.11 * static_cast<double>(i)) + 1e-4 * static_cast<double>(i);
  const auto term = [&](int j, long long i) {
    return j == 0 ? x[i] : j == 1 ? x[i] * x[i] : (i % 7 == 0 ? -x[i] : 0.0);
  };
  ThreadTeam two(2), three(3);
  std::vector<double> scratch;
  const long long n = static_cast<long long>(x.size());
  for (ThreadTeam* team : {static_cast<ThreadTeam*>(nullptr), &two, &three}) {
    double total[3] = {0.0, 0.0, 0.0};
    ordered_sums(team, n, 3, scratch, total, [&](long long first, long long last, double* out) {
      for (int j = 0; j < 3; ++j) {
        double s = 0.0;
        for (long long i = first; i < last; ++i) s += term(j, i);
        out[j] = s;
      }
    });
    for (int j = 0; j < 3; ++j) {
      const double alone = ordered_sum(nullptr, n, scratch, [&](long long first, long long last) {
        double s = 0.0;
        for (long long i = first; i < last; ++i) s += term(j, i);
        return s;
      });
      EXPECT_EQ(total[j], alone) << "sum " << j << " on " << (team ? team->size() : 1) << " thread(s)";
    }
  }
}

}  // namespace
}  // namespace beamimpact
