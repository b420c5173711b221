// The output rules of the protocol (api/output_rules.hpp) on hand-made run directories: a
// triangular contact pulse whose integral is known in closed form, written the way a fixed-step
// method writes it, passes; each broken copy fails the one rule it breaks.
#include <api/output_rules.hpp>
#include <api/run.hpp>

#include <cmath>
#include <fstream>
#include <functional>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <solver/schema/output_schema.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/sha256.hpp>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

constexpr double kH = 0.01;              // s, row spacing (one row per step)
constexpr double kEnd = 1.0;             // s
constexpr double kPeak = 8.0;            // N
constexpr double kOn = 0.2, kOff = 0.6;  // s: R rises linearly to kPeak at 0.4 s and falls to 0 at 0.6 s

double pulse(double t) {
  const double mid = 0.5 * (kOn + kOff), half = 0.5 * (kOff - kOn);
  return std::max(0.0, kPeak * (1.0 - std::abs(t - mid) / half));
}

class OutputRules : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::temp_path("output_rules");
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    scene_ = dir_ / "scene.toml";
    std::ofstream(scene_) << "# any bytes: the rules hash the file given\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Writes the run: rows t_k = k h with R = pulse(t_k); the summary's impulse and interval as a
  /// fixed-step method states them (sum R_k h; first and last row with R > 0), then `edit`.
  void write(const std::function<void(std::vector<std::vector<double>>&, nlohmann::json&)>& edit = {}) {
    std::vector<std::vector<double>> rows;
    double J = 0.0, first = -1.0, last = -1.0;
    for (int k = 0; k <= static_cast<int>(std::lround(kEnd / kH)); ++k) {
      const double t = k * kH, R = pulse(t);
      rows.push_back({t, R});
      J += R * kH;
      if (R > 0.0) {
        if (first < 0.0) first = t;
        last = t;
      }
    }
    std::ifstream in(scene_);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    nlohmann::json s = {
        {"method", "hand"},
        {"scene_sha256", sha256_hex(bytes)},
        {"dt", kH},
        {"steps", 100},
        {"end_time", kEnd},
        {"wall_seconds", 0.0},
        {"complete", true},
        {"units", summary_units()},
        {"contacts", {{{"impulse_normal", J}, {"intervals", {{first, last}}}, {"interval_impulses", {J}}}}}};
    if (edit) edit(rows, s);
    std::ofstream csv(dir_ / "history.csv");
    csv << "t,R\n";
    for (const auto& r : rows) csv << fmt::format("{:.17g},{:.17g}\n", r[0], r[1]);
    std::ofstream(dir_ / "summary.json") << s.dump(1);
  }

  /// The broken rules, "rule: message" each.
  std::vector<std::string> broken() {
    std::vector<std::string> out;
    for (const OutputVerdict& v : check_outputs(dir_, OutputExpectation{scene_, 1, kEnd}))
      if (!v.passed) out.push_back(v.rule + ": " + v.message);
    return out;
  }

  fs::path dir_, scene_;
};

// The honest run: the rectangle sum of a triangle sampled at its kinks is its exact integral
// kPeak (kOff - kOn) / 2 = 1.6 N s, as is the trapezoid rule the rules read the rows by.
TEST_F(OutputRules, AnHonestFixedStepRunKeepsEveryRule) {
  write();
  EXPECT_TRUE(broken().empty()) << ::testing::PrintToString(broken());
}

// A row every step (dt = h): the time conventions agree on these rows (R is 0 at both ends), so
// the tolerance is rounding only and an impulse 0.05 N s (3 %) off breaks the rule. Rows sparser
// than the steps (dt = h / 10: R between rows unseen): the tolerance is the rows' resolution
// h max(max R, TV / 2) = 0.01 x 8 = 0.08 N s (TV = 16 N), so 0.05 N s passes and 0.16 N s (10 %)
// does not.
TEST_F(OutputRules, TheImpulseMustMatchTheRowsWithinTheirResolution) {
  auto impulse_breaks = [&](double J, double dt) {
    write([&](auto&, nlohmann::json& s) {
      s["contacts"][0]["impulse_normal"] = J;
      s["dt"] = dt;
    });
    const auto b = broken();
    EXPECT_LE(b.size(), 1u) << ::testing::PrintToString(b);
    return !b.empty() && b[0].find("consistency: contacts[0].impulse_normal =") == 0;
  };
  EXPECT_FALSE(impulse_breaks(1.6, kH));
  EXPECT_TRUE(impulse_breaks(1.6 + 0.05, kH));
  EXPECT_FALSE(impulse_breaks(1.6 + 0.05, kH / 10));
  EXPECT_TRUE(impulse_breaks(1.6 * 1.1, kH / 10));
  write([](auto&, nlohmann::json& s) { s["contacts"][0]["impulse_normal"] = 1.6 * 1.1; });
  const auto b = broken();
  ASSERT_EQ(b.size(), 1u) << ::testing::PrintToString(b);
  EXPECT_NE(b[0].find("contacts[0].impulse_normal = 1.76 N s in summary.json, 1.6"), std::string::npos)
      << b[0];
}

