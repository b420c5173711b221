// Gate decisions and observed orders on hand-made comparisons.
#include <verification/matrix/evaluate.hpp>
#include <verification/matrix/reports.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <unistd.h>

#include <gtest/gtest.h>

#include <verification/compare/test_histories.hpp>

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

/// report.md as write_markdown writes it for `items`.
std::string markdown_of(const std::vector<ItemResult>& items) {
  const auto md =
      std::filesystem::temp_directory_path() / ("evaluate_test_ladder_" + std::to_string(::getpid()) + ".md");
  write_markdown(md, ReportContext{}, items);
  std::ifstream in(md);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(md);
  return text;
}

TEST(Evaluate, ALadderSaysWhatItIsJudgedAgainst) {
  // A ladder with a reference (names as Convergence::name() makes them) is judged against it; one
  // without against its own next finer rung. report.md says which, in the run and reference cells.
  ItemResult exact, self;
  exact.kind = self.kind = "convergence";
  exact.scene = self.scene = "s1_central";
  exact.name = "s1_central paper dt=0.01/0.005/0.0025 vs exact";
  exact.reference = "exact";
  self.name = "s1_central paper dt=0.01/0.005/0.0025";
  for (ItemResult* i : {&exact, &self})
    i->gates.push_back(check_gate({"impulse", 0.01, std::nullopt, "t", std::nullopt}, with_impulse(0.0)));
  const std::string with_ref = markdown_of({exact});
  EXPECT_NE(with_ref.find("| paper dt=0.01/0.005/0.0025 (ladder: each rung against exact) | exact |"),
            std::string::npos)
      << with_ref;
  EXPECT_EQ(with_ref.find("self-convergence"), std::string::npos);
  const std::string own = markdown_of({self});
  EXPECT_NE(
      own.find("| paper dt=0.01/0.005/0.0025 (self-convergence: each rung against the next finer) | - |"),
      std::string::npos)
      << own;
}

// Run against reference, never the other way round: pairs whose swap changes the error. A
// run whose contact force is (1 + e) times its reference's (the same shape, a sin^2 pulse on
// [1, 2] s) has the relative errors |(1 + e) - 1| / 1 = e in impulse, peak force and R (L2);
// the reference measured against the run would give e / (1 + e).
double pulse(double t) { return t > 1.0 && t < 2.0 ? std::pow(std::sin(M_PI * (t - 1.0)), 2) : 0.0; }

/// A finished run in memory whose force is `scale` times the pulse.
jobs::JobOutcome scaled_run(const jobs::JobSpec& spec, double scale) {
  auto run = std::make_shared<const StoredRun>(
      testing::synthetic(0.01, 3.0, [scale](double t) { return scale * pulse(t); }));
  return jobs::JobOutcome{spec, {}, jobs::JobOutcome::Status::kOk, "", 0.0, 0.0, 300, 0.01, run};
}

jobs::JobSpec spec_at(const std::string& method, std::optional<double> dt) {
  return jobs::JobSpec{"pulse.toml", method, dt, "", {}};
}

double norm_of(const Comparison& c, const std::string& name) {
  const Norm* n = c.find(name);
  EXPECT_TRUE(n && n->value) << name;
  return n && n->value ? *n->value : -1.0;
}

TEST(Evaluate, ACaseMeasuresTheRunAgainstItsReference) {
  Case c;
  c.run = spec_at("paper", 0.01);
  c.reference = spec_at("exact", std::nullopt);
  // tol 0.75 lies between e = 1 (run against reference) and e / (1 + e) = 0.5 (swapped).
  c.gates = {{"impulse", 0.75, std::nullopt, "t", std::nullopt}};
  const std::map<std::string, jobs::JobOutcome> runs = {{c.run.key(), scaled_run(c.run, 2.0)},
                                                        {c.reference.key(), scaled_run(c.reference, 1.0)}};
  const ItemResult r = evaluate_case(c, runs);
  ASSERT_EQ(r.comparisons.size(), 1u);
  // Both histories are the same pulse on the same rows: the errors are e = 1 to roundoff.
  for (const char* n : {"impulse", "peak_R", "R.rel_l2", "R.rel_linf"})
    EXPECT_NEAR(norm_of(r.comparisons[0], n), 1.0, 1e-12) << n;
  ASSERT_EQ(r.gates.size(), 1u);
  EXPECT_EQ(r.gates[0].status, GateStatus::kFail);
}

