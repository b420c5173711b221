// Norms of compare_runs on synthetic histories whose errors are known in closed form.
#include <verification/compare/compare_runs.hpp>

#include <iterator>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <verification/compare/test_histories.hpp>

namespace beamimpact::verification {
namespace {

using testing::synthetic;
constexpr double kPi = std::numbers::pi;

/// compare_runs() of the two runs' views.
Comparison compare(const StoredRun& a, const StoredRun& b, const CompareOptions& options = {}) {
  return compare_runs(a.view(), b.view(), options);
}

double value(const Comparison& c, const std::string& name) {
  const Norm* n = c.find(name);
  EXPECT_NE(n, nullptr) << name;
  if (n == nullptr || !n->value) {
    ADD_FAILURE() << name << " unavailable: " << (n ? n->unavailable : "");
    return NAN;
  }
  return *n->value;
}

// A force step of height P at t_s, and the same step d later (d a whole number of rows).
// Theory (step functions on [0, T]): max |I_a - I_b| = P d; R's relative L2 error
// sqrt(P^2 d / (P^2 (T - t_s - d))); contact start differs by d; W-window averages are ramps of
// width W whose largest difference is P d / W (d < W).
TEST(CompareRuns, ShiftedStep) {
  const double h = 0.01, T = 4.0, ts = 1.0, d = 0.05, P = 2.0;
  const auto a = synthetic(h, T, [&](double t) { return t >= ts - h / 2 ? P : 0.0; });
  const auto b = synthetic(h, T, [&](double t) { return t >= ts + d - h / 2 ? P : 0.0; });
  const Comparison c = compare(a, b);
  EXPECT_NEAR(c.grid_step, h, 1e-12);    // rows are i h: spacings carry round-off
  EXPECT_NEAR(c.window, 10 * h, 1e-12);  // default: 10 output steps
  // The sampled step is a one-row ramp in both runs, the same shape shifted by d: the impulse
  // difference is exactly P d; its reference maximum is P (T - t_s - d) + P h / 2 (half-row ramp).
  EXPECT_NEAR(value(c, "I.rel_linf"), P * d / (P * (T - ts - d) + P * h / 2), 1e-12);
  // Trapezoid integration of the squared one-row ramps gives the step-function answer exactly
  // for the difference; the reference norm carries the half-row ramp (+ P^2 h / 2).
  EXPECT_NEAR(value(c, "R.rel_l2"), std::sqrt(P * P * d / (P * P * (T - ts - d) + P * P * h / 2)), 1e-12);
  EXPECT_NEAR(value(c, "R.rel_l2"), std::sqrt(d / (T - ts - d)), 1e-3);  // continuum value, O(h) off
  EXPECT_NEAR(value(c, "R.rel_linf"), 1.0, 1e-12);  // pointwise: a jump shifted is a full error
  EXPECT_NEAR(value(c, "Rw.rel_linf"), d / (10 * h), 1e-9);
  EXPECT_NEAR(value(c, "contact_start"), d, 1e-12);
  EXPECT_NEAR(value(c, "contact_end"), 0.0, 1e-12);  // both last until T
  EXPECT_EQ(value(c, "impacts"), 0.0);
  EXPECT_NEAR(value(c, "impulse"), d / (T - ts - d + h / 2), 1e-12);
  EXPECT_NEAR(value(c, "peak_R"), 0.0, 1e-12);
  EXPECT_NEAR(value(c, "energy_final"), 0.0, 1e-15);
}

// peak_R leaves out every closure row (the first row in contact after an open one): a penalty
// method's sub-step closure spike is not the force the methods are compared on. Run a has a
// spike of 10 N at its closure row, then the plateau P = 2 N of reference b: the peaks agree.
TEST(CompareRuns, ClosureSpikeIsLeftOutOfThePeak) {
  const double h = 0.01, T = 4.0, ts = 1.0, P = 2.0;
  const auto a =
      synthetic(h, T, [&](double t) { return std::abs(t - ts) < h / 2 ? 10.0 : (t > ts ? P : 0.0); });
  const auto b = synthetic(h, T, [&](double t) { return t >= ts - h / 2 ? P : 0.0; });
  EXPECT_NEAR(value(compare(a, b), "peak_R"), 0.0, 1e-12);
  // Not left out: the peak would be 10 N, an error of (10 - 2) / 2 = 4.
  const auto c = synthetic(
      h, T, [&](double t) { return std::abs(t - ts - 1.0) < h / 2 ? 10.0 : (t >= ts - h / 2 ? P : 0.0); });
  EXPECT_NEAR(value(compare(c, b), "peak_R"), 4.0, 1e-12);
}

// A force scaled by 1 + s: every relative force norm is exactly s (the norms are homogeneous).
TEST(CompareRuns, ScaledForce) {
  const double s = 0.02;
  auto pulse = [](double t) { return t > 0.5 && t < 2.5 ? 2.0 + std::sin(3 * t) : 0.0; };
  const auto b = synthetic(0.01, 4.0, pulse);
  const auto a = synthetic(0.01, 4.0, [&](double t) { return (1 + s) * pulse(t); });
  const Comparison c = compare(a, b);
  for (const char* n :
       {"R.rel_l2", "R.rel_linf", "I.rel_linf", "Rw.rel_l2", "Rw.rel_linf", "impulse", "peak_R"})
    EXPECT_NEAR(value(c, n), s, 1e-12) << n;
  EXPECT_EQ(value(c, "contact_start"), 0.0);
  EXPECT_EQ(value(c, "impacts"), 0.0);
}

// The same sine on two unrelated grids: only interpolation error remains, bounded by
// h^2/8 max|y''| for each grid (linear interpolation); a phase shift delta gives the
// closed form |sin(w t) - sin(w (t - delta))| = 2 sin(w delta / 2) |cos(...)|, so both relative
// norms equal 2 sin(w delta / 2) over whole periods.
TEST(CompareRuns, ResampledSineOnDifferentGrids) {
  const double w = 2 * kPi, ha = 0.01, hb = 0.0037, T = 2.0;  // T: whole periods for both grids
  auto sine = [&](double t) { return std::sin(w * t); };
  auto zero = [](double) { return 0.0; };
  const auto a = synthetic(ha, T, zero, sine);
  const auto b = synthetic(hb, 2.0 - std::fmod(2.0, hb), zero, sine);
  const Comparison c = compare(a, b);
  EXPECT_NEAR(c.grid_step, hb, 1e-12);  // the finer of the two output steps
  const double bound = (ha * ha + hb * hb) / 8 * w * w;
  const double e = value(c, "ua.rel_linf");
  EXPECT_GT(e, 0.0);           // the grids really differ
  EXPECT_LT(e, bound * 1.01);  // bound relative to max|b| = 1 (+1% for max|b| sampled below 1)

  const double delta = 0.01;
  const auto shifted = synthetic(ha, T, zero, [&](double t) { return std::sin(w * (t - delta)); });
  const Comparison cs = compare(shifted, b);
  const double expect = 2 * std::sin(w * delta / 2);
  EXPECT_NEAR(value(cs, "ua.rel_linf"), expect, bound + 1e-3 * expect);
  // b ends 0.0024 s before T: the ratio of the two L2 norms departs from whole-period value by
  // O(0.0024/T); allow 0.5% of the value.
  EXPECT_NEAR(value(cs, "ua.rel_l2"), expect, 5e-3 * expect + bound);
}

// A lost impact: the run misses the second of two pulses.
TEST(CompareRuns, LostImpact) {
  auto two = [](double t) { return (t > 0.5 && t < 1.0) || (t > 2.0 && t < 2.3) ? 1.0 : 0.0; };
  auto one = [](double t) { return t > 0.5 && t < 1.0 ? 1.0 : 0.0; };
  const Comparison c = compare(synthetic(0.01, 3.0, one), synthetic(0.01, 3.0, two));
  EXPECT_EQ(value(c, "impacts"), 1.0);
  EXPECT_EQ(c.find("impacts")->a.value(), 1.0);
  EXPECT_EQ(c.find("impacts")->b.value(), 2.0);
  EXPECT_NEAR(value(c, "contact_start"), 0.0, 1e-12);
}

// Chatter: two contact samples separated by up to two open samples merge into one impact
// (default merge gap 3.5 output steps), three open samples make two impacts.
TEST(CompareRuns, ChatterMergeRule) {
  const double h = 0.01;
  auto with_gap = [&](int open) {
    return synthetic(h, 2.0, [=](double t) {
      const long i = std::lround(t / h);
      return (i >= 50 && i < 60) || (i >= 60 + open && i < 80 + open) ? 1.0 : 0.0;
    });
  };
  EXPECT_EQ(compare(with_gap(2), with_gap(0)).find("impacts")->a.value(), 1.0);
  EXPECT_EQ(compare(with_gap(3), with_gap(0)).find("impacts")->a.value(), 2.0);
}

// A column a norm needs is absent: that norm is unavailable and says which column, others work.
TEST(CompareRuns, MissingColumnMakesNormUnavailable) {
  auto f = [](double t) { return t > 1 ? 1.0 : 0.0; };
  auto a = synthetic(0.01, 2.0, f);
  a.columns().erase("vb_y");
  const Comparison c = compare(a, synthetic(0.01, 2.0, f));
  const Norm* n = c.find("vb.rel_l2");
  ASSERT_NE(n, nullptr);
  EXPECT_FALSE(n->value.has_value());
  EXPECT_NE(n->unavailable.find("vb_y"), std::string::npos);
  EXPECT_NEAR(value(c, "R.rel_l2"), 0.0, 0.0);
}

TEST(CompareRuns, NoOverlapIsAnError) {
  auto f = [](double) { return 0.0; };
  auto late = synthetic(0.01, 1.0, f);
  for (auto& t : late.columns()["t"]) t += 5.0;
  EXPECT_THROW(compare(late, synthetic(0.01, 1.0, f)), std::exception);
}

}  // namespace
}  // namespace beamimpact::verification

