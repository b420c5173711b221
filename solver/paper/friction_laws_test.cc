// Coulomb friction under every contact law (the paper's hard law and the Hertz law) against the
// sliding block of elementary mechanics: a rigid block (1 kg) pressed on an immovable rigid floor
// by gravity g and launched along it at v0 decelerates at mu g until it stops at t_s = v0 / (mu g)
// after v0^2 / (2 mu g), and then stays at rest (Meriam and Kraige, Engineering Mechanics:
// Dynamics, section 3/4).
//
// The block is a horizontal rigid rod (1 m, 1 kg) released 1 um above the floor, whose contact
// node is its centre (node 1 of 2 elements), so neither the floor's push nor the friction has a
// moment about the centre: the block translates. It lands at sqrt(2 g h) = 4.5 mm/s. The discrete
// scheme's momentum is exact whatever the normal force does (the closure impulse of the hard law,
// the bounces on the Hertz spring): every step's impulses add up, so while the block slides
//   m (v_x(t) - v0) = -mu int R dt = -mu m (v_y(t) + g t)
// on every row, to roundoff, and |tau| = mu R on every sliding row (|tau| <= mu R on every row).
#include <solver/paper/solve.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include <solver/scene/scene_io.hpp>

namespace beamimpact::paper {
namespace {

constexpr double kG = 10.0, kMu = 0.3, kV0 = 1.0, kM = 1.0;  // m/s^2, -, m/s, kg
constexpr double kHertzK = 1e6;                              // N/m^1.5
constexpr double kDt = 1e-4, kEnd = 0.5;                     // s: the block stops at 1/3 s
constexpr double kDrop = 1e-6;                               // m: the gap at t = 0

/// @brief The tail of a scene that puts a striker on an immovable rigid floor along y = 0: the
/// floor body (one element from x = -2 m to floor_end, held at its start) and the contact of the
/// striker's node with it, Coulomb friction kMu, under the law (the Hertz law with kHertzK).
/// @param striker the striking body's name
/// @param node the contact node as TOML text: an index ("1") or a quoted end ("\"end\"")
/// @param law "hard" (the paper's law) or "hertz"
/// @param floor_end m, the x of the floor's end
std::string on_rigid_floor(const std::string& striker, const std::string& node, const std::string& law,
                           const std::string& floor_end) {
  std::ostringstream t;
  t.precision(17);
  t << "[[bodies]]\nname = \"floor\"\nstart = [-2.0, 0.0]\nend = [" << floor_end
    << ", 0.0]\nelements = 1\nE = 1e9\nrho = 1.0\narea = 1.0\nrigid = true\n"
       "supports = [{ at = \"start\", fix = [\"x\", \"y\", \"theta\"] }]\n"
    << "[[contacts]]\nstriker = \"" << striker << "\"\nnode = " << node
    << "\ntarget = \"floor\"\nfriction = " << kMu << "\n";
  if (law == "hertz") t << "law = \"hertz\"\nstiffness = " << kHertzK << "\n";
  return t.str();
}

/// The block with its centre (and its axis) at height kDrop above the floor y = 0, under the law.
std::string sliding_block(const std::string& law) {
  std::ostringstream t;
  t.precision(17);
  t << "name = \"sliding_block\"\n[time]\ndt = " << kDt << "\nend = " << kEnd
    << "\noutput_every = 10\n[loads]\ngravity = [0.0, " << -kG << "]\n"
    << "[[bodies]]\nname = \"block\"\nstart = [-0.5, " << kDrop << "]\nend = [0.5, " << kDrop
    << "]\nelements = 2\nE = 1e9\nrho = " << kM << "\narea = 1.0\nvelocity = [" << kV0
    << ", 0.0]\nsupports = []\nrigid = true\n"
    << on_rigid_floor("block", "1", law, "2.0");
  return t.str();
}

/// Runs the block and checks Coulomb's law row by row and the closed-form stop.
void check_sliding_block(const std::string& law) {
  SCOPED_TRACE(law);
  const SimulationResult r = solve(load_scene_text(sliding_block(law), "sliding_block.toml"));
  ASSERT_GT(r.history.size(), 100u);
  const double t_stop = kV0 / (kMu * kG);
  bool sliding = true;  // every row so far open or slipping
  double first_stick = -1.0, vy_max = 0.0, uy_max = 0.0;
  long slip_rows = 0;
  for (const HistoryRow& row : r.history) {
    const ContactSample& c = row.contacts.at(0);
    // Coulomb's law on every row (the roundoff of mu R: relative 1e-12).
    EXPECT_LE(std::abs(c.tau), kMu * c.R * (1 + 1e-12)) << "t " << row.t;
    vy_max = std::max(vy_max, std::abs(c.va[1]));
    uy_max = std::max(uy_max, std::abs(c.ua[1]));
    if (c.state == ContactState::kStick && first_stick < 0.0) first_stick = row.t;
    sliding = sliding && (c.state == ContactState::kSlip || c.state == ContactState::kOpen);
    if (!sliding) continue;
    if (c.state == ContactState::kSlip) {
      ++slip_rows;
      // Sliding forward: the friction on the block points back, at its full value mu R.
      EXPECT_NEAR(c.tau, -kMu * c.R, 1e-12 * kMu * c.R) << "t " << row.t;
    }
    // The momentum account above: roundoff of 5000 steps of velocities of order 1 (1e-10 m/s).
    EXPECT_NEAR(c.va[0] - kV0, -kMu * (c.va[1] + kG * row.t), 1e-10) << "t " << row.t;
  }
  EXPECT_GT(slip_rows, 250) << "the block slides about 1/3 s (330 rows)";
  // The stop: v_x = v0 - mu g t - mu v_y reaches 0 within mu max|v_y| / (mu g) of t_s, seen on
  // the next output row (10 steps).
  ASSERT_GT(first_stick, 0.0) << "the block never stops";
  EXPECT_NEAR(first_stick, t_stop, vy_max / kG + 10 * kDt + 1e-12);
  const ContactSample& last = r.history.back().contacts.at(0);
  EXPECT_EQ(last.state, ContactState::kStick);
  // At rest (roundoff of the stick step's velocity).
  EXPECT_NEAR(last.va[0], 0.0, 1e-10);
  // Distance: int v_x dt = v0 t - mu g t^2 / 2 - mu u_y(t) up to the stop, which the bounce moves
  // by at most max|v_y| / g from t_s (a second-order change of the distance at its maximum:
  // mu max|v_y|^2 / (2 g)); within one step's travel at v0 on each end of the slide.
  EXPECT_NEAR(last.ua[0], kV0 * kV0 / (2 * kMu * kG),
              kMu * (uy_max + vy_max * vy_max / (2 * kG)) + 2 * kV0 * kDt);
}

// The hard law closes the gap at landing (an inelastic closure) and holds it: R = m g.
TEST(Friction, BlockSlidingOnTheHardLawStopsAtV0OverMuG) { check_sliding_block("hard"); }

// The Hertz law: the block lands on a spring R = k delta^(3/2) (k = 1e6 N/m^1.5: m g compresses
// it by 0.46 mm) and rides it, bouncing; the momentum account holds through every bounce.
TEST(Friction, BlockSlidingOnTheHertzLawStopsAtV0OverMuG) { check_sliding_block("hertz"); }

// A tilted rigid rod (1 m, 1 kg, 45 degrees) strikes a rigid floor with its lower end while it
// moves fast along it, so it slides through the whole impact. The end is off the centre, so the
// normal force turns the rod and moves the end along the floor (the contact's normal and
// tangential responses are coupled: the stick trial's normal force is not the slip's). Whatever
// the normal law does, sliding friction is mu R at every instant, so the impulses of the impact
// satisfy I_t = -mu I_n, and the centre's momentum (summary final_velocity: the bodies' momentum
// over their mass, not the contact rows) obeys
//   m (v_x - v0_x) = -mu m (v_y - v0_y).
void check_tilted_rod_sliding(const std::string& law) {
  SCOPED_TRACE(law);
  constexpr double kVx = 5.0, kVy = -1.0, kH = 1e-3;  // m/s, m/s, m: the end's drop to the floor
  const double s = std::sqrt(0.5);
  std::ostringstream t;
  t.precision(17);
  t << "name = \"tilted_rod\"\n[time]\ndt = 1e-5\nend = 0.03\noutput_every = 1\n"
    << "[[bodies]]\nname = \"rod\"\nstart = [0.0, " << kH + s << "]\nend = [" << s << ", " << kH
    << "]\nelements = 1\nE = 1e9\nrho = 1.0\narea = 1.0\nvelocity = [" << kVx << ", " << kVy
    << "]\nsupports = []\nrigid = true\n"
    << on_rigid_floor("rod", "\"end\"", law, "4.0");
  const SimulationResult r = solve(load_scene_text(t.str(), "tilted_rod.toml"));
  long slip_rows = 0;
  for (const HistoryRow& row : r.history) {
    const ContactSample& c = row.contacts.at(0);
    // The premise: the end slides forward through the whole impact (never sticks).
    ASSERT_NE(c.state, ContactState::kStick) << "t " << row.t;
    if (c.state == ContactState::kSlip) ++slip_rows;
  }
  // The hard law closes the gap in one step (one slipping row); the Hertz spring over many.
  ASSERT_GE(slip_rows, law == "hard" ? 1 : 20) << "the rod never slid on the floor";
  ASSERT_EQ(r.history.back().contacts.at(0).state, ContactState::kOpen) << "the impact has not ended";
  const Vec2 v = r.final_velocity.at("rod");
  ASSERT_GT(v[1] - kVy, 0.1) << "the floor did not push the rod up";
  // Roundoff of the momentum sums over 3000 steps of velocities of order 1: 1e-10 m/s. A slip
  // friction taken from another normal force than the one applied moves v_x by a few percent of
  // mu (v_y - v0_y), about 1e-2 m/s.
  EXPECT_NEAR(v[0] - kVx, -kMu * (v[1] - kVy), 1e-10);
}

TEST(Friction, TiltedRodSlidingOnTheHardLawLosesMuTimesItsNormalImpulse) { check_tilted_rod_sliding("hard"); }

TEST(Friction, TiltedRodSlidingOnTheHertzLawLosesMuTimesItsNormalImpulse) {
  check_tilted_rod_sliding("hertz");
}

}  // namespace
}  // namespace beamimpact::paper
