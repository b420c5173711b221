// `beamimpact study` end to end, serial: the table, a refused case recorded (not fatal), bad
// input, and (when MPI is built) mpirun -n 2 against the serial run byte for byte.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <tools/beamimpact/testing/cli_run.hpp>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

class StudyCommand : public testing::CliTest {
 protected:
  fs::path study(const std::string& body) {
    const fs::path p = tmp_ / "study.toml";
    std::ofstream(p)
        << "name = \"t\"\nscene = \"" << BEAMIMPACT_SOURCE
        << "/verification/scenes/paper/s4_oblique_90.toml\"\n"
           "methods = [\"paper\"]\nreference = { method = \"ida\" }\n"
           "set = [\"model.kinematics=linear\", \"time.end=0.03\", \"bodies.A.end=[5.0, 0.001]\"]\n"
        << body;
    return p;
  }
};

const char* kGrid = R"(
[[parameter]]
name = "alpha0"
rake = "A"
values = [90, 45]
[[parameter]]
name = "mu"
key = "contacts[0].friction"
values = [0.0, 0.6]
[[parameter]]
name = "fraction"
key = "time.fraction"
values = [0.5, 3.0]
)";

TEST_F(StudyCommand, TableRecordsRefusedCasesAndFrictionActsOnlyOnObliqueImpacts) {
  const auto [code, out] =
      run(fmt::format("study '{}' --out '{}'", study(kGrid).string(), (tmp_ / "o").string()));
  ASSERT_EQ(code, 0) << out;
  const auto j = nlohmann::json::parse(read(tmp_ / "o/study.json"));
  const auto& cases = j.at("cases");
  ASSERT_EQ(cases.size(), 8u);  // 2 x 2 x 2 points, one method
  auto find = [&](double a, double mu, double f) -> const nlohmann::json& {
    for (const auto& c : cases) {
      const auto& p = c.at("parameters");
      if (p.at("alpha0") == a && p.at("mu") == mu && p.at("fraction") == f) return c;
    }
    throw std::runtime_error("no such case");
  };
  // 3 x the critical step: the paper run is refused, recorded, not fatal.
  for (double a : {90.0, 45.0})
    for (double mu : {0.0, 0.6}) {
      const auto& c = find(a, mu, 3.0);
      EXPECT_EQ(c.at("status"), "error");
      EXPECT_TRUE(c.at("broke").get<bool>());  // listed in study.md as a breakdown
      EXPECT_NE(c.at("message").get<std::string>().find("fraction"), std::string::npos) << c.dump();
      EXPECT_EQ(find(a, mu, 0.5).at("status"), "ok");
    }
  // alpha0 = 90 deg hits the midspan of a symmetric beam along the normal: with linear kinematics
  // nothing moves tangentially, so friction cannot act and mu changes nothing. The paper run is
  // the same; IDA's regularised friction sees round-off tangential velocities: the reference
  // moves within its tolerance (rtol 1e-5), and so does every relative error norm.
  for (const auto& [name, v] : find(90, 0.0, 0.5).at("norms").items())
    EXPECT_NEAR(v.get<double>(), find(90, 0.6, 0.5).at("norms").at(name).get<double>(), 1e-5) << name;
  // At 45 deg the striker slides: friction changes the run (the override reached the scene) by far
  // more than that tolerance.
  EXPECT_GT(std::abs(find(45, 0.0, 0.5).at("norms").at("impulse").get<double>() -
                     find(45, 0.6, 0.5).at("norms").at("impulse").get<double>()),
            1e-4);
  // One progress line per point; the CSV has a header and one row per case.
  EXPECT_NE(out.find("[8/8]"), std::string::npos) << out;
  const std::string csv = read(tmp_ / "o/study.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9);
  EXPECT_EQ(csv.find("seconds"), std::string::npos);  // timing lives in timing.csv only
  EXPECT_NE(read(tmp_ / "o/timing.csv").find("seconds"), std::string::npos);
}

TEST_F(StudyCommand, APointWhoseOverridesFailKeepsEveryColumn) {
  // mu = -0.5 is refused when the rake after it loads the scene: the point's cases are errors,
  // and their rows still have one cell per header column (norms empty, not missing).
  const char* grid = R"(
[[parameter]]
name = "mu"
key = "contacts[0].friction"
values = [0.0, -0.5]
[[parameter]]
name = "alpha0"
rake = "A"
values = [90]
)";
  const auto [code, out] =
      run(fmt::format("study '{}' --out '{}'", study(grid).string(), (tmp_ / "o").string()));
  ASSERT_EQ(code, 0) << out;
  std::istringstream csv(read(tmp_ / "o/study.csv"));
  auto cells = [](const std::string& line) {  // commas outside double quotes, plus one
    int n = 1;
    bool quoted = false;
    for (char ch : line) {
      if (ch == '"') quoted = !quoted;
      n += ch == ',' && !quoted;
    }
    return n;
  };
  std::string header, line;
  std::getline(csv, header);
  int rows = 0, errors = 0;
  while (std::getline(csv, line)) {
    ++rows;
    errors += line.find(",error,") != std::string::npos;
    EXPECT_EQ(cells(line), cells(header)) << line;
  }
  EXPECT_EQ(rows, 2);
  EXPECT_EQ(errors, 1);
}

