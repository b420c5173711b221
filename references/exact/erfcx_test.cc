// erfcx from GSL's hazard function against independent evaluations.
#include <references/exact/erfcx.hpp>

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace beamimpact::exact {
namespace {

TEST(Erfcx, MatchesDirectProductWhereThatIsAccurate) {
  // For x <= 5, exp(x^2) erfc(x) loses nothing to overflow; std::erfc is an independent
  // implementation (libm). 1e-13 relative: a few ulps of each factor.
  for (double x : {0.0, 0.1, 0.5, 1.0, 2.0, 3.5, 5.0}) {
    const double direct = std::exp(x * x) * std::erfc(x);
    EXPECT_NEAR(erfcx(x), direct, 1e-13 * direct) << x;
  }
  EXPECT_DOUBLE_EQ(erfcx(0.0), 1.0);
}

TEST(Erfcx, FollowsTheAsymptoticSeriesForLargeArguments) {
  // erfcx(x) ~ 1/(x sqrt(pi)) (1 - 1/(2x^2) + 3/(4x^4) - 15/(8 x^6)); the next term is
  // 105/(16 x^8) ~ 7e-8 relative at x = 10 and 7e-16 at x = 100.
  for (double x : {10.0, 30.0, 100.0, 1e4}) {
    const double y = 1.0 / (x * x);
    const double series =
        (1.0 - y / 2.0 + 3.0 * y * y / 4.0 - 15.0 * y * y * y / 8.0) / (x * std::sqrt(std::numbers::pi));
    EXPECT_NEAR(erfcx(x), series, 1e-7 * series) << x;
  }
}

TEST(Erfcx, NegativeArguments) {
  EXPECT_NEAR(erfcx(-1.0), std::exp(1.0) * (2.0 - std::erfc(1.0)), 1e-14 * erfcx(-1.0));
}

}  // namespace
}  // namespace beamimpact::exact
