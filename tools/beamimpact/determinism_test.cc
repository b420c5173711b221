// Determinism: the same scene gives byte-identical history.csv and summary.json (apart from the
// wall time, its own line "wall_seconds", and the cost rates made from it) across reruns and across
// verify --jobs values.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <solver/testing/test_scenes.hpp>
#include <tools/beamimpact/testing/cli_run.hpp>

namespace {

namespace fs = std::filesystem;

using beamimpact::testing::read_file;

/// summary.json without its "wall_seconds" line and the cost rates made from it ("ns_per_...":
/// cost.ns_per_dof_step, cost.ns_per_element_step), the fields that may differ.
std::string without_wall_time(const std::string& json) {
  std::istringstream in(json);
  std::string out;
  for (std::string line; std::getline(in, line);)
    if (line.find("\"wall_seconds\"") == std::string::npos && line.find("\"ns_per_") == std::string::npos)
      out += line + "\n";
  return out;
}

/// The lines of a summary that name the threads (asked for: overrides; used: "threads").
/// The summary without what names the threads: the count used, its note, settings.threads and a
/// warning that capped them to the cores.
std::string without_threads(const std::string& json) {
  nlohmann::json j = nlohmann::json::parse(json);
  j.erase("threads");
  j.erase("threads_note");
  if (j.contains("settings")) j["settings"].erase("threads");
  if (j.contains("warnings")) {
    nlohmann::json kept = nlohmann::json::array();
    for (const auto& w : j["warnings"])
      if (w.get<std::string>().find("threads asked for") == std::string::npos) kept.push_back(w);
    if (kept.empty())
      j.erase("warnings");
    else
      j["warnings"] = kept;
  }
  return j.dump(2);
}

void expect_same_run(const fs::path& a, const fs::path& b) {
  ASSERT_TRUE(fs::exists(a / "summary.json")) << a;
  ASSERT_TRUE(fs::exists(b / "summary.json")) << b;
  EXPECT_EQ(read_file(a / "history.csv"), read_file(b / "history.csv")) << a << " vs " << b;
  const std::string sa = read_file(a / "summary.json"), sb = read_file(b / "summary.json");
  EXPECT_NE(sa.find("\"wall_seconds\""), std::string::npos) << "wall time kept in its own field";
  EXPECT_EQ(without_wall_time(sa), without_wall_time(sb)) << a << " vs " << b;
}

/// Runs beamimpact with args in the source root; its exit code.
int beamimpact(const std::string& args) { return beamimpact::testing::run_cli(args).code; }

TEST(Determinism, RerunsGiveIdenticalFiles) {
  const fs::path dir = beamimpact::testing::temp_path("rerun");
  for (const auto& [scene, method] :
       {std::pair{"s2_transverse", "paper"}, std::pair{"s2_transverse", "ida"},
        std::pair{"s1_central", "exact"}, std::pair{"s4_oblique_45", "paper"}}) {
    const fs::path a = dir / (std::string(scene) + method + "_a"),
                   b = dir / (std::string(scene) + method + "_b");
    for (const fs::path& out : {a, b})
      ASSERT_EQ(beamimpact(fmt::format("run verification/scenes/paper/{}.toml --method {} --out '{}' --quiet",
                                       scene, method, out.string())),
                0);
    expect_same_run(a, b);
  }
}

TEST(Determinism, ThreadsDoNotChangeTheRuns) {
  // The element sweep split over 2 and 3 threads sums every entry in the one-thread order:
  // history.csv is the same bytes, summary.json too apart from the threads asked for and used.
  // A count above the cores runs on the cores (the split itself at 3 parts on a machine with fewer
  // cores: Threads.*GiveTheBitsOfOneThread, on the integrator).
  // Rods (S1, 40 + 41 elements: splits at the bodies' edge and inside both) and frames (S2, 20 +
  // 40: inside B's chain and at the edge), each through its contact.
  const fs::path dir = beamimpact::testing::temp_path("threads");
  for (const auto& [scene, sets] :
       {std::pair{"s1_central",
                  "--set bodies.A.elements=40 --set bodies.B.elements=41 --set 'time.dt=\"auto\"'"},
        std::pair{"s2_transverse",
                  "--set bodies.A.elements=20 --set bodies.B.elements=40 --set 'time.dt=\"auto\"'"}}) {
    std::vector<fs::path> outs;
    for (int threads : {1, 2, 3}) {
      outs.push_back(dir / fmt::format("{}_{}", scene, threads));
      ASSERT_EQ(
          beamimpact(fmt::format("run verification/scenes/paper/{}.toml {} --threads {} --out '{}' --quiet",
                                 scene, sets, threads, outs.back().string())),
          0);
      const auto j = nlohmann::json::parse(read_file(outs.back() / "summary.json"));
      EXPECT_EQ(j["threads"], std::min(threads, beamimpact::testing::cores_of_this_process())) << scene;
    }
    for (int k : {1, 2}) {
      EXPECT_EQ(read_file(outs[0] / "history.csv"), read_file(outs[k] / "history.csv")) << outs[k];
      EXPECT_EQ(without_wall_time(without_threads(read_file(outs[0] / "summary.json"))),
                without_wall_time(without_threads(read_file(outs[k] / "summary.json"))))
          << outs[k];
    }
  }
}

TEST(Determinism, VerifyJobsDoNotChangeTheRuns) {
  const fs::path dir = beamimpact::testing::temp_path("jobs");
  for (int jobs : {1, 2})
    ASSERT_EQ(beamimpact(fmt::format("verify verification/matrix.toml --only 's1_central paper dt=0.01 vs' "
                                     "--out '{}' --jobs {}",
                                     (dir / std::to_string(jobs)).string(), jobs)),
              0);
  int compared = 0;
  for (const auto& e : fs::directory_iterator(dir / "1" / "runs")) {
    expect_same_run(e.path(), dir / "2" / "runs" / e.path().filename());
    ++compared;
  }
  EXPECT_GE(compared, 2) << "the case's run and its reference";
}

}  // namespace
