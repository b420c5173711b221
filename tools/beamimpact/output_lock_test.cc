// End to end: while another process holds an output directory (its OutputLock), every command
// that writes a folder exits 2 with one line naming the directory and the holder's pid, and
// removes or writes nothing there; after the holder ends the directory is free again.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include <solver/testing/test_scenes.hpp>
#include <solver/util/OutputLock.hpp>
#include <tools/beamimpact/testing/cli_run.hpp>

namespace {

namespace fs = std::filesystem;
using beamimpact::OutputLock;
using beamimpact::testing::paper_scene;

using beamimpact::testing::CliResult;
using beamimpact::testing::fresh_dir;
using beamimpact::testing::read_file;

CliResult run(const std::string& args) {
  // timeout: a command that wrongly ignored the lock would otherwise run its whole work here
  return beamimpact::testing::run_cli(args, "timeout 120");
}

/// The refusal every command gives while this test process holds the directory.
void expect_refused(const CliResult& r, const fs::path& dir, const std::string& what) {
  EXPECT_EQ(r.code, 2) << what << ": " << r.output;
  EXPECT_NE(r.output.find(dir.string()), std::string::npos) << what << ": " << r.output;
  EXPECT_NE(r.output.find("pid " + std::to_string(getpid())), std::string::npos) << what << ": " << r.output;
  EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << what << ": one line: " << r.output;
}

TEST(OutputLockCli, SecondRunRefusedAndTheFirstRunsOutputsIntact) {
  const fs::path d = fresh_dir("run");
  const std::string cmd = "run " + paper_scene("s1_central") + " --quiet --out " + d.string();
  ASSERT_EQ(run(cmd).code, 0);
  const std::string summary = read_file(d / "summary.json"), history = read_file(d / "history.csv");
  {
    const OutputLock first(d);  // a first writer still at work in d
    expect_refused(run(cmd), d, "run");
    EXPECT_EQ(read_file(d / "summary.json"), summary);
    EXPECT_EQ(read_file(d / "history.csv"), history);
  }
  EXPECT_EQ(run(cmd).code, 0) << "the directory is free once its holder has ended";
  EXPECT_NO_THROW(OutputLock{d}) << "and the run released it when it exited";
}

TEST(OutputLockCli, EveryCommandWritingAFolderIsRefused) {
  const fs::path runs = fresh_dir("source");
  ASSERT_EQ(run("run " + paper_scene("s1_central") + " --quiet --out " + runs.string()).code, 0);
  struct Case {
    std::string what, args, output;  // output: a file of an earlier result that must stay
  };
  const fs::path d = fresh_dir("every");
  const std::string o = " --out " + d.string();
  const std::vector<Case> cases = {
      {"verify", "verify verification/matrix.toml --only s1_central" + o, "report.md"},
      {"sweep", "sweep " + paper_scene("s1_central") + " --dt 0.01" + o, "sweep.csv"},
      {"study", "study verification/studies/s4_throughput.toml" + o, "study.csv"},
      {"compare",
       "compare " + runs.string() + " " + runs.string() + " --json " + (d / "compare.json").string(),
       "compare.json"},
      {"model", "model " + paper_scene("s1_central") + o, "model.json"},
      {"score", "score paper" + o, "scorecard.json"},
      {"conform", "conform example" + o, "junit.xml"},
  };
  const OutputLock held(d);
  for (const Case& c : cases) {
    std::ofstream(d / c.output) << "earlier " << c.what;
    expect_refused(run(c.args), d, c.what);
    EXPECT_EQ(read_file(d / c.output), "earlier " + c.what) << c.what;
  }
}

}  // namespace
