// Gate decisions and observed orders on hand-made comparisons.
#include <verification/matrix/evaluate.hpp>
#include <verification/matrix/reports.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <unistd.h>

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
  EXPECT_EQ(
      check_gate({"impulse", 1.0, std::nullopt, "test", std::nullopt}, with_impulse(std::nullopt)).status,
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

TEST(Evaluate, MarginIsTheShareOfTheLimitUsed) {
  // An error of 0.005 under a limit of 0.01 uses half of it; an order of 2 against a minimum of 1.5
  // uses 0.75 of it (min_order / order: below 1 while the order holds).
  EXPECT_DOUBLE_EQ(
      *check_gate({"impulse", 0.01, std::nullopt, "t", std::nullopt}, with_impulse(0.005)).margin(), 0.5);
  GateResult order{{"impulse", std::nullopt, 1.5, "t", std::nullopt}, 2.0, GateStatus::kPass, ""};
  EXPECT_DOUBLE_EQ(*order.margin(), 0.75);
  order.gate.tol = 0.1;  // two limits: no single margin
  EXPECT_FALSE(order.margin().has_value());
}

TEST(Evaluate, OneVerdictForEveryReport) {
  // Every gate passes, but the run was interrupted: not a pass, in norms.json and report.md alike.
  ItemResult item;
  item.scene = "s";
  item.gates.push_back(check_gate({"impulse", 0.01, std::nullopt, "t", std::nullopt}, with_impulse(0.0)));
  ReportContext ctx;
  ctx.incomplete = "interrupted by signal 2";
  EXPECT_FALSE(verification_passed({item}, false));
  EXPECT_EQ(norms_json(ctx, {item}).at("verdict"), "FAIL");
  const auto md =
      std::filesystem::temp_directory_path() / ("evaluate_test_" + std::to_string(::getpid()) + ".md");
  write_markdown(md, ctx, {item});
  std::ifstream in(md);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(md);
  EXPECT_NE(text.find("**FAIL**: 1 gates"), std::string::npos);
  ctx.incomplete.clear();
  EXPECT_EQ(norms_json(ctx, {item}).at("verdict"), "PASS");
}

}  // namespace
}  // namespace beamimpact::verification
