// IDA with Coulomb friction on a soft target whose struck point moves along the target's axis,
// against the paper's integrator on the same beam model: the striker of slide_off_roller (20 deg,
// E = 100 Pa) slides along the simply supported B with mu = 0.5, dragging B's surface along its
// axis (B's roller end lets it stretch), in two contact intervals. Only there does IDA's
// struck-point kinematics (the material point under the striker, followed through B's axial
// displacement) act: the frictionless and transverse scenes of ida_vs_paper_test never move it.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <references/ida/solve.hpp>
#include <solver/paper/solve.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact::ida {
namespace {

Scene friction_scene(std::vector<std::string> extra) {
  extra.push_back("contacts[0].friction=0.5");
  return load_scene(testing::hard_scene("slide_off_roller"), extra);
}

// The paper at dt0 = 0.005 s and dt0/2 against IDA near the paper's contact law (restitution
// 0.001, kn = 1e4 EA/le, rtol 1e-8, as ida_vs_paper_test). Measured (impulse relative to IDA's
// 0.13874 N s; interval ends in paper steps):
//   dt0:   impulse 3.4e-3, first end 1.62 dt, second end 1.50 dt
//   dt0/2: impulse 1.9e-3, first end 1.24 dt, second end 2.01 dt
//   (dt0/4: 5.9e-4; dt0/8: 1.8e-5: the difference is the paper's first-order time stepping.)
// Bounds: the impulse within 5e-3 at dt0 (1.5 x measured) and shrinking with dt by at least
// 0.75 (first order gives 0.5; measured 0.55); each interval end within 3 dt (the paper's end is
// its last step with R > 0 and its forward multiplier releases up to half a step early: 1.5 dt,
// plus IDA's release through the regularised friction and penalty, measured up to 0.5 dt more).
// An IDA struck point that follows B's axial displacement with the wrong sign moves IDA's impulse
// by 1.8 % and its second release by 38 ms: 1.5e-2 and 6.1 dt from the paper at dt0, outside
// both bounds.
// Not bounded: the second interval's start, where IDA's penalty touches 15-22 ms before the paper
// closes at every dt (0.535 s against 0.550-0.5575 s): a graze the paper's gap prediction does
// not close, not a difference that shrinks with dt.
TEST(IdaFrictionSoftTarget, SlideOffTheRollerAgreesWithThePaper) {
  const SimulationResult ida =
      ida::solve(friction_scene({"ida.restitution=0.001", "ida.kn_factor=1e4", "ida.rtol=1e-8"}));
  const ContactSummary& ci = ida.contacts.at(0);
  ASSERT_EQ(ci.intervals.size(), 2u);
  ASSERT_GT(std::abs(ci.impulse_tangential), 0.4 * ci.impulse_normal) << "friction must act (slip: mu R)";
  double dI0 = 0.0;
  for (int k = 0; k <= 1; ++k) {
    const double dt = 0.005 / (1 << k);
    const SimulationResult paper = paper::solve(
        friction_scene({"time.dt=" + std::to_string(dt), "time.output_every=" + std::to_string(1 << k)}));
    const ContactSummary& cp = paper.contacts.at(0);
    ASSERT_EQ(cp.intervals.size(), 2u) << "dt " << dt;
    const double dI = std::abs(cp.impulse_normal - ci.impulse_normal) / ci.impulse_normal;
    std::printf("dt %.4g: impulse %.3e relative, ends %.2f and %.2f dt\n", dt, dI,
                std::abs(cp.intervals[0][1] - ci.intervals[0][1]) / dt,
                std::abs(cp.intervals[1][1] - ci.intervals[1][1]) / dt);
    if (k == 0) {
      EXPECT_LT(dI, 5e-3);
      dI0 = dI;
    } else {
      EXPECT_LT(dI, 0.75 * dI0) << "the difference must shrink with the paper's step";
    }
    EXPECT_NEAR(cp.intervals[0][1], ci.intervals[0][1], 3.0 * dt) << "first release, dt " << dt;
    EXPECT_NEAR(cp.intervals[1][1], ci.intervals[1][1], 3.0 * dt) << "second release, dt " << dt;
    EXPECT_NEAR(cp.impulse_tangential / cp.impulse_normal, ci.impulse_tangential / ci.impulse_normal, 0.01)
        << "slip throughout: |It| = mu In for both (IDA's regularisation: |tau| < mu R)";
  }
}

}  // namespace
}  // namespace beamimpact::ida
