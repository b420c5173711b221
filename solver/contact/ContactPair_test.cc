// The struck point against the geometry of a turned target: the rows close the gap along the
// target's normal n, so the gap they measure must be the distance along n to the deformed chord.
#include <solver/contact/ContactPair.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include <solver/model/Model.hpp>
#include <solver/testing/turned_chord.hpp>

namespace beamimpact::paper {
namespace {

using testing::strike_next_to_the_pin;
using testing::turned_chord;

// B's first element turned about the pin (node 1 down by 0.6 m: 31 deg) and the striker d below
// that chord, straight under its reference position (a prediction that penetrates). Along n (up)
// the striker is d below the chord point under it, at xi = 0.5: the row's gap is -d and the point
// stays at xi = 0.5. The chord's own perpendicular foot instead lies d sin cos along the chord
// (xi 0.5044) and the row reads -d cos^2 = -0.735 d: a correction along n then leaves the striker
// d sin^2 below the chord. Tolerance: roundoff of metre-sized coordinates.
TEST(ContactPair, StrikerBelowATurnedChordKeepsThePointUnderIt) {
  const Scene s = strike_next_to_the_pin();
  const Model model(s, true);
  ContactPair pair(model, s, 0);
  ASSERT_EQ(pair.element(), 0);
  const double d = 0.01;
  const Eigen::VectorXd U = turned_chord(model, pair.striker_node(), -0.6, 0.0, d);
  pair.relocate(U);
  EXPECT_EQ(pair.element(), 0);
  EXPECT_NEAR(pair.xi2(), 0.5, 1e-14);
  EXPECT_NEAR(pair.g0() + ContactPair::eval(pair.normal_row(), U), -d, 1e-14);
}

// The same turned chord with the striker on it, moved along the target to x = 0.7: the point
// follows to xi = 0.7 with a zero gap (both readings agree on the chord itself).
TEST(ContactPair, StrikerOnATurnedChordIsClosedWhereItStands) {
  const Scene s = strike_next_to_the_pin();
  const Model model(s, true);
  ContactPair pair(model, s, 0);
  const Eigen::VectorXd U = turned_chord(model, pair.striker_node(), -0.6, 0.2, 0.0);
  EXPECT_TRUE(pair.relocate(U));
  EXPECT_NEAR(pair.xi2(), 0.7, 1e-14);
  EXPECT_NEAR(pair.g0() + ContactPair::eval(pair.normal_row(), U), 0.0, 1e-14);
}

}  // namespace
}  // namespace beamimpact::paper
