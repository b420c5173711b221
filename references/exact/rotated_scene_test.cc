// The rod-on-beam solution recognises S2 rotated with its target's supports in the target's own
// axes (pin + roller across it) as S2, and refuses the copy whose roller stays in global axes.
#include <references/exact/recognise_scene.hpp>
#include <references/exact/solve.hpp>

#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::exact {
namespace {

// S2's data (docs/paper-scenes.md): gap 0.1 m, struck at x_c = 5 m of the 10 m target, v0 =
// 1 m/s, node to node. The rotated copy's coordinates carry roundoff of cos and sin (1 ulp of
// 10 m): 1e-13 m on the lengths, 1e-15 on the speed.
TEST(RotatedSceneExact, BodyAxisRollerIsTheSimplySupportedBeam) {
  for (double degrees : {37.0, 90.0}) {
    const ExactProblem p = recognise_scene(testing::rotated_s2(degrees));
    EXPECT_EQ(p.kind, ExactKind::kRodOnBeam) << degrees;
    EXPECT_NEAR(p.gap, 0.1, 1e-13) << degrees;
    EXPECT_NEAR(p.x_c, 5.0, 1e-13) << degrees;
    EXPECT_NEAR(p.v0, 1.0, 1e-15) << degrees;
    EXPECT_EQ(p.contact_kind, ContactKind::kNodeToNode) << degrees;
  }
}

// The solution depends on the scene only through the recognised data, so the rotated copy's
// answer is S2's to the roundoff above propagated through the event location (1e-9 relative:
// the events are found to ~1e-12 s and the modal sums agree to 1e-13; measured 3e-15).
TEST(RotatedSceneExact, RotatedCopyHasTheSameImpulseAndContactTimes) {
  const ContactSummary a = solve(testing::load_paper_scene("s2_transverse")).contacts.at(0);
  const ContactSummary b = solve(testing::rotated_s2(37.0)).contacts.at(0);
  EXPECT_NEAR(b.impulse_normal, a.impulse_normal, 1e-9 * a.impulse_normal);
  ASSERT_EQ(b.intervals.size(), a.intervals.size());
  for (std::size_t i = 0; i < a.intervals.size(); ++i)
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(b.intervals[i][k], a.intervals[i][k], 1e-9);
}

// A roller in global axes ("y") on the inclined target holds a slanted direction (37 deg) or
// its axis (90 deg): not a simple support of the beam, so not this solution.
TEST(RotatedSceneExact, GlobalRollerOnTheRotatedTargetIsRefused) {
  for (double degrees : {37.0, 90.0}) {
    try {
      recognise_scene(testing::rotated_s2(degrees, true));
      ADD_FAILURE() << degrees << " deg: accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "bodies[1].supports") << degrees;
      EXPECT_NE(std::string(e.what()).find("not simply supported"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace beamimpact::exact
