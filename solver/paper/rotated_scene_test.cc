// A scene and its rotated copy are one problem when the supports turn with the body (a roller
// across the target: fix = ["normal"]): the paper integrator gives the same contact intervals,
// impulse and peak force. A roller left in global axes is another problem, and shows.
#include <solver/paper/solve.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include <solver/model/Effects.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::paper {
namespace {

// Rotating a problem changes no scalar of its answer. The rotated copy differs only by the
// roundoff of its coordinates (cos, sin to 1 ulp) and of the element matrices' rotation
// (to_global and the node axes' T^T K T): relative 1e-15 per operation, grown by 300 steps of a
// stable scheme; 1e-12 relative leaves room for that (measured 3.4e-15 at 37 deg, 0 at 90 deg,
// where cos and sin are exact). Contact intervals are whole steps: equal to 1e-12 s.
void expect_same_answer(const SimulationResult& a, const SimulationResult& b, double degrees) {
  const ContactSummary &ca = a.contacts.at(0), &cb = b.contacts.at(0);
  EXPECT_NEAR(cb.impulse_normal, ca.impulse_normal, 1e-12 * ca.impulse_normal) << degrees << " deg";
  EXPECT_NEAR(cb.peak_R, ca.peak_R, 1e-12 * ca.peak_R) << degrees << " deg";
  ASSERT_EQ(cb.intervals.size(), ca.intervals.size()) << degrees << " deg";
  for (std::size_t i = 0; i < ca.intervals.size(); ++i)
    for (int k = 0; k < 2; ++k)
      EXPECT_NEAR(cb.intervals[i][k], ca.intervals[i][k], 1e-12) << degrees << " deg";
  EXPECT_NEAR(b.energy_final, a.energy_final, 1e-12 * a.energy_initial) << degrees << " deg";
}

TEST(RotatedScene, BodyAxisRollerGivesTheSameAnswerAt37And90Degrees) {
  const SimulationResult s2 = solve(testing::load_paper_scene("s2_transverse"));
  ASSERT_EQ(s2.contacts.at(0).intervals.size(), 2u);  // S2's two collisions in 3 s
  for (double degrees : {37.0, 90.0}) expect_same_answer(s2, solve(testing::rotated_s2(degrees)), degrees);
}

// The global roller ("y") on the target rotated by 90 degrees holds it along its axis: with the
// pin at its start, nothing holds it across, and it swings about the pin. At 37 degrees the
// roller's slant still changes the answer by far more than roundoff (measured 4e-4 in impulse).
TEST(RotatedScene, GlobalRollerOnTheRotatedTargetIsAnotherProblem) {
  const SimulationResult s2 = solve(testing::load_paper_scene("s2_transverse"));
  for (double degrees : {37.0, 90.0}) {
    const SimulationResult g = solve(testing::rotated_s2(degrees, true));
    EXPECT_GT(std::abs(g.contacts.at(0).impulse_normal - s2.contacts.at(0).impulse_normal),
              1e-6 * s2.contacts.at(0).impulse_normal)
        << degrees << " deg";
  }
}

// Corotational kinematics forms its element forces in global axes: a body it rebuilds (held at
// one node only, so free to turn) with a roller in the axes of that inclined body is refused,
// naming the support's key; the simply supported target (held at two nodes) stays linear and runs.
TEST(RotatedScene, CorotationalRefusesABodyAxisRollerOnABodyItTurns) {
  Scene s = testing::rotated_s2(37.0);
  s.model.kinematics = Kinematics::kCorotational;
  EXPECT_NO_THROW(derive_effects(s));
  s.bodies[1].supports.erase(s.bodies[1].supports.begin());  // no pin: held at one node, B can turn
  try {
    derive_effects(s);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "bodies[1].supports[0].fix");
    EXPECT_NE(std::string(e.what()).find("model.kinematics = \"linear\""), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace beamimpact::paper
