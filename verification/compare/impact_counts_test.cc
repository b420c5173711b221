// Impact counts of the paper integrator against the exact solutions' (no golden numbers): the
// number of separate collisions is the paper's headline claim for S2. Both runs' contact
// intervals are merged with one gap in seconds, so the count is the physical one and does not
// depend on a merge rule in steps.
// S3 is not here: the continuum's second contact starts at 2.86 s, close to the 3 s end, and the
// beam models miss or split it (S3_10: none; S3_20: struck at 2.07, 2.21 and 2.59 s), the beam
// model's mesh error in the late bending response. Against IDA on the same mesh the counts agree
// (matrix rows and references/ida/ida_vs_paper_test.cc).

#include <array>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <api/run.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact::verification {
namespace {

/// Intervals closer than gap seconds joined into one; returns the count.
std::size_t merged_count(const std::vector<std::array<double, 2>>& in, double gap) {
  std::size_t n = 0;
  double last_end = -1e300;
  for (const auto& iv : in) {
    if (iv[0] - last_end >= gap) ++n;
    last_end = iv[1];
  }
  return n;
}

std::string list(const std::vector<std::array<double, 2>>& in) {
  std::string s;
  for (const auto& iv : in) s += "[" + std::to_string(iv[0]) + ", " + std::to_string(iv[1]) + "] ";
  return s.empty() ? "(none)" : s;
}

struct CountCase {
  const char* scene;
  double dt;  ///< s, paper step
};

void PrintTo(const CountCase& c, std::ostream* os) { *os << c.scene << " dt=" << c.dt; }

class ImpactCounts : public ::testing::TestWithParam<CountCase> {};

TEST_P(ImpactCounts, PaperCountsTheExactSolutionsCollisions) {
  const CountCase& k = GetParam();
  const std::string file = testing::paper_scene(k.scene);
  // 0.035 s: above the paper's chatter at closure (bounces of one or two steps at dt = 0.01) and
  // far below the separation of real collisions (S2: the striker leaves at ~1.1 s and returns at
  // ~2 s).
  constexpr double kMergeGap = 0.035;
  const SimulationResult exact = run(file, "exact");
  const SimulationResult paper = run(file, "paper", {.set = {"time.dt=" + std::to_string(k.dt)}, .out = {}});
  const auto& ie = exact.contacts.at(0).intervals;
  const auto& ip = paper.contacts.at(0).intervals;
  std::printf("%s dt=%g: paper %s| exact %s\n", k.scene, k.dt, list(ip).c_str(), list(ie).c_str());
  ASSERT_FALSE(ie.empty());
  EXPECT_EQ(merged_count(ip, kMergeGap), merged_count(ie, kMergeGap))
      << k.scene << " dt=" << k.dt << " (merge gap " << kMergeGap << " s): paper " << list(ip) << ", exact "
      << list(ie);
}

INSTANTIATE_TEST_SUITE_P(PaperScenes, ImpactCounts,
                         ::testing::Values(CountCase{"s1_central", 0.01}, CountCase{"s1_central", 0.0025},
                                           CountCase{"s2_transverse", 0.01},
                                           CountCase{"s2_transverse", 0.0025}),
                         [](const ::testing::TestParamInfo<CountCase>& i) {
                           return std::string(i.param.scene) + "_" + std::to_string(i.index);
                         });

}  // namespace
}  // namespace beamimpact::verification
