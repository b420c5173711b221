// The merge rule on hand-made phase sequences whose intervals follow from the rule's statement:
// a phase beginning less than merge_gap after the last interval's end joins it.
#include <solver/record/ContactIntervals.hpp>

#include <gtest/gtest.h>

namespace beamimpact {
namespace {

using Phases = std::vector<std::array<double, 2>>;

Phases merged(const Phases& phases, double merge_gap) {
  ContactIntervals iv(merge_gap);
  for (const auto& [start, end] : phases) {
    iv.begin(start);
    iv.extend(end);
  }
  return iv.intervals();
}

TEST(ContactIntervals, GapShorterThanMergeGapJoins) {
  // Gaps 0.5 (joins at 1.0) and 2.0 (splits): two intervals [0, 3] and [5, 6].
  EXPECT_EQ(merged({{0.0, 1.0}, {1.5, 3.0}, {5.0, 6.0}}, 1.0), (Phases{{0.0, 3.0}, {5.0, 6.0}}));
}

TEST(ContactIntervals, GapEqualToMergeGapSplits) {
  // The rule is "less than": a gap of exactly merge_gap (0.5, exact in binary) opens a new interval.
  EXPECT_EQ(merged({{0.0, 1.0}, {1.5, 2.0}}, 0.5), (Phases{{0.0, 1.0}, {1.5, 2.0}}));
}

TEST(ContactIntervals, ZeroGapMergesNothingAndChainsJoin) {
  EXPECT_EQ(merged({{0.0, 0.0}, {1.0, 1.0}}, 0.0), (Phases{{0.0, 0.0}, {1.0, 1.0}}));
  // Each gap (0.25) is measured from the grown interval's end, so a chain of chatter is one interval.
  EXPECT_EQ(merged({{0.0, 0.25}, {0.5, 0.75}, {1.0, 1.25}}, 0.3), (Phases{{0.0, 1.25}}));
}

TEST(ContactIntervals, BeginTellsWhetherAPhaseOpensAnInterval) {
  ContactIntervals iv(1.0);
  EXPECT_TRUE(iv.begin(0.0));
  iv.extend(2.0);
  EXPECT_FALSE(iv.begin(2.5));  // 0.5 after the end
  EXPECT_TRUE(iv.begin(4.0));   // 1.5 after the end (2.5)
  EXPECT_EQ(iv.size(), 2u);
}

}  // namespace
}  // namespace beamimpact