// R x 1.5 in the rows with the summary left honest: the rows' integral is 2.4 N s, 0.8 N s off.
TEST_F(OutputRules, RowsThatDisagreeWithTheSummaryBreakConsistency) {
  write([](auto& rows, nlohmann::json&) {
    for (auto& r : rows) r[1] *= 1.5;
  });
  const auto b = broken();
  ASSERT_EQ(b.size(), 1u) << ::testing::PrintToString(b);
  EXPECT_NE(b[0].find("consistency"), std::string::npos) << b[0];
}

// An interval 0.1 s late (10 row spacings) and an interval impulse 20 % off each break consistency.
TEST_F(OutputRules, IntervalsAndIntervalImpulsesAreChecked) {
  write([](auto&, nlohmann::json& s) { s["contacts"][0]["intervals"][0][0] = 0.31; });
  auto b = broken();
  ASSERT_EQ(b.size(), 1u) << ::testing::PrintToString(b);
  EXPECT_NE(b[0].find("contacts[0].intervals[0]"), std::string::npos) << b[0];
  write([](auto&, nlohmann::json& s) { s["contacts"][0]["interval_impulses"][0] = 1.6 * 1.2; });
  b = broken();
  ASSERT_EQ(b.size(), 1u) << ::testing::PrintToString(b);
  EXPECT_NE(b[0].find("contacts[0].interval_impulses[0]"), std::string::npos) << b[0];
  write([](auto&, nlohmann::json& s) {
    s["contacts"][0]["intervals"] = nlohmann::json::array();
    s["contacts"][0].erase("interval_impulses");
  });
  b = broken();
  ASSERT_EQ(b.size(), 1u) << ::testing::PrintToString(b);
  EXPECT_NE(b[0].find("lists no interval there"), std::string::npos) << b[0];
}

// Each of the other rules, broken alone.
TEST_F(OutputRules, EachOtherRuleIsNamedWhenBrokenAlone) {
  const struct {
    const char* rule;
    std::function<void(std::vector<std::vector<double>>&, nlohmann::json&)> edit;
  } cases[] = {
      {"complete", [](auto&, nlohmann::json& s) { s["complete"] = false; }},
      {"finite", [](auto& rows, nlohmann::json&) { rows[3][1] = std::nan(""); }},
      {"times", [](auto& rows, nlohmann::json&) { rows[5][0] = rows[4][0]; }},
      {"summary keys", [](auto&, nlohmann::json& s) { s.erase("steps"); }},
      {"scene sha256", [](auto&, nlohmann::json& s) { s["scene_sha256"] = std::string(64, '0'); }},
      {"units",  // every time in ms, units still saying s: impulse and intervals scale alike
       [](auto& rows, nlohmann::json& s) {
         for (auto& r : rows) r[0] *= 1000.0;
         for (const char* k : {"dt", "end_time"}) s[k] = s[k].get<double>() * 1000.0;
         auto& c = s["contacts"][0];
         for (auto& iv : c["intervals"])
           for (auto& x : iv) x = x.get<double>() * 1000.0;
         c["impulse_normal"] = c["impulse_normal"].get<double>() * 1000.0;
         c["interval_impulses"][0] = c["interval_impulses"][0].get<double>() * 1000.0;
       }},
  };
  for (const auto& c : cases) {
    write(c.edit);
    const auto b = broken();
    ASSERT_EQ(b.size(), 1u) << c.rule << ": " << ::testing::PrintToString(b);
    EXPECT_EQ(b[0].rfind(std::string(c.rule) + ": ", 0), 0u) << b[0];
  }
  fs::remove(dir_ / "history.csv");
  const auto b = broken();
  ASSERT_EQ(b.size(), 1u);
  EXPECT_NE(b[0].find("outputs: expected history.csv and summary.json"), std::string::npos) << b[0];
}

// The IDA reference's own run directory keeps every rule, consistency included: its rows are
// the means of its impulse quadrature over each output step (references/ida/step_mean_rows.hpp),
// so the rows' trapezoid integral is the summary's impulse. The rows hold a row every step, so
// the rule's tolerance is the spread of the time conventions on them, rounding where the pulse
// starts and ends open: S1's rows of the penalty force at the output times (3.755 N s against the
// summary's 3.856 N s) break it, as do the bouncing bar's.
TEST(OutputRulesOfIda, IdaRunsKeepEveryRule) {
  struct IdaRun {
    std::string scene;
    std::vector<std::string> set;
    double end;  // s, the scene's time.end
  };
  for (const IdaRun& c : {IdaRun{testing::paper_scene("s1_central"), {}, 4.0},
                          IdaRun{testing::benchmark_scene("bouncing_bar"), {"time.end=2.0"}, 2.0}}) {
    const std::string& scene = c.scene;
    const fs::path dir = testing::temp_path("output_rules_ida");
    fs::remove_all(dir);
    run(fs::path(scene), "ida", RunOptions{c.set, dir});
    const auto verdicts = check_outputs(dir, OutputExpectation{scene, 1, c.end});
    EXPECT_EQ(first_broken_rule(verdicts), "") << scene;
    fs::remove_all(dir);
  }
}

}  // namespace
}  // namespace beamimpact