// A ladder with a reference: rung k has e_k = 0.4, 0.1, 0.025 (e = 6.4 dt^2, order 2 at each
// halving of dt); swapped, e / (1 + e) gives orders 1.65 and 1.90, below the gates' 1.95. The
// Richardson limit of the rungs' impulses (1 + e_k) I is I, the reference's own value.
TEST(Evaluate, ALadderMeasuresEveryRungAgainstItsReference) {
  Convergence v;
  const double steps[3] = {0.25, 0.125, 0.0625}, e[3] = {0.4, 0.1, 0.025};
  std::map<std::string, jobs::JobOutcome> runs;
  for (int k = 0; k < 3; ++k) {
    v.runs.push_back(spec_at("paper", steps[k]));
    v.steps.push_back(steps[k]);
    runs.emplace(v.runs.back().key(), scaled_run(v.runs.back(), 1.0 + e[k]));
  }
  v.reference = spec_at("exact", std::nullopt);
  runs.emplace(v.reference->key(), scaled_run(*v.reference, 1.0));
  v.gates = {{"impulse", std::nullopt, 1.95, "t", std::nullopt},
             {"R.rel_l2", std::nullopt, 1.95, "t", std::nullopt}};
  const ItemResult r = evaluate_ladder(v, runs);
  ASSERT_EQ(r.comparisons.size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(norm_of(r.comparisons[k], "impulse"), e[k], 1e-12) << k;
  for (const auto& g : r.gates) EXPECT_EQ(g.status, GateStatus::kPass) << g.gate.metric << ": " << g.message;
  const auto& [errors, orders] = r.orders.at("impulse");
  ASSERT_EQ(orders.size(), 2u);
  for (const auto& p : orders) EXPECT_NEAR(p.value_or(0.0), 2.0, 1e-9);
  ASSERT_TRUE(r.richardson.contains("impulse"));
  // The pulse's impulse: int_1^2 sin^2 = 1/2 (the trapezoidal rule is exact for it on whole periods).
  const double I = 0.5;
  EXPECT_NEAR(r.richardson.at("impulse").reference, I, 1e-12);
  EXPECT_NEAR(r.richardson.at("impulse").limit, I, 1e-9 * I);
  EXPECT_NEAR(r.richardson.at("impulse").error, 0.0, 1e-9);
}

// A ladder without a reference compares consecutive rungs, the finer one the reference:
// (1 + e_i) against (1 + e_{i+1}) gives (e_i - e_{i+1}) / (1 + e_{i+1}): 0.3 / 1.1 and
// 0.075 / 1.025 (swapped: 0.3 / 1.4 and 0.075 / 1.1).
TEST(Evaluate, ASelfConvergenceLadderTakesTheFinerRungAsTheReference) {
  Convergence v;
  const double steps[3] = {0.25, 0.125, 0.0625}, e[3] = {0.4, 0.1, 0.025};
  std::map<std::string, jobs::JobOutcome> runs;
  for (int k = 0; k < 3; ++k) {
    v.runs.push_back(spec_at("paper", steps[k]));
    v.steps.push_back(steps[k]);
    runs.emplace(v.runs.back().key(), scaled_run(v.runs.back(), 1.0 + e[k]));
  }
  v.gates = {{"impulse", std::nullopt, 1.0, "t", std::nullopt}};
  const ItemResult r = evaluate_ladder(v, runs);
  ASSERT_EQ(r.comparisons.size(), 2u);
  EXPECT_NEAR(norm_of(r.comparisons[0], "impulse"), 0.3 / 1.1, 1e-12);
  EXPECT_NEAR(norm_of(r.comparisons[1], "impulse"), 0.075 / 1.025, 1e-12);
}

}  // namespace
}  // namespace beamimpact::verification
