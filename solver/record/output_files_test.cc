// The writer: docs/scene-format.md columns, and a non-finite value leaves nothing that looks complete.
#include <solver/record/output_files.hpp>

#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

SimulationResult one_row(double R) {
  SimulationResult r;
  r.method = "test";
  HistoryRow row;
  row.contacts.resize(2);
  row.contacts[0].R = R;
  r.history.push_back(row);
  return r;
}

Scene two_contacts() {
  Scene s;
  s.name = "t";
  s.contacts.resize(2);
  return s;
}

TEST(RunOutput, ColumnsRepeatPerContactWithSuffixes) {
  const auto c = history_columns(2);
  EXPECT_EQ(c.front(), "t");
  EXPECT_EQ(c[1], "R");
  EXPECT_NE(std::find(c.begin(), c.end(), "R_2"), c.end());
  EXPECT_NE(std::find(c.begin(), c.end(), "vb_y_2"), c.end());
  EXPECT_EQ(c.back(), "py");
}

TEST(RunOutput, WritesBothFiles) {
  const fs::path d = testing::temp_path("ro_ok");
  fs::remove_all(d);
  write_outputs(two_contacts(), one_row(1.5), d);
  EXPECT_TRUE(fs::exists(d / "history.csv"));
  EXPECT_TRUE(fs::exists(d / "summary.json"));
  std::ifstream h(d / "history.csv");
  std::string header, line;
  std::getline(h, header);
  std::getline(h, line);
  EXPECT_EQ(line.substr(0, 6), "0,1.5,");
}

// The writer produces every key the schema promises (the FEniCSx test holds the script to the
// same list), and the history header is the schema's.
TEST(RunOutput, SummaryHasEverySchemaKey) {
  SimulationResult r = one_row(1.5);
  r.contacts.resize(2);
  const nlohmann::json s = summary_json(two_contacts(), r);
  for (const std::string& k : summary_keys()) EXPECT_TRUE(s.contains(k)) << k;
  for (const std::string& k : contact_summary_keys()) EXPECT_TRUE(s.at("contacts").at(1).contains(k)) << k;
  const fs::path d = testing::temp_path("ro_keys");
  fs::remove_all(d);
  write_outputs(two_contacts(), r, d);
  std::ifstream h(d / "history.csv");
  std::string header;
  std::getline(h, header);
  std::string expected;
  for (const std::string& c : history_columns(2)) expected += (expected.empty() ? "" : ",") + c;
  EXPECT_EQ(header, expected);
  fs::remove_all(d);
}

TEST(RunOutput, NonFiniteValueWritesNothingComplete) {
  const fs::path d = testing::temp_path("ro_nan");
  fs::remove_all(d);
  write_outputs(two_contacts(), one_row(1.0), d);  // an earlier, complete result in the same place
  EXPECT_THROW(write_outputs(two_contacts(), one_row(std::nan("")), d), std::runtime_error);
  EXPECT_FALSE(fs::exists(d / "summary.json"));
  EXPECT_FALSE(fs::exists(d / "history.csv"));
}

}  // namespace
}  // namespace beamimpact
