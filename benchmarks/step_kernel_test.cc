/// @file step_kernel_test.cc
/// @brief The benchmark yardstick is a stable step: central difference below the critical step
/// conserves a modified energy, so the displacement of the chain stays of the order of its
/// initial value over many steps (an unstable step grows like |lambda|^k and leaves this bound
/// after a few hundred steps).
#include "step_kernel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

TEST(StepKernel, RodAndFrameStayBoundedOverTwentyThousandSteps) {
  for (bool frame : {false, true}) {
    beamimpact::bench::StepKernel k(200, frame);
    const double u0 = max_abs(k.displacement());
    for (int i = 0; i < 20000; ++i) k.step();
    // Bound 10x: the initial field is a smooth sine whose modes keep their amplitude; 10x leaves
    // room for their superposition and is far below any unstable growth.
    EXPECT_LT(max_abs(k.displacement()), 10.0 * u0) << (frame ? "frame" : "rod");
    EXPECT_EQ(k.dofs(), frame ? 603u : 201u);
  }
}

}  // namespace
