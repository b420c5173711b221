// Interrupting `verify` (Ctrl-C, a CI time-out): the child runs and their process groups end, the
// report is written marked incomplete, the exit code is 128 + SIGINT.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>

#include <solver/testing/test_scenes.hpp>
#include <tools/beamimpact/testing/cli_run.hpp>

extern char** environ;

namespace {

namespace fs = std::filesystem;

using beamimpact::testing::processes_mentioning;
using beamimpact::testing::read_file;

TEST(Interruption, SigintToVerifyLeavesNoChildAndMarksTheReport) {
  const fs::path dir = beamimpact::testing::temp_path("interrupt");
  fs::create_directories(dir);
  // Two runs of 5e6 and 1e7 steps (several seconds each): still running when the signal comes.
  std::ofstream(dir / "m.toml") << fmt::format(R"([settings]
root = "{}"
[scenes]
s1 = "verification/scenes/paper/s1_central.toml"
[[case]]
scene = "s1"
method = "paper"
set = ["time.end=50000"]
reference = {{ method = "paper", set = ["time.end=50000", "time.dt=0.005"] }}
gates = [{{ metric = "impulse", tol = 0.1, why = "never evaluated: interrupted" }}]
)",
                                               BEAMIMPACT_SOURCE);
  const std::string out = (dir / "v").string();
  std::vector<std::string> args = {BEAMIMPACT_EXE, "verify", (dir / "m.toml").string(), "--out", out,
                                   "--jobs",       "2"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, (dir / "log.txt").c_str(), O_WRONLY | O_CREAT, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&fa);

  // Wait (at most 30 s) until both runs are going: two processes mention the output folder.
  for (int i = 0; i < 1500 && processes_mentioning(out + "/runs", pid).size() < 2; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_EQ(processes_mentioning(out + "/runs", pid).size(), 2u) << "the runs did not start";

  kill(pid, SIGINT);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  const std::string text = read_file(dir / "log.txt");
  ASSERT_TRUE(WIFEXITED(status)) << text;
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT) << text;
  EXPECT_TRUE(processes_mentioning(out, pid).empty()) << "a child run outlived verify";
  const std::string md = read_file(fs::path(out) / "report.md");
  EXPECT_NE(md.find("**INCOMPLETE: interrupted by signal 2"), std::string::npos) << md;
}

}  // namespace
