// Reading a run directory: good files parse, bad ones give one message naming file and column.
#include <verification/compare/StoredRun.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include <api/run.hpp>
#include <solver/record/output_files.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;

fs::path make_run(const std::string& name, const std::string& csv, bool summary = true) {
  const fs::path dir = beamimpact::testing::temp_path("rh_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "history.csv") << csv;
  if (summary) std::ofstream(dir / "summary.json") << R"({"method": "paper", "bodies": {}})";
  return dir;
}

std::string error_of(const fs::path& dir) {
  try {
    StoredRun::read(dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(StoredRun, ReadsColumnsAndContacts) {
  const auto dir = make_run("ok", "t,R,gap,R_2\n0,0,1,0\n0.01,2.5,0,1\n0.02,0,0.1,0\n");
  const auto h = StoredRun::read(dir);
  EXPECT_EQ(h.contacts(), 2);
  EXPECT_DOUBLE_EQ(h.column("R")[1], 2.5);
  EXPECT_DOUBLE_EQ(h.output_step(), 0.01);
  EXPECT_EQ(h.summary().at("method"), "paper");
  EXPECT_THROW(h.column("kinetic"), InputError);
  fs::remove_all(dir);
}

TEST(StoredRun, BadInputNamesFileAndColumn) {
  struct Case {
    std::string name, csv;
    bool summary;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {"noR", "t,gap\n0,1\n", true, "key 'R'"},
      {"nan", "t,R\n0,0\n0.01,nan\n", true, "row 3"},
      {"word", "t,R\n0,abc\n", true, "'abc'"},
      {"short", "t,R\n0,0\n0.01\n", true, "has 1 cells, expected 2"},
      {"time", "t,R\n0,0\n0,1\n", true, "strictly increasing"},
      {"nosummary", "t,R\n0,0\n", false, "summary.json"},
  };
  for (const auto& c : cases) {
    const auto dir = make_run(c.name, c.csv, c.summary);
    const std::string msg = error_of(dir);
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.name << ": " << msg;
    EXPECT_NE(msg.find(dir.string()), std::string::npos) << c.name << ": " << msg;
    fs::remove_all(dir);
  }
}

TEST(StoredRun, BadSummaryNamesTheKey) {
  // Each was read (null as 0) or ended in a raw JSON library error (type_error.304, exit 3).
  struct Case {
    std::string name, summary, expect;
  };
  const std::vector<Case> cases = {
      {"null", R"({"method": "paper", "energy_final": null})",
       "key '/energy_final': expected a value, found null"},
      {"intervals", R"({"contacts": [{"intervals": "x"}]})",
       "key 'contacts/0/intervals': expected an array of [start, end]"},
      {"interval3", R"({"contacts": [{"intervals": [[0, 1, 2]]}]})", "key 'contacts/0/intervals'"},
      {"impulse", R"({"contacts": [{"impulse_normal": "4"}]})",
       "key 'contacts/0/impulse_normal': expected a number"},
      {"bodies", R"({"bodies": []})", "key 'bodies': expected an object"},
      {"velocity", R"({"bodies": {"A": {"final_velocity": [1, 2, 3]}}})", "key 'bodies/A/final_velocity'"},
      {"array", "[1]", "expected a JSON object"},
  };
  for (const auto& c : cases) {
    const auto dir = make_run(c.name, "t,R\n0,0\n0.01,1\n");
    std::ofstream(dir / "summary.json") << c.summary;
    const std::string msg = error_of(dir);
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.name << ": " << msg;
    EXPECT_NE(msg.find((dir / "summary.json").string()), std::string::npos) << c.name << ": " << msg;
  }
}

// A run in memory is the run its directory holds: RunView::from_result gives the columns and the
// summary's numbers that read() gets back from the files write_outputs writes (both formats
// round-trip every double), so a comparison does not depend on which of the two it was given.
TEST(StoredRun, ViewFromResultEqualsTheRunDirectory) {
  const Scene scene = beamimpact::testing::load_paper_scene("s1_central", {"time.end=3.0"});
  const SimulationResult r = beamimpact::run(scene, "paper");
  const fs::path dir = beamimpact::testing::temp_path("rh_from_result");
  fs::remove_all(dir);
  write_outputs(scene, r, dir);
  const StoredRun stored = StoredRun::read(dir);
  const RunView disk = stored.view(), memory = RunView::from_result(scene, r, "memory");
  ASSERT_GT(disk.t().size(), 10u);
  EXPECT_EQ(*memory.columns, *disk.columns);
  ASSERT_EQ(memory.contacts_summary.size(), 1u);
  EXPECT_EQ(memory.contacts_summary, disk.contacts_summary);
  // S1's exact impulse is m v0 / 2 = 4 N s; the paper's 10-element run is within 5 % of it.
  EXPECT_NEAR(*memory.contacts_summary[0].impulse_normal, 4.0, 0.2);
  EXPECT_FALSE(memory.contacts_summary[0].intervals->empty());
  EXPECT_EQ(memory.final_velocity, disk.final_velocity);
  EXPECT_EQ(memory.final_velocity->size(), 2u);
  EXPECT_EQ(memory.scene_sha256, disk.scene_sha256);
  EXPECT_EQ(memory.scene_sha256, scene.sha256);
  fs::remove_all(dir);
}

TEST(StoredRun, ViewFromResultRefusesANonFiniteValue) {
  const Scene scene = beamimpact::testing::load_paper_scene("s1_central", {"time.end=0.1"});
  SimulationResult r = beamimpact::run(scene, "paper");
  r.history.back().kinetic = std::nan("");
  EXPECT_THROW(RunView::from_result(scene, r, "memory"), std::runtime_error);
}

// A summary given in memory (Python's compare) with a wrong type is bad input naming the key.
TEST(StoredRun, ViewRefusesAWrongSummaryType) {
  const StoredRun h = StoredRun::from_columns({{"t", {0.0, 0.01}}, {"R", {0.0, 1.0}}},
                                              {{"contacts", {{{"impulse_normal", "4"}}}}}, "mem");
  try {
    (void)h.view();
    FAIL() << "a string impulse was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "contacts/0/impulse_normal") << e.what();
  }
}

}  // namespace
}  // namespace beamimpact::verification
