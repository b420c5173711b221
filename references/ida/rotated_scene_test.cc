// IDA on a scene and its rotated copy with the target's roller across it (fix = ["normal"]):
// one problem, so one answer, through the shared model's node axes.
#include <references/ida/solve.hpp>

#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>

namespace beamimpact::ida {
namespace {

// IDA's steps are adaptive: the rotated copy's roundoff (1e-15 relative) moves its step
// choices, and each run is accurate to its tolerances (rtol 1e-8), so the two answers differ by
// the integration error, not by roundoff: measured 6e-8 relative in impulse, 5e-10 s in the
// contact times. Bounds: 1e-6 relative (100 rtol: the global error of two runs over about a
// hundred steps of contact) and 1e-6 s (root finding to ~rtol on a 1 s scale, with the same
// margin). The peak force is read after each touch's closure window (5 cn/kn, where the
// dashpot's jump decays): a touch time moved by the integration error (5e-10 s) moves the window's
// end, and R still falls steeply there, so the peak moves by more than the impulse does: measured
// 7.4e-6 relative at 37 deg; bound 2e-5 (a wrong axis in the rotation moves it by percent).
TEST(RotatedSceneIda, BodyAxisRollerGivesTheSameAnswerAt37And90Degrees) {
  const SimulationResult s2 = ida::solve(testing::load_paper_scene("s2_transverse"));
  const ContactSummary& a = s2.contacts.at(0);
  ASSERT_EQ(a.intervals.size(), 2u);  // S2's two collisions in 3 s
  for (double degrees : {37.0, 90.0}) {
    const ContactSummary b = ida::solve(testing::rotated_s2(degrees)).contacts.at(0);
    EXPECT_NEAR(b.impulse_normal, a.impulse_normal, 1e-6 * a.impulse_normal) << degrees << " deg";
    EXPECT_NEAR(b.peak_R, a.peak_R, 2e-5 * a.peak_R) << degrees << " deg";
    ASSERT_EQ(b.intervals.size(), a.intervals.size()) << degrees << " deg";
    for (std::size_t i = 0; i < a.intervals.size(); ++i)
      for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(b.intervals[i][k], a.intervals[i][k], 1e-6) << degrees << " deg";
  }
}

}  // namespace
}  // namespace beamimpact::ida
