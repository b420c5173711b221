// Interrupting `verify` (Ctrl-C, a CI time-out): the runs end (isolated: the child processes and
// their process groups; in verify's own process: at their next RunLimit check), the report is
// written marked incomplete, the exit code is 128 + SIGINT.
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

/// Starts `verify` on two long runs (with `--isolate` when isolate), waits until both are going,
/// interrupts it and checks the exit code and the report; returns the seconds from the signal to
/// its end.
double interrupt_verify(bool isolate) {
  const fs::path dir = beamimpact::testing::temp_path(isolate ? "interrupt_isolated" : "interrupt");
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
  if (isolate) args.push_back("--isolate");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, (dir / "log.txt").c_str(), O_WRONLY | O_CREAT, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&fa);

  // Wait (at most 30 s) until both runs are going: two processes mention the output folder
  // (isolated), or two run.log files are there (in verify's process).
  const auto going = [&]() -> std::size_t {
    if (isolate) return processes_mentioning(out + "/runs", pid).size();
    std::error_code ec;
    std::size_t n = 0;
    for (const auto& d : fs::directory_iterator(out + "/runs", ec)) n += fs::exists(d.path() / "run.log");
    return n;
  };
  for (int i = 0; i < 1500 && going() < 2; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(going(), 2u) << "the runs did not start";
  std::this_thread::sleep_for(std::chrono::milliseconds(200));

  kill(pid, SIGINT);
  const auto signalled = std::chrono::steady_clock::now();
  int status = 0;
  EXPECT_EQ(waitpid(pid, &status, 0), pid);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count();
  const std::string text = read_file(dir / "log.txt");
  EXPECT_TRUE(WIFEXITED(status)) << text;
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT) << text;
  EXPECT_TRUE(processes_mentioning(out, pid).empty()) << "a child run outlived verify";
  const std::string md = read_file(fs::path(out) / "report.md");
  EXPECT_NE(md.find("**INCOMPLETE: interrupted by signal 2"), std::string::npos) << md;
  return seconds;
}

TEST(Interruption, SigintToVerifyLeavesNoChildAndMarksTheReport) { interrupt_verify(true); }

TEST(Interruption, SigintToVerifyStopsItsOwnRunsAndMarksTheReport) {
  // Each run is 5e6 steps, seconds of work: a run that ignored the interruption would hold verify
  // that long. Stopped at their next check (every 256 steps), they end at once; 3 s is the margin
  // of a loaded machine for writing the report.
  EXPECT_LT(interrupt_verify(false), 3.0);
}

}  // namespace
