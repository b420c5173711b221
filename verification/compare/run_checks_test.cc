// The health metrics of one run against hand-made histories with known answers.
#include <verification/compare/run_checks.hpp>

#include <gtest/gtest.h>

#include <verification/compare/StoredRun.hpp>

namespace beamimpact::verification {
namespace {

// Three rows: E0 = K + S = 10 J; row 1 books 1 J too little (K + S + D = 9), row 2 creates
// 0.5 J (10.5): band 0.1, growth 0.05; D falls from 1 to 0.5 J: dissipated_decrease 0.05. R = {0, 4, -0.2}:
// tension 0.2 / 4 = 0.05. With mu = 0.5, tau = {0, 2.5, 0}: |tau| - mu R = 0.5 at row 1: cone 0.5 / 4 =
// 0.125. Momentum 2 N s, drift 1e-3 N s: 5e-4. Real gap -3 mm: penetration 3e-3 m.
StoredRun hand_made() {
  std::map<std::string, std::vector<double>> c;
  c["t"] = {0.0, 1.0, 2.0};
  c["R"] = {0.0, 4.0, -0.2};
  c["tau"] = {0.0, 2.5, 0.0};
  c["kinetic"] = {10.0, 5.0, 6.0};
  c["strain"] = {0.0, 3.0, 4.0};
  c["dissipated"] = {0.0, 1.0, 0.5};
  c["px"] = {2.0, 2.0, 2.001};
  c["py"] = {0.0, 0.0, 0.0};
  nlohmann::json summary = {{"momentum_drift_max", 1e-3},
                            {"contacts", {{{"friction", 0.5}, {"real_gap_min", -3e-3}}}}};
  return StoredRun::from_columns(c, summary, "hand-made");
}

TEST(RunChecks, KnownAnswers) {
  const Comparison c = check_run(hand_made().view());
  auto v = [&](const char* n) { return c.find(n)->value.value_or(-1.0); };
  EXPECT_NEAR(v("energy_band"), 0.1, 1e-15);
  EXPECT_NEAR(v("energy_growth"), 0.05, 1e-15);
  EXPECT_NEAR(v("dissipated_decrease"), 0.05, 1e-15);
  EXPECT_NEAR(v("tension"), 0.05, 1e-15);
  EXPECT_NEAR(v("friction_cone"), 0.125, 1e-15);
  EXPECT_NEAR(v("penetration"), 3e-3, 1e-18);
  EXPECT_NEAR(v("momentum_drift"), 5e-4, 1e-15);
  for (const std::string& n : check_names()) EXPECT_NE(c.find(n), nullptr) << n;
}

TEST(RunChecks, InitialEnergyFromTheSummaryWhenGiven) {
  // A t = 0 row with a step-0 contact force in its velocity: K[0] = 9.5 J, while the initial
  // conditions held 10 J (summary.json). Band against 10 J: row 0 books 0.5 J too little (0.05).
  StoredRun r = hand_made();
  r.columns()["kinetic"] = {9.5, 6.0, 5.5};
  nlohmann::json summary = r.summary();
  summary["energy_initial"] = 10.0;
  const Comparison c = check_run(StoredRun::from_columns(r.columns(), summary, "closed at t = 0").view());
  EXPECT_NEAR(c.find("energy_band")->value.value_or(-1.0), 0.05, 1e-15);
}

TEST(RunChecks, MissingInputsAreUnavailableWithAReason) {
  StoredRun r = hand_made();
  r.columns().erase("dissipated");
  const Comparison c =
      check_run(StoredRun::from_columns(r.columns(), nlohmann::json::object(), "bare").view());
  EXPECT_FALSE(c.find("energy_band")->value);
  EXPECT_NE(c.find("energy_band")->unavailable.find("dissipated"), std::string::npos);
  EXPECT_FALSE(c.find("friction_cone")->value);  // no friction coefficient in the summary
  EXPECT_FALSE(c.find("penetration")->value.has_value() && *c.find("penetration")->value > 0.0);
  EXPECT_TRUE(known_check("penetration"));
  EXPECT_FALSE(known_check("impulse"));
}

}  // namespace
}  // namespace beamimpact::verification
