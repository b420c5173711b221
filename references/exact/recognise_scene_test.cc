// Scene recognition: what the exact method accepts, and the condition named when it refuses.
#include <references/exact/recognise_scene.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::exact {
namespace {

using beamimpact::testing::benchmark_scene;
using beamimpact::testing::paper_scene;

// Expects a InputError whose key is `key` and whose message contains `text`.
void expect_refused(const Scene& s, const std::string& key, const std::string& text) {
  try {
    recognise_scene(s);
    ADD_FAILURE() << "accepted, expected refusal: " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), key);
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

TEST(RecogniseScene, PaperScenes) {
  const ExactProblem s1 = recognise_scene(load_scene(paper_scene("s1_central")));
  EXPECT_EQ(s1.kind, ExactKind::kCoaxialRods);
  EXPECT_DOUBLE_EQ(s1.gap, 0.5);
  EXPECT_DOUBLE_EQ(s1.v0, 1.0);
  EXPECT_EQ(s1.contact_kind, ContactKind::kEndToEnd);

  const ExactProblem s2 = recognise_scene(load_scene(paper_scene("s2_transverse")));
  EXPECT_EQ(s2.kind, ExactKind::kRodOnBeam);
  EXPECT_NEAR(s2.gap, 0.1, 1e-15);
  EXPECT_NEAR(s2.x_c, 5.0, 1e-15);
  EXPECT_DOUBLE_EQ(s2.v0, 1.0);
  EXPECT_EQ(s2.contact_kind, ContactKind::kNodeToNode);

  EXPECT_EQ(recognise_scene(load_scene(paper_scene("s3_surface_10"))).contact_kind,
            ContactKind::kNodeToSurface);
  EXPECT_EQ(recognise_scene(load_scene(paper_scene("s3_surface_20"))).contact_kind, ContactKind::kNodeToNode);
  EXPECT_NEAR(recognise_scene(load_scene(paper_scene("s3_surface_10"))).x_c, 4.5, 1e-15);

  expect_refused(load_scene(paper_scene("s4_oblique_45")), "contacts[0].friction", "friction is not zero");
  // Without friction, the 45-degree striker is still oblique to the beam.
  expect_refused(load_scene(paper_scene("s4_oblique_45"), {"contacts[0].friction=0"}), "bodies[0].end",
                 "not perpendicular");
  EXPECT_EQ(recognise_scene(load_scene(paper_scene("s4_oblique_90"), {"contacts[0].friction=0"})).kind,
            ExactKind::kRodOnBeam);
}

TEST(RecogniseScene, RefusesWhatItCannotSolve) {
  const Scene s2 = load_scene(paper_scene("s2_transverse"));
  Scene s = s2;
  s.bodies[1].supports[0].fix_theta = true;  // clamped end
  expect_refused(s, "bodies[1].supports", "not simply supported");
  s = s2;
  s.bodies[1].supports.pop_back();  // cantilever-like: one support only
  expect_refused(s, "bodies[1].supports", "not simply supported");
  s = s2;
  s.bodies[0].velocity = {0.3, -1.0};
  expect_refused(s, "bodies[0].velocity", "not along its own axis");
  s = s2;
  s.bodies[1].velocity = {0.0, 0.5};
  expect_refused(s, "bodies[1].velocity", "not at rest");
  s = s2;
  s.model.rayleigh_mass = 0.1;
  expect_refused(s, "model.rayleigh_mass", "damping is not zero");
  s = s2;
  s.bodies[0].supports.push_back(Support{0, true, true, false});
  expect_refused(s, "bodies[0].supports", "striker has supports");
  s = s2;
  s.contacts.push_back(s.contacts[0]);
  expect_refused(s, "contacts", "exactly one contact");
  s = s2;  // rod moved onto the support line x = 0
  s.bodies[0].start = {0.0, 5.1};
  s.bodies[0].end = {0.0, 0.1};
  expect_refused(s, "bodies[1].start", "not strictly between");

  const Scene s1 = load_scene(paper_scene("s1_central"));
  s = s1;
  s.bodies[1].start = {10.5, 1.0};  // parallel but offset
  s.bodies[1].end = {20.5, 1.0};
  expect_refused(s, "bodies[1].start", "not coaxial");
  s = s1;
  s.bodies[1].velocity = {0.0, 0.2};
  expect_refused(s, "bodies[1].velocity", "not along the common axis");
}

// A coaxial target with one support at its far end holding the axial displacement is a rod
// clamped there; any other support on a coaxial target is refused, naming the supports.
TEST(RecogniseScene, CoaxialTargetClampedAtItsFarEnd) {
  Scene s = load_scene(benchmark_scene("two_rods_second_contact"));
  const ExactProblem p = recognise_scene(s);
  EXPECT_EQ(p.kind, ExactKind::kCoaxialRods);
  EXPECT_EQ(p.target_far_end, FarEnd::kFixed);
  EXPECT_DOUBLE_EQ(p.gap, 0.5);
  EXPECT_EQ(recognise_scene(load_scene(paper_scene("s1_central"))).target_far_end, FarEnd::kFree);
  const Scene clamped = s;
  s.bodies[1].supports[0] = Support{0, true, true, true};  // at the struck end instead
  expect_refused(s, "bodies[1].supports", "one support at its far end");
  s = clamped;
  s.bodies[1].supports[0].fix_x = false;  // holds y and theta only: axially free
  expect_refused(s, "bodies[1].supports", "holding the axial");
  s = clamped;
  s.bodies[1].supports[0] = Support{14, false, false, false, /*axial*/ true, false};  // fix = ["axial"]
  EXPECT_EQ(recognise_scene(s).target_far_end, FarEnd::kFixed);
  s.bodies[1].supports[0] = Support{14, false, false, false, false, /*normal*/ true};  // across the axis
  expect_refused(s, "bodies[1].supports", "holding the axial");
  s = clamped;
  s.bodies[1].supports.push_back(Support{3, false, true, false});
  expect_refused(s, "bodies[1].supports", "one support at its far end");
  s = clamped;
  s.bodies[1].velocity = {0.3, 0.0};
  expect_refused(s, "bodies[1].velocity", "fixed at its far end but not at rest");
}

}  // namespace
}  // namespace beamimpact::exact

