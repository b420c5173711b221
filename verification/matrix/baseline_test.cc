// The baseline's noise rule (baseline.hpp): a value moved by more than max(1 % of the
// baseline's value, 1e-9) is a change; worse is larger for errors, smaller for orders.
#include <gtest/gtest.h>

#include <solver/util/InputError.hpp>
#include <verification/matrix/baseline.hpp>

namespace beamimpact::verification {
namespace {

ItemResult item(const std::string& name, std::vector<GateResult> gates) {
  ItemResult r;
  r.name = name;
  r.gates = std::move(gates);
  return r;
}

GateResult error_gate(const std::string& metric, std::optional<double> value) {
  Gate g;
  g.metric = metric;
  g.tol = 0.05;
  return {g, value, value ? GateStatus::kPass : GateStatus::kFail, {}};
}

GateResult order_gate(const std::string& metric, double value) {
  Gate g;
  g.metric = metric;
  g.min_order = 0.9;
  return {g, value, GateStatus::kPass, {}};
}

std::vector<std::string> names(const std::vector<BaselineDelta>& d) {
  std::vector<std::string> out;
  for (const auto& x : d) out.push_back(x.gate);
  return out;
}

TEST(Baseline, ChangesBeyondTheNoiseOnly) {
  const std::vector<ItemResult> then{
      item("a", {error_gate("grew", 0.01), error_gate("grew_little", 0.01), error_gate("fell", 0.01),
                 error_gate("rounding", 1e-15), error_gate("lost", 0.01)}),
      item("b", {order_gate("impulse", 2.0), order_gate("R.rel_l2", 2.0)}),
      item("gone", {error_gate("impulse", 0.01)})};
  const nlohmann::json baseline = baseline_json("v", "quick", then);
  const std::vector<ItemResult> now{
      // 1.02 and 1.005 times the value: 2 % is beyond the 1 % noise, 0.5 % within it; 0.98: better.
      item("a", {error_gate("grew", 0.0102), error_gate("grew_little", 0.01005), error_gate("fell", 0.0098),
                 // 1e-15 -> 5e-10: below the 1e-9 floor, rounding, not a change.
                 error_gate("rounding", 5e-10), error_gate("lost", std::nullopt)}),
      // An order that fell by 2 % is worse; one that rose by 2 % is better.
      item("b", {order_gate("impulse", 1.96), order_gate("R.rel_l2", 2.04)}),
      item("new", {error_gate("impulse", 0.01)})};
  const BaselineComparison c = compare_baseline(baseline, "b.json", now);
  EXPECT_EQ(names(c.worse), (std::vector<std::string>{"a / grew", "a / lost", "b / impulse (order)"}));
  EXPECT_EQ(names(c.better), (std::vector<std::string>{"a / fell", "b / R.rel_l2 (order)"}));
  EXPECT_EQ(c.unchanged, 2);
  EXPECT_EQ(c.added, std::vector<std::string>{"new / impulse"});
  EXPECT_EQ(c.not_run, std::vector<std::string>{"gone / impulse"});
  EXPECT_FALSE(c.passed());
  // The same values: nothing changed.
  EXPECT_TRUE(compare_baseline(baseline, "b.json", then).passed());
}

TEST(Baseline, AbsoluteFloorAboveRounding) {
  const nlohmann::json baseline = baseline_json("v", "quick", {item("a", {error_gate("impulse", 1e-15)})});
  // 2e-9 is beyond the 1e-9 floor: a change even where the baseline was rounding.
  EXPECT_FALSE(compare_baseline(baseline, "b.json", {item("a", {error_gate("impulse", 2e-9)})}).passed());
}

TEST(Baseline, ItemsOfOneNameByTheirOrder) {
  // Two ladders of one name (another reference): the second one's order falling by 10 % is its own.
  const nlohmann::json baseline = baseline_json(
      "v", "quick", {item("l", {order_gate("impulse", 2.0)}), item("l", {order_gate("impulse", 2.0)})});
  const BaselineComparison c = compare_baseline(
      baseline, "b.json", {item("l", {order_gate("impulse", 2.0)}), item("l", {order_gate("impulse", 1.8)})});
  EXPECT_EQ(names(c.worse), std::vector<std::string>{"l [2] / impulse (order)"});
  EXPECT_EQ(c.unchanged, 1);
}

TEST(Baseline, RefusesWhatIsNoBaseline) {
  EXPECT_THROW(compare_baseline(nlohmann::json{{"verdict", "PASS"}}, "b.json", {}), InputError);
}

}  // namespace
}  // namespace beamimpact::verification