TEST_F(StudyCommand, BadStudyExitsTwoNamingFileAndKey) {
  const auto [code, out] =
      run(fmt::format("study '{}' --out '{}'",
                      study("[[parameter]]\nname = \"mu\"\nkey = \"contacts[0].friction\"\n").string(),
                      (tmp_ / "o").string()));
  EXPECT_EQ(code, 2) << out;
  EXPECT_NE(out.find("study.toml"), std::string::npos) << out;
  EXPECT_NE(out.find("parameter[0].values"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(tmp_ / "o/study.csv"));
}

// Every norm `beamimpact compare` gives for a run with one contact.
const char* kAllNorms =
    R"("R.rel_l2", "R.rel_linf", "I.rel_linf", "Rw.rel_l2", "Rw.rel_linf", "impulse", "impacts", )"
    R"("contact_start", "contact_end", "peak_R", "contact_starts", "contact_ends", "impulse_per_impact", )"
    R"("R_variation", )"
    R"("ua.rel_l2", "ua.rel_linf", "ub.rel_l2", "ub.rel_linf", "va.rel_l2", "va.rel_linf", "vb.rel_l2", )"
    R"("vb.rel_linf", "final_velocity", "energy_final", "energy_drift_per_impact")";

// A study row is `beamimpact compare` of the same two runs (the case's run against the point's
// reference), every norm column, to the bit: the study compares in memory what it wrote to its
// run directories, compare reads them back (history.csv holds round-trip decimals). The columns
// are every norm compare gives for one contact; two points, so rows and runs must also pair up.
TEST_F(StudyCommand, EachRowEqualsTheCompareCommandOnTheSameRuns) {
  const fs::path file = tmp_ / "rows.toml";
  std::ofstream(file) << "name = \"rows\"\nscene = \"" << BEAMIMPACT_SOURCE
                      << "/verification/scenes/paper/s1_central.toml\"\n"
                         "methods = [\"paper\"]\nreference = { method = \"exact\" }\nkeep_runs = true\n"
                         "norms = ["
                      << kAllNorms
                      << "]\n"
                         "[[parameter]]\nname = \"dt\"\nkey = \"time.dt\"\nvalues = [0.02, 0.005]\n";
  const auto [code, out] = run(fmt::format("study '{}' --out '{}'", file.string(), (tmp_ / "o").string()));
  ASSERT_EQ(code, 0) << out;
  const auto cases = nlohmann::json::parse(read(tmp_ / "o/study.json")).at("cases");
  ASSERT_EQ(cases.size(), 2u);
  for (const auto& c : cases) {
    ASSERT_EQ(c.at("status"), "ok") << c.dump();
    const int i = c.at("index").get<int>();
    const fs::path runs = tmp_ / "o/runs", json = tmp_ / fmt::format("compare{}.json", i);
    const auto [rc, log] =
        run(fmt::format("compare '{}' '{}' --json '{}'", (runs / fmt::format("{}.paper", i)).string(),
                        (runs / fmt::format("{}.reference", i)).string(), json.string()));
    ASSERT_EQ(rc, 0) << log;
    std::map<std::string, nlohmann::json> expected;
    const auto compared = nlohmann::json::parse(read(json));
    for (const auto& n : compared.at("norms")) expected[n.at("name").get<std::string>()] = n.at("value");
    int columns = 0;
    for (const auto& [name, v] : c.at("norms").items()) {
      ASSERT_TRUE(expected.count(name)) << name << " is no norm of " << json;
      EXPECT_EQ(v, expected.at(name)) << "case " << i << ", column " << name;
      ++columns;
    }
    EXPECT_EQ(columns, static_cast<int>(expected.size()));  // every norm compare gives is a column
    // The paper against the exact solution is not error-free: the equality is not of zeros.
    EXPECT_GT(c.at("norms").at("impulse").get<double>(), 1e-4);
  }
}

}  // namespace
}  // namespace beamimpact