namespace beamimpact::exact {
namespace {

// Timoshenko's ball on a beam: a rigid striker with the Hertz law on a simply supported beam. Its
// mass is rho A L of the rigid body (4/3 pi r^3 rho for r = 20 mm of steel) and k = 4/3 E* sqrt(r)
// from the contact's radius and modulus (Johnson 1985, Eq. 4.22).
TEST(RecogniseScene, BallOnBeamWithTheHertzLaw) {
  const Scene scene =
      load_scene((testing::source_dir() / "verification/scenes/extra/ball_on_beam.toml").string());
  const ExactProblem p = recognise_scene(scene);
  EXPECT_EQ(p.kind, ExactKind::kBallOnBeam);
  const double r = 0.02, rho = 7800.0, pi = 3.14159265358979323846;
  EXPECT_NEAR(p.mass, 4.0 / 3.0 * pi * r * r * r * rho, 1e-12);
  EXPECT_NEAR(p.hertz_stiffness, 4.0 / 3.0 * 2.1e11 / (2.0 * (1.0 - 0.09)) * std::sqrt(r),
              1e-6 * p.hertz_stiffness);
  EXPECT_NEAR(p.x_c, 0.5, 1e-15);
  EXPECT_NEAR(p.gap, 1e-4, 1e-15);
  EXPECT_DOUBLE_EQ(p.v0, 1.0);
  EXPECT_EQ(p.contact_kind, ContactKind::kNodeToNode);
  // The Hertz law anywhere else has no exact solution here: a flexible striker (S2), or a rigid
  // striker on a rigid target.
  expect_refused(
      load_scene(paper_scene("s2_transverse"), {"contacts[0].law=hertz", "contacts[0].stiffness=50"}),
      "contacts[0].law", "rigid striker");
  expect_refused(load_scene((testing::source_dir() / "verification/scenes/extra/hertz_drop.toml").string()),
                 "contacts[0].law", "rigid striker");
}

}  // namespace
}  // namespace beamimpact::exact

namespace beamimpact::exact {
namespace {

// A rod end-on onto a simply supported Timoshenko beam is solved with the Timoshenko beam's
// modes: the target's shear coefficient and G = E / (2 (1 + nu)) are passed on; the striker's
// theory does not enter (struck end-on it carries axial waves only). A Timoshenko body in any other
// problem is refused naming its theory.
TEST(RecogniseScene, RodOnTimoshenkoBeam) {
  const std::string file =
      (testing::source_dir() / "verification/scenes/extra/s2_stocky_timoshenko.toml").string();
  const ExactProblem p = recognise_scene(load_scene(file));
  EXPECT_EQ(p.kind, ExactKind::kRodOnBeam);
  EXPECT_DOUBLE_EQ(p.shear.kappa, 5.0 / 6.0);
  EXPECT_DOUBLE_EQ(p.shear.G, 50.0);  // E / 2 with nu = 0
  EXPECT_FALSE(recognise_scene(load_scene(paper_scene("s2_transverse"))).shear.timoshenko());
  const std::string stocky = (testing::source_dir() / "verification/scenes/extra/s2_stocky.toml").string();
  EXPECT_EQ(recognise_scene(load_scene(stocky, {"bodies.B.theory=timoshenko"})).shear.G, 100.0 / 2.6);
  expect_refused(load_scene(paper_scene("s1_central"), {"bodies.B.theory=timoshenko"}), "bodies[1].theory",
                 "rod striking a simply supported beam");
  expect_refused(load_scene((testing::source_dir() / "verification/scenes/extra/ball_on_beam.toml").string(),
                            {"bodies.B.theory=timoshenko"}),
                 "bodies[1].theory", "ball-on-beam");
}

}  // namespace
}  // namespace beamimpact::exact
