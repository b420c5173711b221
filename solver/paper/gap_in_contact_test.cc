// The gap under force: a striker strikes B's first element next to its pin, where the element
// turns by over 0.6 rad. Measured here from U after every step against the deformed chord
// (model/deformed_geometry), never from the solver's rows.
#include <solver/paper/gap_in_contact.hpp>

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include <solver/integrator/ExplicitContactIntegrator.hpp>
#include <solver/paper/solve.hpp>
#include <solver/testing/turned_chord.hpp>

namespace beamimpact::paper {
namespace {

using testing::strike_next_to_the_pin;

// Frictionless, lumped mass, a vertical striker: the step's correction moves the striker and B's
// nodes along the normal only, so with the struck point on the striker's line along the normal
// the corrected striker lies on the chord exactly; 1e-12 m is roundoff of metre-sized coordinates
// over a thousand-fold margin. Relocating to the chord's perpendicular foot left it 4e-4 m below.
TEST(GapInContact, StrikeNextToThePinStaysOnTheChordWhileRIsPositive) {
  const Scene s = strike_next_to_the_pin();
  const Effects fx = derive_effects(s);
  const Model model(s, fx.bending);
  ExplicitContactIntegrator in(model, effective_scene(s, fx), fx, *s.time.dt);
  DeformedSurface chords(model, 1, in.pairs()[0].striker_node(), Centreline::kChord);
  double worst = 1e300, turn = 0.0;
  long loaded = 0;
  const long N = std::lround(s.time.end / *s.time.dt);
  for (long p = 0; p < N; ++p) {
    in.step();
    if (!(in.forces()[0].R > 0.0)) continue;
    ++loaded;
    const RealGap g = chords.gap(in.U());
    worst = std::min(worst, g.gap);
    turn = std::max(turn, std::abs(chords.turn(in.U(), g.element, g.xi)));
  }
  EXPECT_GT(loaded, 50);  // the contact lasts about 1 s of 0.01 s steps
  EXPECT_GT(turn, 0.5);   // rad: the first element turns about the pin
  EXPECT_GT(worst, -1e-12);
}

// The run's summary says the same: the least gap under force, its time inside the contact
// interval, and no warning.
TEST(GapInContact, SummaryReportsTheGapUnderForce) {
  const SimulationResult r = solve(strike_next_to_the_pin());
  const nlohmann::json& c = r.contacts[0].extra;
  ASSERT_TRUE(c.contains("real_gap_in_contact_min"));
  EXPECT_GT(c["real_gap_in_contact_min"].get<double>(), -1e-12);  // as above
  const double t = c["real_gap_in_contact_min_time"].get<double>();
  EXPECT_GE(t, r.contacts[0].intervals.front()[0]);
  EXPECT_LE(t, r.contacts[0].intervals.back()[1]);
  for (const auto& w : r.extra.value("warnings", nlohmann::json::array()))
    EXPECT_EQ(w.get<std::string>().find("inside the target"), std::string::npos) << w;
}

// A striker placed d straight below B's first element turned by atan 0.6 about the pin: its
// distance from the chord is d cos(atan 0.6) = d / sqrt(1.36) (geometry; roundoff tolerance).
// Counted only while R > 0; reported with its time and a warning (1 mm >> 1e-9 x 10 m).
TEST(GapInContact, ReportsAndWarnsAPenetrationUnderForce) {
  const Scene s = strike_next_to_the_pin();
  const Model model(s, true);
  const std::vector<ContactPair> pairs{ContactPair(model, s, 0)};
  GapInContact gap(model, s, pairs, SurfaceInterpolation::kLinear);
  auto below = [&](double d) { return testing::turned_chord(model, pairs[0].striker_node(), -0.6, 0.0, d); };
  std::vector<ContactForce> f(1);
  gap.track(0, {0}, f, below(5e-3), 0.3);  // open (R = 0): not counted
  f[0].R = 1.0;
  gap.track(0, {0}, f, below(1e-3), 0.5);
  gap.track(0, {0}, f, below(1e-4), 0.6);
  SimulationResult r;
  r.contacts.resize(1);
  gap.report(s, r);
  const nlohmann::json& c = r.contacts[0].extra;
  EXPECT_NEAR(c["real_gap_in_contact_min"].get<double>(), -1e-3 / std::sqrt(1.36), 1e-15);
  EXPECT_EQ(c["real_gap_in_contact_min_time"].get<double>(), 0.5);
  ASSERT_EQ(r.extra["warnings"].size(), 1u);
  const std::string w = r.extra["warnings"][0].get<std::string>();
  EXPECT_NE(w.find("contact A -> B"), std::string::npos) << w;
  EXPECT_NE(w.find("0.000857 m inside the target"), std::string::npos) << w;
}

}  // namespace
}  // namespace beamimpact::paper
