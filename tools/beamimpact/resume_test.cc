// Resuming `study` and `verify`: a command killed half-way (SIGKILL, or SIGINT as from Ctrl-C)
// and started again with the same command reuses the pieces it finished and ends with the same
// tables as a run that was never interrupted, byte for byte for the study's tables (only
// timing.csv and timing.json hold times) and value for value for verify's norms.json (its wall
// and solver times and start time apart). A record of another version or scene is not reused.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <tools/beamimpact/testing/cli_run.hpp>

extern char** environ;

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

using testing::read_file;

/// Files in dir whose name ends with `suffix`.
int count_files(const fs::path& dir, const std::string& suffix) {
  int n = 0;
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    n += e.path().filename().string().ends_with(suffix);
  return n;
}

using testing::processes_mentioning;

class ResumeBase : public testing::CliTest {
 protected:
  /// Runs beamimpact with args (one shell word each) in the source root; exit code and output.
  static testing::CliResult run(const std::vector<std::string>& args) {
    return testing::run_cli(testing::shell_words(args));
  }

  /// Starts beamimpact with args (SIGINT at its default action, as from a terminal), waits until
  /// `ready` holds, then sends `sig` and waits for the end. Returns the wait status.
  int interrupt(const std::vector<std::string>& args, const std::function<bool()>& ready, int sig) {
    std::vector<std::string> all{BEAMIMPACT_EXE};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, (tmp_ / "killed.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_adddup2(&fa, 1, 2);
    posix_spawn_file_actions_addchdir_np(&fa, BEAMIMPACT_SOURCE);  // as run() does
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
    pid_t pid = 0;
    EXPECT_EQ(posix_spawn(&pid, argv[0], &fa, &attr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&fa);
    posix_spawnattr_destroy(&attr);
    int status = 0;
    while (!ready()) {  // polled, not timed: the command's own progress decides when
      if (waitpid(pid, &status, WNOHANG) == pid) return status;  // it ended first: the caller fails
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    kill(pid, sig);
    waitpid(pid, &status, 0);
    return status;
  }
};

class Resume : public ResumeBase, public ::testing::WithParamInterface<int> {};

// Latin hypercube points of S4, the paper method against itself at an eighth of the step, up to
// time `end` (0.3 s: about a tenth of a second of work per point; the kill comes once three of
// twelve points are recorded).
fs::path write_study(const fs::path& dir, const std::string& scene, int samples = 12, double end = 0.3) {
  const fs::path file = dir / "s.toml";
  std::ofstream(file)
      << "name = \"resume\"\nscene = \"" << scene
      << "\"\nmethods = [\"paper\"]\n"
         "reference = { method = \"paper\", set = [\"time.fraction=0.125\"] }\n"
         "set = [\"model.kinematics=linear\", \"time.end="
      << end
      << "\", \"bodies.A.end=[5.0, 0.001]\"]\n"
         "[design]\nkind = \"lhs\"\nsamples = "
      << samples
      << "\n"
         "[[parameter]]\nname = \"alpha0\"\nrake = \"A\"\nfrom = 5.0\nto = 90.0\n"
         "[[parameter]]\nname = \"mu\"\nkey = \"contacts[0].friction\"\nfrom = 0.0\nto = 1.0\n";
  return file;
}

TEST_P(Resume, StudyKilledHalfWayEndsWithTheTablesOfAnUninterruptedOne) {
  const int sig = GetParam();
  const fs::path out = tmp_ / "o";
  const std::string scene = std::string(BEAMIMPACT_SOURCE) + "/verification/scenes/paper/s4_oblique_90.toml";
  const std::vector<std::string> cmd{"study", write_study(tmp_, scene).string(), "--out", out.string()};
  const auto [code, log] = run(cmd);
  ASSERT_EQ(code, 0) << log;
  const char* tables[] = {"study.csv", "study.json", "study.md"};  // timing.* hold the times
  std::map<std::string, std::string> whole;
  for (const char* t : tables) whole[t] = read(out / t);
  fs::remove_all(out);

  const int status = interrupt(
      cmd, [&] { return count_files(out / "points", ".json") >= 3; }, sig);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << read(tmp_ / "killed.txt");
  ASSERT_FALSE(fs::exists(out / "study.csv")) << "the study ended before the signal: nothing was resumed";
  const int finished = count_files(out / "points", ".json");
  ASSERT_LT(finished, 12);
  std::ofstream(out / "points" / "11.json.partial") << "{\"input\": {\"stu";  // a record cut short

  const auto [again, resumed] = run(cmd);
  ASSERT_EQ(again, 0) << resumed;
  EXPECT_NE(resumed.find(fmt::format("resumed: {} of 12 points finished earlier", finished)),
            std::string::npos)
      << resumed;
  EXPECT_NE(resumed.find(fmt::format("[{}/12]", finished + 1)), std::string::npos) << resumed;
  EXPECT_FALSE(fs::exists(out / "points" / "11.json.partial"));
  for (const char* t : tables) EXPECT_EQ(read(out / t), whole[t]) << t;
  const auto timing = nlohmann::json::parse(read(out / "timing.json"));
  EXPECT_EQ(timing.at("points_finished_earlier"), finished);
}

/// Replaces the version a record names (as if another build had written it).
void set_version(const fs::path& record, const std::string& version) {
  auto j = nlohmann::json::parse(read_file(record));
  auto& input = j.at("input");
  (input.contains("study") ? input.at("study") : input).at("program").at("version") = version;
  std::ofstream(record) << j.dump(1);
}

// Only a record of the same input is taken: not one of another version, nor one that cannot be
// read, nor any after the scene file changed (a comment is enough), nor any with --fresh. The
// tables stay the same throughout (the runs are deterministic).
TEST_F(ResumeBase, StudyTakesOnlyRecordsOfTheSameInput) {
  fs::copy_file(std::string(BEAMIMPACT_SOURCE) + "/verification/scenes/paper/s4_oblique_90.toml",
                tmp_ / "scene.toml");
  const fs::path out = tmp_ / "o";
  const std::vector<std::string> cmd{"study", write_study(tmp_, "scene.toml", 4, 0.03).string(), "--out",
                                     out.string()};
  auto expect_resumed = [&](int n, std::vector<std::string> args) {
    const auto [code, log] = run(args);
    ASSERT_EQ(code, 0) << log;
    if (n == 0)
      EXPECT_EQ(log.find("resumed:"), std::string::npos) << log;
    else
      EXPECT_NE(log.find(fmt::format("resumed: {} of 4 points", n)), std::string::npos) << log;
  };
  expect_resumed(0, cmd);
  const std::string table = read(out / "study.csv");
  expect_resumed(4, cmd);
  set_version(out / "points/0.json", "0.0.0+another");
  std::ofstream(out / "points/1.json") << "{\"input\": ";
  expect_resumed(2, cmd);
  std::vector<std::string> fresh = cmd;
  fresh.push_back("--fresh");
  expect_resumed(0, fresh);
  expect_resumed(4, cmd);
  std::ofstream(tmp_ / "scene.toml", std::ios::app) << "# the same scene, other bytes\n";
  expect_resumed(0, cmd);
  EXPECT_EQ(read(out / "study.csv"), table);
}

// The same rule for verify's runs: two runs of S1 (paper against the exact solution).
TEST_F(ResumeBase, VerifyTakesOnlyRunsOfTheSameInput) {
  fs::copy_file(std::string(BEAMIMPACT_SOURCE) + "/verification/scenes/paper/s1_central.toml",
                tmp_ / "s1.toml");
  std::ofstream(tmp_ / "m.toml")
      << "[settings]\nroot = \".\"\n[scenes]\ns1 = \"s1.toml\"\n[[case]]\n"
         "scene = \"s1\"\nmethod = \"paper\"\nreference = { method = \"exact\" }\n"
         "gates = [{ metric = \"impulse\", tol = 0.05, why = \"the paper at the scene step is within 0.2 % "
         "of the exact impulse; a loose bound: this test is about resuming\" }]\n";
  const fs::path out = tmp_ / "v";
  const std::vector<std::string> cmd{"verify", (tmp_ / "m.toml").string(), "--out", out.string()};
  auto expect_resumed = [&](int n) {
    const auto [code, log] = run(cmd);
    ASSERT_EQ(code, 0) << log;
    if (n == 0)
      EXPECT_EQ(log.find("resumed:"), std::string::npos) << log;
    else
      EXPECT_NE(log.find(fmt::format("resumed: {} of 2 runs", n)), std::string::npos) << log;
  };
  expect_resumed(0);
  expect_resumed(2);
  set_version(out / "runs/s1.paper/finished.json", "0.0.0+another");
  expect_resumed(1);
  std::ofstream(tmp_ / "s1.toml", std::ios::app) << "# the same scene, other bytes\n";
  expect_resumed(0);
}

/// norms.json without what measures time: started_utc and every *_seconds field.
nlohmann::json without_times(nlohmann::json j) {
  if (j.is_object()) {
    j.erase("started_utc");
    for (auto it = j.begin(); it != j.end();)
      it = it.key().ends_with("_seconds") ? j.erase(it) : std::next(it);
    for (auto& [k, v] : j.items()) v = without_times(v);
  } else if (j.is_array()) {
    for (auto& e : j) e = without_times(e);
  }
  return j;
}

/// report.md without its start time and wall time line and the gate tables' last column (wall s).
std::string without_times(const std::string& md) {
  const std::string a = std::regex_replace(md, std::regex("- started [^\n]*\n"), "");
  return std::regex_replace(a, std::regex("\\| [0-9]+\\.[0-9]{2} \\|\n"), "| (wall s) |\n");
}

// The S1 items of the quick tier (about 24 runs of paper, IDA, exact and FEniCSx, a few seconds),
// one job: killed once five runs are recorded.
TEST_P(Resume, VerifyKilledHalfWayEndsWithTheNormsOfAnUninterruptedOne) {
  const int sig = GetParam();
  const fs::path out = tmp_ / "v";
  const std::vector<std::string> cmd{
      "verify", "verification/matrix.toml", "--tier", "quick", "--only", "s1_central", "--out", out.string()};
  const auto [code, log] = run(cmd);
  ASSERT_EQ(code, 0) << log;
  const auto whole = without_times(nlohmann::json::parse(read(out / "norms.json")));
  const std::string whole_md = without_times(read(out / "report.md"));
  ASSERT_FALSE(whole.at("items").empty());
  std::smatch plan;
  ASSERT_TRUE(std::regex_search(log, plan, std::regex("([0-9]+) run\\(s\\)"))) << log;
  const int runs = std::stoi(plan[1]);
  fs::remove_all(out);

  const int status = interrupt(
      cmd, [&] { return count_files(out / "runs", "finished.json") >= 5; }, sig);
  if (sig == SIGINT)  // verify ends its runs and writes a report marked incomplete
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGINT) << read(tmp_ / "killed.txt");
  else
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << read(tmp_ / "killed.txt");
  // A SIGKILL leaves the run under way to finish alone: wait for it (polled) before the restart.
  while (!processes_mentioning(out.string()).empty())
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const int finished = count_files(out / "runs", "finished.json");
  ASSERT_LT(finished, runs) << "verify ended before the signal: nothing was resumed";

  const auto [again, resumed] = run(cmd);
  ASSERT_EQ(again, 0) << resumed;
  EXPECT_NE(resumed.find(fmt::format("resumed: {} of {} runs finished earlier", finished, runs)),
            std::string::npos)
      << resumed;
  EXPECT_EQ(without_times(nlohmann::json::parse(read(out / "norms.json"))), whole);
  EXPECT_EQ(without_times(read(out / "report.md")), whole_md);
}

INSTANTIATE_TEST_SUITE_P(Signals, Resume, ::testing::Values(SIGKILL, SIGINT),
                         [](const auto& p) { return p.param == SIGKILL ? "SIGKILL" : "SIGINT"; });

}  // namespace
}  // namespace beamimpact
