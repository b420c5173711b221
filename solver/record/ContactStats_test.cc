// Interval, impulse and peak bookkeeping on hand-made force sequences with known answers.
#include <solver/record/ContactStats.hpp>

#include <gtest/gtest.h>

namespace beamimpact {
namespace {

ContactSummary feed(const std::vector<double>& R, double dt, int merge_steps) {
  ContactStats s((merge_steps + 0.5) * dt, "rule");
  for (std::size_t i = 0; i < R.size(); ++i)
    s.add(static_cast<double>(i) * dt, R[i], 0.0, dt, R[i] > 0 ? ContactState::kClosed : ContactState::kOpen);
  ContactSummary out;
  s.fill(out);
  return out;
}

TEST(ContactStats, ImpulsePeaksAndClosure) {
  const ContactSummary c = feed({0, 0, 10, 2, 3, 2, 0, 0}, 0.5, 3);
  ASSERT_EQ(c.intervals.size(), 1u);
  EXPECT_DOUBLE_EQ(c.intervals[0][0], 1.0);
  EXPECT_DOUBLE_EQ(c.intervals[0][1], 2.5);
  EXPECT_DOUBLE_EQ(c.impulse_normal, (10 + 2 + 3 + 2) * 0.5);
  EXPECT_DOUBLE_EQ(c.peak_R, 10);
  EXPECT_DOUBLE_EQ(c.first_step_R, 10);
  EXPECT_DOUBLE_EQ(c.peak_R_excluding_closure, 3);  // the closure step is left out
}

TEST(ContactStats, ShortGapsMergeLongGapsSplit) {
  // Merge rule "fewer than 3 open steps": 2 open steps merge, 3 open steps split.
  EXPECT_EQ(feed({1, 1, 0, 0, 1, 1}, 1.0, 3).intervals.size(), 1u);
  EXPECT_EQ(feed({1, 1, 0, 0, 0, 1, 1}, 1.0, 3).intervals.size(), 2u);
  EXPECT_EQ(feed({1, 0, 1}, 1.0, 0).intervals.size(), 2u);  // no merging at all
  EXPECT_EQ(feed({0, 0, 0}, 1.0, 3).intervals.size(), 0u);
}

}  // namespace
}  // namespace beamimpact