namespace beamimpact::verification {
namespace {

// known_norm accepts exactly the names compare_runs produces (checked on a two-contact history).
TEST(CompareRuns, KnownNormMatchesProducedNames) {
  auto f = [](double t) { return t > 1 ? 1.0 : 0.0; };
  auto h = testing::synthetic(0.01, 2.0, f);
  for (const char* base : {"R", "tau", "gap", "ua_x", "ua_y", "va_x", "va_y", "ub_x", "ub_y", "vb_x", "vb_y"})
    h.columns()[std::string(base) + "_2"] = h.columns().at(base == std::string("R") ? "R" : base);
  const Comparison c = compare(h, h);
  for (const auto& n : c.norms) EXPECT_TRUE(known_norm(n.name)) << n.name;
  EXPECT_NE(c.find("impulse_2"), nullptr);
  for (const char* bad : {"R.rel_l1", "impulse_1", "I.rel_l2", "Impulse", "ua", "R_x.rel_l2"})
    EXPECT_FALSE(known_norm(bad)) << bad;
}

}  // namespace
}  // namespace beamimpact::verification

namespace beamimpact::verification {
namespace {

// The method's own scalars in summary.json take precedence over the rows for impulse and
// intervals (an adaptive method's rows miss sub-step closure spikes).
TEST(CompareRuns, SummaryScalarsTakePrecedence) {
  auto f = [](double t) { return t > 0.5 && t < 1.5 ? 1.0 : 0.0; };
  auto a = testing::synthetic(0.01, 2.0, f);
  auto b = testing::synthetic(0.01, 2.0, f);
  const nlohmann::json sb = {
      {"contacts", {{{"impulse_normal", 1.0}, {"intervals", {{0.5, 1.0}, {1.2, 1.5}}}}}}};
  const nlohmann::json sa = {{"contacts", {{{"impulse_normal", 1.1}, {"intervals", {{0.503, 1.5}}}}}}};
  const Comparison c =
      compare(StoredRun::from_columns(a.columns(), sa), StoredRun::from_columns(b.columns(), sb));
  EXPECT_NEAR(*c.find("impulse")->value, 0.1, 1e-12);
  EXPECT_NEAR(*c.find("contact_start")->value, 0.003, 1e-12);
  EXPECT_NEAR(*c.find("contact_end")->value, 0.5, 1e-12);
  EXPECT_EQ(*c.find("impacts")->value, 1.0);
  EXPECT_EQ(*c.find("R.rel_l2")->value, 0.0);  // time series still from the rows
}

// Sequence norms pair each reference interval with the run's interval starting nearest to it:
// reference [0.5, 1.0], [1.2, 1.5]; run [0.51, 0.98], [1.17, 1.56], and a spurious [1.8, 1.85]
// that pairs with nothing. Starts differ by 0.01 and 0.03 s, ends by 0.02 and 0.06 s.
TEST(CompareRuns, SequenceNormsPairIntervalsByStart) {
  auto f = [](double t) { return (t > 0.5 && t < 1.0) || (t > 1.2 && t < 1.5) ? 1.0 : 0.0; };
  auto a = testing::synthetic(0.01, 2.0, f);
  auto b = testing::synthetic(0.01, 2.0, f);
  const nlohmann::json sb = {{"contacts", {{{"intervals", {{0.5, 1.0}, {1.2, 1.5}}}}}}};
  const nlohmann::json sa = {{"contacts", {{{"intervals", {{0.51, 0.98}, {1.17, 1.56}, {1.8, 1.85}}}}}}};
  const Comparison c =
      compare(StoredRun::from_columns(a.columns(), sa), StoredRun::from_columns(b.columns(), sb));
  EXPECT_NEAR(*c.find("contact_starts")->value, 0.03, 1e-12);
  EXPECT_NEAR(*c.find("contact_ends")->value, 0.06, 1e-12);
  EXPECT_EQ(*c.find("impacts")->value, 1.0);
}

// A run whose rows say R x 1.5 of the reference's half-sine pulse while its summary.json states
// the reference's impulse and interval. Trusted, its summary gives an impulse error of 0; read
// from its history (score's option), the error is the rows' 1.5 J / J - 1 = 0.5 and its interval
// is its rows'. The pulse P sin(pi (t - t0) / D) on [t0, t0 + D] has impulse 2 P D / pi.
TEST(CompareRuns, ARunReadFromItsHistoryIgnoresWhatItsSummaryClaims) {
  const double h = 1e-3, T = 2.0, t0 = 0.5, D = 0.4, P = 3.0;
  auto pulse = [&](double scale) {
    return [=](double t) { return t > t0 && t < t0 + D ? scale * P * std::sin(kPi * (t - t0) / D) : 0.0; };
  };
  const StoredRun b = synthetic(h, T, pulse(1.0));
  StoredRun a = synthetic(h, T, pulse(1.5));
  const double J = 2.0 * P * D / kPi;
  nlohmann::json claim = {{"contacts", {{{"impulse_normal", J}, {"intervals", {{t0, t0 + D}}}}}}};
  a = StoredRun::from_columns(a.columns(), claim, "claims");
  EXPECT_NEAR(value(compare(a, b), "impulse"), 0.0, 1e-3);  // trapezoid vs 2 P D / pi: O(h^2)
  CompareOptions history;
  history.run_from_history = true;
  const Comparison c = compare(a, b, history);
  EXPECT_NEAR(value(c, "impulse"), 0.5, 1e-9);            // both sides' rows: R_a = 1.5 R_b row by row
  EXPECT_NEAR(value(c, "contact_start"), 0.0, 1.01 * h);  // the rows' first R > 0, as the reference's
  // Interval impulses from the rows too (the reference, without a summary, read the same way).
  history.reference_from_history = true;
  EXPECT_NEAR(value(compare(a, b, history), "impulse_per_impact"), 0.5, 1e-9);
}

}  // namespace
}  // namespace beamimpact::verification

