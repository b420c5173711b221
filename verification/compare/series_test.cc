// Building blocks of the norms, against closed forms.
#include <verification/compare/series.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace beamimpact::verification {
namespace {

TEST(Series, UniformGridNeverExceedsStep) {
  const auto g = uniform_grid(0.0, 1.0, 0.3);
  ASSERT_EQ(g.size(), 5u);  // 4 steps of 0.25 <= 0.3
  EXPECT_DOUBLE_EQ(g.back(), 1.0);
}

TEST(Series, InterpolationIsExactForLines) {
  const std::vector<double> t{0, 1, 3}, y{1, 3, 7};  // y = 2 t + 1
  const auto v = interpolate(t, y, {0.5, 2.0, 2.9});
  EXPECT_DOUBLE_EQ(v[0], 2.0);
  EXPECT_DOUBLE_EQ(v[1], 5.0);
  EXPECT_NEAR(v[2], 6.8, 1e-15);
}

TEST(Series, RunningIntegralOfLineIsExact) {
  std::vector<double> t, y;
  for (int i = 0; i <= 10; ++i) {
    t.push_back(0.1 * i);
    y.push_back(3.0 * 0.1 * i);
  }
  const auto I = running_integral(t, y);  // trapezoid is exact for linear integrands: 1.5 t^2
  EXPECT_NEAR(I.back(), 1.5, 1e-14);
  EXPECT_NEAR(I[5], 1.5 * 0.25, 1e-14);
}

TEST(Series, L2NormOfConstantVector) {
  const std::vector<double> t{0, 0.5, 2};
  const Series s{{3, 3, 3}, {4, 4, 4}};  // |s| = 5 on [0, 2]: sqrt(25 * 2)
  EXPECT_NEAR(l2_norm(t, s), std::sqrt(50.0), 1e-14);
  EXPECT_DOUBLE_EQ(linf_norm(s), 5.0);
}

TEST(Series, WindowAverageOfConstantIsConstantInside) {
  std::vector<double> t, y;
  for (int i = 0; i <= 100; ++i) {
    t.push_back(0.01 * i);
    y.push_back(2.0);
  }
  const auto w = window_average(t, running_integral(t, y), 0.1, {0.5, 0.0});
  EXPECT_NEAR(w[0], 2.0, 1e-12);
  EXPECT_NEAR(w[1], 1.0, 1e-12);  // half the window lies before the record: y = 0 there
}

}  // namespace
}  // namespace beamimpact::verification
