// Outside programs end with beamimpact: an external method's run and a methods file's check run in
// their own process group, which SIGTERM to beamimpact ends (the output lock held until it is
// gone), and a check has a time limit (check_timeout).
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

/// Starts beamimpact with `args` (stdout and stderr to log); returns its pid.
pid_t start(std::vector<std::string> args, const fs::path& log) {
  args.insert(args.begin(), BEAMIMPACT_EXE);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&fa);
  return pid;
}

/// Waits (at most 20 s) until `count` processes other than `except` mention `text`.
bool wait_for(const std::string& text, std::size_t count, pid_t except) {
  for (int i = 0; i < 1000; ++i) {
    if (processes_mentioning(text, except).size() >= count) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

class ChildProcess : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = beamimpact::testing::temp_path("children");
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(ChildProcess, SigtermToRunEndsTheSolverAndItsChildrenBeforeTheLockIsFreed) {
  // The stand-in solver starts a helper in the background and both sleep 4 s, then write into the
  // run directory: a process left behind would write there after beamimpact has gone.
  std::ofstream(dir_ / "slow.sh") << R"T(#!/bin/sh
python3 -c 'import sys, time; time.sleep(4); open(sys.argv[1] + "/late_helper.txt", "w").write("late")' "$2" &
python3 -c 'import sys, time; time.sleep(4); open(sys.argv[1] + "/late.txt", "w").write("late")' "$2"
)T";
  std::ofstream(dir_ / "methods.toml") << R"T([[method]]
name = "slowpoke"
command = ["/bin/sh", "{here}/slow.sh", "{scene}", "{out}"]
)T";
  const fs::path out = dir_ / "run";
  const pid_t pid =
      start({"run", fmt::format("{}/verification/scenes/paper/s1_central.toml", BEAMIMPACT_SOURCE),
             "--method", "slowpoke", "--methods", (dir_ / "methods.toml").string(), "--out", out.string()},
            dir_ / "log.txt");
  // The solver and its helper both mention the run directory.
  ASSERT_TRUE(wait_for(out.string(), 2, pid)) << read_file(dir_ / "log.txt");
  kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << read_file(dir_ / "log.txt");
  // When beamimpact has ended (and its lock with it), no child of it is left ...
  EXPECT_TRUE(processes_mentioning(out.string(), pid).empty()) << "a child outlived beamimpact";
  // ... and nothing writes into the directory later.
  std::this_thread::sleep_for(std::chrono::seconds(5));
  EXPECT_FALSE(fs::exists(out / "late.txt"));
  EXPECT_FALSE(fs::exists(out / "late_helper.txt"));
}

TEST_F(ChildProcess, ACheckThatNeverEndsIsEndedAtItsTimeLimit) {
  // A check that sleeps 1000 s, limited to 1 s: `methods` ends within a few seconds, lists the
  // method as not runnable here, and leaves no check running.
  std::ofstream(dir_ / "methods.toml") << R"T([[method]]
name = "hangs"
command = ["/bin/sh", "{here}/never.sh", "{scene}", "{out}"]
check = ["/usr/bin/python3", "-c", "import time; time.sleep(1000)", "{here}/check-marker"]
check_timeout = 1.0
)T";
  std::ofstream(dir_ / "never.sh") << "exit 1\n";
  const auto t0 = std::chrono::steady_clock::now();
  const beamimpact::testing::CliResult r =
      beamimpact::testing::run_cli("methods --methods " + (dir_ / "methods.toml").string(), "timeout 60");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(seconds, 20.0) << r.output;  // 1 s limit, 2 s grace at most, start-up
  EXPECT_NE(r.output.find("time limit"), std::string::npos) << r.output;
  EXPECT_TRUE(processes_mentioning((dir_ / "check-marker").string()).empty()) << "the check outlived it";
}

TEST_F(ChildProcess, SigtermDuringACheckEndsTheCheck) {
  std::ofstream(dir_ / "methods.toml") << R"T([[method]]
name = "hangs"
command = ["/bin/sh", "{here}/never.sh", "{scene}", "{out}"]
check = ["/usr/bin/python3", "-c", "import time; time.sleep(1000)", "{here}/check-marker"]
check_timeout = 600
)T";
  std::ofstream(dir_ / "never.sh") << "exit 1\n";
  const std::string marker = (dir_ / "check-marker").string();
  const pid_t pid = start({"methods", "--methods", (dir_ / "methods.toml").string()}, dir_ / "log.txt");
  ASSERT_TRUE(wait_for(marker, 1, pid)) << read_file(dir_ / "log.txt");
  kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(processes_mentioning(marker, pid).empty()) << "the check outlived beamimpact";
}

}  // namespace