namespace beamimpact::verification {
namespace {

/// The whitespace-separated words of the line of `text` that starts with `name` and a space.
std::vector<std::string> row_words(const std::string& text, const std::string& name) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(name + " ", 0) == 0) {
      std::istringstream w(line);
      return {std::istream_iterator<std::string>(w), std::istream_iterator<std::string>()};
    }
  return {};
}

// The terminal table says what each column holds. impulse is a scalar norm: the run's 1.6 N s and
// the reference's 1.4 N s are printed as values with their difference 0.2. impulse_per_impact is
// a difference norm: intervals' impulses 1.1, 0.5 against 1.0, 0.4 differ by 0.1 at most, over
// the scale max |J_b| = 1.0; its run and reference columns stay blank (they are not the run's
// value), and compare.json names the two numbers "difference" and "scale".
TEST(CompareRuns, TextLabelsValuesAndDifferences) {
  auto f = [](double t) { return (t > 0.5 && t < 1.0) || (t > 1.2 && t < 1.5) ? 1.0 : 0.0; };
  auto a = testing::synthetic(0.01, 2.0, f);
  auto b = testing::synthetic(0.01, 2.0, f);
  const nlohmann::json iv = {{0.5, 1.0}, {1.2, 1.5}};
  const nlohmann::json sa = {
      {"contacts", {{{"impulse_normal", 1.6}, {"intervals", iv}, {"interval_impulses", {1.1, 0.5}}}}}};
  const nlohmann::json sb = {
      {"contacts", {{{"impulse_normal", 1.4}, {"intervals", iv}, {"interval_impulses", {1.0, 0.4}}}}}};
  const Comparison c =
      compare(StoredRun::from_columns(a.columns(), sa), StoredRun::from_columns(b.columns(), sb));
  const std::string text = c.to_text();
  const auto header = text.find("run value");
  ASSERT_NE(header, std::string::npos) << text;
  EXPECT_NE(text.find("ref. value", header), std::string::npos) << text;
  EXPECT_NE(text.find("|run - ref|", header), std::string::npos) << text;
  EXPECT_NE(text.find("scale", header), std::string::npos) << text;
  // name, error, unit, run value, reference value, |run - ref|
  EXPECT_EQ(row_words(text, "impulse"),
            (std::vector<std::string>{"impulse", fmt::format("{:.4e}", 0.2 / 1.4), "1", "1.6", "1.4", "0.2"}))
      << text;
  // name, error, unit, |run - ref|, scale: no run or reference value
  EXPECT_EQ(row_words(text, "impulse_per_impact"),
            (std::vector<std::string>{"impulse_per_impact", fmt::format("{:.4e}", 0.1), "1", "0.1", "1"}))
      << text;
  const nlohmann::json j = c.to_json();
  for (const auto& n : j.at("norms"))
    if (n.at("name") == "impulse_per_impact") {
      EXPECT_NEAR(n.at("difference").get<double>(), 0.1, 1e-12);
      EXPECT_EQ(n.at("scale").get<double>(), 1.0);
      EXPECT_FALSE(n.contains("run_value"));
    }
}

}  // namespace
}  // namespace beamimpact::verification
