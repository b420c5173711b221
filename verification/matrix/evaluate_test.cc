// Gate decisions and observed orders on hand-made comparisons.
#include <verification/matrix/evaluate.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace beamimpact::verification {
namespace {

Comparison with_impulse(std::optional<double> v) {
  Comparison c;
  Norm n{"impulse", v, "1", "test", {}, {}, v ? "" : "reference value is zero"};
  c.norms.push_back(n);
  return c;
}

TEST(Evaluate, GatePassesAtOrBelowTolerance) {
  const Gate g{"impulse", 0.01, std::nullopt, "test gate", std::nullopt};
  EXPECT_EQ(check_gate(g, with_impulse(0.01)).status, GateStatus::kPass);  // "error <= tol"
  const GateResult f = check_gate(g, with_impulse(0.0100001));
  EXPECT_EQ(f.status, GateStatus::kFail);
  EXPECT_NE(f.message.find("exceeds"), std::string::npos);
}

TEST(Evaluate, UnavailableOrMissingNormFails) {
  EXPECT_EQ(check_gate({"impulse", 1.0, std::nullopt, "test", std::nullopt}, with_impulse(std::nullopt)).status,
            GateStatus::kFail);
  const GateResult m = check_gate({"impulse_2", 1.0, std::nullopt, "test", std::nullopt}, with_impulse(0.0));
  EXPECT_EQ(m.status, GateStatus::kFail);
  EXPECT_NE(m.message.find("not produced"), std::string::npos);
}

// e = C h^p: halving h divides the error by 2^p.
TEST(Evaluate, ObservedOrder) {
  EXPECT_NEAR(*observed_order(4e-3, 1e-3, 2.0), 2.0, 1e-12);
  EXPECT_NEAR(*observed_order(1e-3, 1e-3, 2.0), 0.0, 1e-12);
  EXPECT_NEAR(*observed_order(9e-3, 1e-3, 3.0), 2.0, 1e-12);
  EXPECT_FALSE(observed_order(0.0, 1e-3, 2.0));
  EXPECT_FALSE(observed_order(1e-3, 0.0, 2.0));
  EXPECT_FALSE(observed_order(std::nullopt, 1e-3, 2.0));
}

// Richardson extrapolation: Q(h) = 1 + 0.5 h^2 sampled at h = 1, 1/2, 1/4 gives the limit 1 and
// the order 2 exactly (to roundoff: the formula is exact for a pure power); differences that do
// not shrink monotonically (no asymptotic range) give no limit.
TEST(Richardson, ExactForAPurePowerAndRefusedOutsideTheAsymptoticRange) {
  auto q = [](double h) { return 1.0 + 0.5 * h * h; };
  const auto lim = richardson_limit(q(1.0), q(0.5), q(0.25), 2.0);
  ASSERT_TRUE(lim);
  EXPECT_NEAR(lim->first, 1.0, 1e-14);
  EXPECT_NEAR(lim->second, 2.0, 1e-12);
  EXPECT_FALSE(richardson_limit(1.0, 2.0, 1.5, 2.0));  // oscillating
  EXPECT_FALSE(richardson_limit(1.0, 1.5, 2.5, 2.0));  // diverging
}

}  // namespace
}  // namespace beamimpact::verification
