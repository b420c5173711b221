// A study point measures each method's run against the point's reference, not the reverse: S1
// solved exactly at A's speed 1 m/s against the exact S1 at 2 m/s. The exact S1 (a 4 kg rod
// striking an equal one end-on) transfers A's whole momentum: impulse 4 v N s, a force of 2 v N
// for 2 s (references.md: the 1D wave solution). The run's errors against the reference are
// |4 - 8| / 8 = 0.5 in impulse and |2 - 4| / 4 = 0.5 in peak force; the reference measured
// against the run would give 1.
#include <verification/study/run_point.hpp>

#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>

namespace beamimpact::study {
namespace {

TEST(StudyPoint, EachMethodIsMeasuredAgainstThePointsReference) {
  Study s;
  s.name = "asymmetric";
  s.scene = testing::paper_scene("s1_central");
  s.file = testing::temp_path("study.toml");
  s.methods = {"exact"};
  s.reference = {"exact", {"bodies.A.velocity=[2.0, 0.0]"}};
  s.norms = {"impulse", "peak_R"};
  const PointResult r = run_point(s, Point{}, 0, testing::temp_path("runs"));
  ASSERT_EQ(r.reference_status, "ok") << r.reference_message;
  ASSERT_EQ(r.cases.size(), 1u);
  const CaseResult& c = r.cases[0];
  ASSERT_EQ(c.status, "ok") << c.message;
  ASSERT_EQ(c.norms.size(), 2u);
  // The exact solutions' impulses and forces are exact to roundoff; 1e-9 relative covers it.
  ASSERT_TRUE(c.norms[0] && c.norms[1]);
  EXPECT_NEAR(*c.norms[0], 0.5, 1e-9);
  EXPECT_NEAR(*c.norms[1], 0.5, 1e-9);
}

}  // namespace
}  // namespace beamimpact::study
