// The rigid-rod impact's motion after the impact against the contact condition it must meet
// (references.md section 3): with restitution e the contact end leaves the surface at e V along
// the normal (Newton's rule at the contact point), and in stick it does not slide. The end is l/2
// from the centre, so its velocity is (v_t - omega (l/2) s, v_n + omega (l/2) c) in the
// (tangential, normal) axes of RigidRodImpact.
#include <references/exact/RigidRodImpact.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace beamimpact::exact {
namespace {

TEST(RigidRodImpact, ContactEndLeavesAtRestitutionTimesApproachAndStickDoesNotSlide) {
  const double m = 1.0, l = 1.0, theta = std::acos(-1.0) / 6, V = 1.0;  // the rigid_rod_oblique scene
  const double s = std::sin(theta), c = std::cos(theta);
  for (double e : {0.0, 0.5})
    for (double mu : {0.0, 0.3, 1.5}) {
      const RigidRodImpact r = rigid_rod_impact(m, l, theta, V, mu, e);
      EXPECT_NEAR(r.v_n + r.omega * (l / 2) * c, e * V, 1e-14) << "mu " << mu << " e " << e;
      if (r.stick) EXPECT_NEAR(r.v_t - r.omega * (l / 2) * s, 0.0, 1e-14) << "mu " << mu << " e " << e;
    }
}

}  // namespace
}  // namespace beamimpact::exact
