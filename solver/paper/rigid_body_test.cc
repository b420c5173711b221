// Rigid bodies: a rigid rod falling without spin onto an immovable rigid surface with
// Coulomb friction, against the closed form of references.md section 3 (restitution 0).
#include <solver/paper/solve.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include <solver/model/Model.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::paper {
namespace {

std::string rigid_scene() {
  return (testing::source_dir() / "verification/scenes/extra/rigid_rod_oblique.toml").string();
}

// The closed form for the scene's rod: 1 kg, 1 m, 30 deg to the surface, V = 1 m/s.
constexpr double kS = 0.5, kC = 0.86602540378443865, kM = 1.0, kV = 1.0;
double mu_star() { return 3 * kS * kC / (1 + 3 * kS * kS); }
std::pair<double, double> closed_form(double mu) {
  if (mu >= mu_star()) {
    const double pn = kM * kV * (1 + 3 * kS * kS) / 4;
    return {pn, pn * mu_star()};
  }
  const double pn = kM * kV / (1 + 3 * kC * kC - 3 * kS * kC * mu);
  return {pn, mu * pn};
}

// Below, at and above the stick threshold, and at three closure phases (the rod shifted up by
// f V dt: the contact closes f dt later within its step). The paper's closure is a plastic
// impact (restitution 0) and with small rotations the contact rows are constant, so once the
// gap and (for stick) the slide are closed the contact point's velocity is exactly zero: the
// impulse is the closed form's to roundoff (1e-9 relative: ~200 steps of 1e-16 updates), in one
// or two steps.
TEST(RigidBodies, ObliqueRodOnARigidSurfaceMatchesTheClosedForm) {
  const double dt = 1e-4;
  for (double mu : {0.0, 0.3, 0.5 * mu_star(), mu_star(), 1.5}) {
    for (double f : {0.0, 0.3, 0.7}) {
      Scene s = load_scene(rigid_scene());
      s.contacts[0].friction = mu;
      for (Vec2* x : {&s.bodies[0].start, &s.bodies[0].end}) (*x)[1] += f * kV * dt;
      const SimulationResult r = solve(s);
      const auto [pn, pt] = closed_form(mu);
      EXPECT_NEAR(r.contacts[0].impulse_normal, pn, 1e-9 * pn) << "mu " << mu << " f " << f;
      EXPECT_NEAR(r.contacts[0].impulse_tangential, pt, 1e-9 * pn) << "mu " << mu << " f " << f;
      EXPECT_EQ(r.contacts[0].intervals.size(), 1u) << "one impact";
    }
  }
}

// Momentum drift with a known value: the surface is immovable (its support takes every impulse),
// so the total momentum changes by the rod's alone, p(t) - p(0) = -(pt, pn) summed over the
// impact, and after it the rod flies free (one impact): momentum_drift_max is |(pt, pn)| of the
// closed form, both components non-zero (to roundoff, as the impulses above).
TEST(RigidBodies, MomentumDriftIsTheSupportsImpulse) {
  for (double mu : {0.3, 1.5}) {
    Scene s = load_scene(rigid_scene());
    s.contacts[0].friction = mu;
    const SimulationResult r = solve(s);
    const auto [pn, pt] = closed_form(mu);
    EXPECT_NEAR(r.momentum_drift_max, std::hypot(pn, pt), 1e-9 * pn) << "mu " << mu;
  }
}

// A rigid body's nodes follow its centre: a rotation theta moves the end at r = (L/2)(cos a,
// sin a) from the centre by theta (-r_y, r_x); its mass is rho A L with inertia m L^2 / 12, and
// it has no stiffness. An elastic-body key (inertia) is not needed.
TEST(RigidBodies, NodesFollowTheCentreAndMassIsTheRodsOwn) {
  const Scene s = load_scene(rigid_scene());
  const Model m(s, true);
  EXPECT_TRUE(m.rigid(0));
  EXPECT_EQ(m.size(), 3);  // the rod's centre (x, y, theta); the surface is immovable
  EXPECT_DOUBLE_EQ(m.body_mass(0), 1.0);
  EXPECT_EQ(m.K().nonZeros(), 0);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(3);
  const int th = m.equation(m.node_id(0, 0), 2);
  ASSERT_GE(th, 0);
  U(th) = 1e-3;
  const Vec2 u = m.node_vector(U, m.node_id(0, 0));  // lower end: r = -(L/2)(c, s)
  EXPECT_NEAR(u[0], -1e-3 * (-0.5 * kS), 1e-15);
  EXPECT_NEAR(u[1], 1e-3 * (-0.5 * kC), 1e-15);
  const Eigen::VectorXd md = Eigen::VectorXd(m.M().diagonal());
  EXPECT_NEAR(md(th), 1.0 / 12.0, 1e-15);
}

// A rigid body is free or immovable: a partial support is refused, naming the key.
TEST(RigidBodies, PartialSupportIsRefused) {
  try {
    load_scene(rigid_scene(), {"bodies.B.supports=[{ at = \"start\", fix = [\"y\"] }]"});
    FAIL() << "expected a InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "bodies[1].supports") << e.what();
  }
}

}  // namespace
}  // namespace beamimpact::paper
