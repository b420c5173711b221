// RunOptions::dt and RunOptions::mesh are typed edits of the parsed scene (solver/scene/Override):
// a run with them is the run of the scene file that says the same, bit for bit, and its
// summary.json records them as the --set text it always recorded.
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <api/run.hpp>
#include <solver/record/output_files.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/Progress.hpp>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// A copy of S1 (two free 10-element rods) with `from` replaced by `to`, in a temporary file.
fs::path edited_s1(const std::string& from, const std::string& to, const std::string& name) {
  const std::string text = read_text(testing::paper_scene("s1_central"));
  const std::string edited = std::regex_replace(text, std::regex(from), to);
  EXPECT_NE(edited, text) << from;
  const fs::path p = testing::temp_path(name);
  std::ofstream(p) << edited;
  return p;
}

fs::path run_dir(const std::string& name) {
  return fs::temp_directory_path() / ("beamimpact_typed_" + name + "_" + std::to_string(::getpid()));
}

// The same scene, one step asked for by RunOptions::dt and one written in the file: the same
// rows, every bit (history.csv writes shortest round-trip decimals), and the run records the step
// as `--set time.dt=` with 17 digits did ("0.0040000000000000001"), so that finished-run records
// do not change with the way the step is passed.
TEST(TypedOptions, StepIsTheRunOfTheFileWithThatStep) {
  Progress::set_enabled(false);
  const fs::path file = edited_s1(R"(dt = 0\.01 )", "dt = 0.004 ", "s1_dt_0004.toml");
  const fs::path a = run_dir("dt"), b = run_dir("file");
  RunOptions o;
  o.set = {"time.end=1.5"};
  o.dt = 0.004;
  o.out = a;
  const SimulationResult ra = run(testing::paper_scene("s1_central"), "paper", o);
  const SimulationResult rb = run(file, "paper", RunOptions{{"time.end=1.5"}, b});
  ASSERT_GT(ra.history.size(), 300u);  // 1.5 s / 0.004 s rows: the step took effect
  EXPECT_EQ(read_text(a / "history.csv"), read_text(b / "history.csv"));
  EXPECT_EQ(ra.contacts.at(0).impulse_normal, rb.contacts.at(0).impulse_normal);
  const nlohmann::json s = nlohmann::json::parse(read_text(a / "summary.json"));
  EXPECT_EQ(s.at("overrides").at("time.dt"), "0.0040000000000000001");
  EXPECT_EQ(s.at("overrides").at("time.end"), "1.5");
  fs::remove_all(a);
  fs::remove_all(b);
}

// A method that picks its own step refuses RunOptions::dt as it refused --set time.dt: naming the
// scene file, the key time.dt and what it expected. A step that is not positive names --dt.
TEST(TypedOptions, RefusedStepNamesFileAndKey) {
  RunOptions o;
  o.dt = 0.005;
  try {
    run(testing::paper_scene("s1_central"), "fenicsx", o);
    FAIL() << "fenicsx took a step";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.key(), "time.dt") << what;
    EXPECT_NE(what.find("s1_central.toml"), std::string::npos) << what;
    EXPECT_NE(what.find("does not take a time step"), std::string::npos) << what;
  }
  o.dt = -1.0;
  try {
    run(testing::paper_scene("s1_central"), "paper", o);
    FAIL() << "a negative step ran";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "--dt") << e.what();
  }
  // The stability check still sees the step: S1's critical step is le / c = 1 m / (10 m/s) = 0.1 s.
  o.dt = 0.2;
  EXPECT_THROW(run(testing::paper_scene("s1_central"), "paper", o), InputError);
}

// RunOptions::mesh = "2" doubles every body's element count of the file: the run of the file with
// 20 + 20 elements, every bit, recorded as the element overrides the --set text recorded.
TEST(TypedOptions, MeshIsTheRunOfTheFileWithThoseElements) {
  Progress::set_enabled(false);
  const fs::path file = edited_s1("elements = 10", "elements = 20", "s1_20.toml");
  const fs::path a = run_dir("mesh"), b = run_dir("mesh_file");
  RunOptions o;
  o.set = {"time.end=1.5"};
  o.mesh = "2";
  o.out = a;
  const SimulationResult ra = run(testing::paper_scene("s1_central"), "paper", o);
  (void)run(file, "paper", RunOptions{{"time.end=1.5"}, b});
  EXPECT_EQ(read_text(a / "history.csv"), read_text(b / "history.csv"));
  const nlohmann::json s = nlohmann::json::parse(read_text(a / "summary.json"));
  EXPECT_EQ(s.at("overrides").at("bodies[0].elements"), "20");
  EXPECT_EQ(s.at("overrides").at("bodies[1].elements"), "20");
  EXPECT_FALSE(ra.history.empty());
  fs::remove_all(a);
  fs::remove_all(b);
}

}  // namespace
}  // namespace beamimpact
