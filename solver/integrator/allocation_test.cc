// The time-stepping loop allocates nothing: every vector it touches exists before the first step.
// Global operator new is replaced in this test program to count allocations while stepping.
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include <solver/integrator/ExplicitContactIntegrator.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  if (counting) ++allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace beamimpact::paper {
namespace {

/// Allocations in `steps` steps after `warm_up` steps (which may size buffers at a first contact).
long allocations_while_stepping(const std::string& path, const std::vector<std::string>& sets, int steps,
                                int warm_up, SurfaceInterpolation surface = SurfaceInterpolation::kLinear) {
  const Scene s = load_scene(path, sets);
  const Effects fx = derive_effects(s);
  const Model m(s, fx.bending);
  ExplicitContactIntegrator in(m, s, fx, s.time.dt ? *s.time.dt : 5e-5, surface);
  for (int p = 0; p < warm_up; ++p) in.step();
  allocations = 0;
  counting = true;
  int contact = 0;
  for (int p = 0; p < steps; ++p) {
    contact += in.forces()[0].R > 0;
    in.step();
  }
  counting = false;
  EXPECT_GT(contact, 0) << path << ": the counted steps must include contact";
  return allocations;
}

TEST(Allocation, LumpedSteppingAllocatesNothing) {
  // Rods (S1 from 0.3 s: contact starts at 0.5 s), frames with a struck node (S2), frames with a
  // sliding, sticking and slipping point and corotation (S4 at 45 deg).
  using testing::paper_scene;
  EXPECT_EQ(allocations_while_stepping(paper_scene("s1_central"), {}, 30, 30), 0);
  EXPECT_EQ(allocations_while_stepping(paper_scene("s2_transverse"), {}, 40, 40), 0);
  EXPECT_EQ(allocations_while_stepping(paper_scene("s4_oblique_45"), {}, 160, 160), 0);
  EXPECT_EQ(allocations_while_stepping(paper_scene("s4_oblique_45"), {"model.kinematics=linear"}, 160, 160),
            0);
}

TEST(Allocation, TheLongestContactRowsFitTheirBuffersFromTheStart) {
  // A rigid striker node projects onto 3 equations (x, y and its body's rotation lever); on a
  // Hermite surface each target node adds its rotation: a normal row of 9 terms here (11 on a
  // rigid target). Counted from the first step, so the first contact may not grow a buffer.
  // The rod falls 0.01 m at 1 m/s onto a tilted elastic cantilever (a tilted normal: both
  // translations count): contact from about 0.01 s (dt 5e-6 s, below its critical step).
  const std::string scene =
      (testing::source_dir() / "verification/scenes/extra/rigid_rod_oblique.toml").string();
  for (const char* friction : {"0", "0.3"})
    EXPECT_EQ(allocations_while_stepping(scene,
                                         {"bodies.B.rigid=false", "bodies.B.inertia=0.08",
                                          "bodies.B.start=[-2.0, -0.2]", "bodies.B.end=[2.0, 0.2]",
                                          "time.dt=5e-6", std::string("contacts[0].friction=") + friction},
                                         2400, 0, SurfaceInterpolation::kHermite),
              0)
        << "friction " << friction;
}

}  // namespace
}  // namespace beamimpact::paper
