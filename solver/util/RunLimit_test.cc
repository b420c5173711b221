// A RunLimit holds the runs of its thread only: check() passes before the budget is spent and
// throws RunStopped after it or after an interruption, and an inner limit gives way to the outer
// one when it ends.
#include <chrono>
#include <cmath>
#include <thread>

#include <gtest/gtest.h>

#include <solver/util/RunLimit.hpp>

namespace beamimpact {
namespace {

TEST(RunLimit, ChecksStopARunOnlyPastItsBudgetOrOnAnInterruption) {
  RunLimit::check();  // no limit: nothing to stop
  EXPECT_TRUE(std::isinf(RunLimit::seconds_left()));
  {
    const RunLimit outer(3600.0, [] { return 0; });
    RunLimit::check();  // an hour left
    EXPECT_GT(RunLimit::seconds_left(), 3500.0);
    {
      const RunLimit inner(0.05, [] { return 0; });
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      EXPECT_EQ(RunLimit::seconds_left(), 0.0);
      EXPECT_THROW(RunLimit::check(), RunStopped);
    }
    RunLimit::check();  // the outer hour again
    int signal = 0;
    const RunLimit interrupted(3600.0, [&] { return signal; });
    RunLimit::check();
    signal = 2;
    try {
      RunLimit::check();
      ADD_FAILURE() << "an interrupted run went on";
    } catch (const RunStopped& e) {
      EXPECT_STREQ(e.what(), "interrupted by signal 2");
    }
  }
  // Another thread never sees this thread's limit.
  const RunLimit spent(1e-9, {});
  std::thread([] { EXPECT_NO_THROW(RunLimit::check()); }).join();
  EXPECT_THROW(RunLimit::check(), RunStopped);
  EXPECT_THROW(RunLimit(0.0, {}), std::invalid_argument);
}

}  // namespace
}  // namespace beamimpact
