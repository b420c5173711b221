// The time-stepping loop allocates nothing: every vector it touches exists before the first step.
// Global operator new is replaced in this test program to count allocations while stepping.
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include <beamimpact/integrator/ExplicitContactIntegrator.hpp>
#include <beamimpact/scene/scene_io.hpp>
#include <beamimpact/testing/test_scenes.hpp>

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

long allocations_while_stepping(const std::string& scene, const std::vector<std::string>& sets, int steps) {
  const Scene s = load_scene(testing::paper_scene(scene), sets);
  const Effects fx = derive_effects(s);
  const Model m(s, fx.bending);
  ExplicitContactIntegrator in(m, s, fx, s.time.dt ? *s.time.dt : 5e-5);
  // Warm-up: the first contact sizes the row buffers once.
  for (int p = 0; p < steps; ++p) in.step();
  allocations = 0;
  counting = true;
  int contact = 0;
  for (int p = 0; p < steps; ++p) {
    contact += in.forces()[0].R > 0;
    in.step();
  }
  counting = false;
  EXPECT_GT(contact, 0) << scene << ": the counted steps must include contact";
  return allocations;
}

TEST(Allocation, LumpedSteppingAllocatesNothing) {
  // Rods (S1 from 0.3 s: contact starts at 0.5 s), frames with a struck node (S2), frames with a
  // sliding, sticking and slipping point and corotation (S4 at 45 deg).
  EXPECT_EQ(allocations_while_stepping("s1_central", {}, 30), 0);
  EXPECT_EQ(allocations_while_stepping("s2_transverse", {}, 40), 0);
  EXPECT_EQ(allocations_while_stepping("s4_oblique_45", {}, 160), 0);
  EXPECT_EQ(allocations_while_stepping("s4_oblique_45", {"model.kinematics=linear"}, 160), 0);
}

}  // namespace
}  // namespace beamimpact::paper
