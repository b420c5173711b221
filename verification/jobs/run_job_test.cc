// One run, two ways: in this process (beamimpact::run) and isolated (a `beamimpact run`
// process). Both must leave the same run and the same typed outcome, so that a verification
// verdict does not depend on how its runs were started; a refusal comes back as the method's
// InputError (file and key), and a run past its time limit stops and fails in either way.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include <solver/util/ScratchDir.hpp>
#include <verification/jobs/run_job.hpp>

namespace beamimpact::jobs {
namespace {

namespace fs = std::filesystem;

const fs::path kScene = fs::path(BEAMIMPACT_SOURCE) / "verification/scenes/paper/s1_central.toml";

std::string bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

Launcher in_process() { return Launcher{}; }

Launcher isolated() {
  Launcher l;
  l.exe = BEAMIMPACT_EXE;
  return l;
}

TEST(RunJob, InProcessAndIsolatedRunsLeaveTheSameHistoryBytes) {
  const ScratchDir tmp(fs::temp_directory_path() / "beamimpact_run_job_test_1");
  const JobSpec spec{kScene, "paper", 0.01, "", {}};
  const JobOutcome a = run_job(spec, tmp.path() / "a", in_process(), 600.0);
  const JobOutcome b = run_job(spec, tmp.path() / "b", isolated(), 600.0);
  ASSERT_EQ(a.status, JobOutcome::Status::kOk) << a.message;
  ASSERT_EQ(b.status, JobOutcome::Status::kOk) << b.message;
  // The same scene, method and step through the same library: the same bits, whoever ran it.
  const std::string history = bytes(tmp.path() / "a/history.csv");
  EXPECT_GT(history.size(), 1000u);
  EXPECT_EQ(history, bytes(tmp.path() / "b/history.csv"));
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.dt, b.dt);
  ASSERT_TRUE(a.run && b.run);  // read once, when the run finished
  EXPECT_EQ(a.run->summary().at("contacts"), b.run->summary().at("contacts"));  // impulses, intervals
}

TEST(RunJob, ARefusalIsTheMethodsInputErrorInBothWays) {
  const ScratchDir tmp(fs::temp_directory_path() / "beamimpact_run_job_test_2");
  // The exact solutions take friction only between rigid bodies: S1's beams deform.
  const JobSpec spec{kScene, "exact", std::nullopt, "", {"contacts[0].friction=0.2"}};
  for (const auto& [name, launcher] :
       {std::pair{"in process", in_process()}, std::pair{"isolated", isolated()}}) {
    const JobOutcome o = run_job(spec, tmp.path() / name, launcher, 600.0);
    EXPECT_EQ(o.status, JobOutcome::Status::kNotApplicable) << name << ": " << o.message;
    ASSERT_TRUE(o.refusal) << name;
    EXPECT_EQ(o.refusal->key, "contacts[0].friction") << name;
    EXPECT_EQ(fs::path(o.refusal->file).filename(), "s1_central.toml") << name;
    EXPECT_NE(o.message.find("does not take friction where a body deforms"), std::string::npos) << name;
    EXPECT_FALSE(fs::exists(tmp.path() / name / "summary.json")) << name;
  }
}

TEST(RunJob, ARunPastItsTimeLimitFailsAndLeavesNoSummary) {
  const ScratchDir tmp(fs::temp_directory_path() / "beamimpact_run_job_test_3");
  // S1 at a step 10^4 times finer than the matrix's: tens of seconds of work, stopped after 0.5 s.
  const JobSpec spec{kScene, "paper", 1e-6, "", {"time.allow_long_run=true"}};
  for (const auto& [name, launcher] :
       {std::pair{"in process", in_process()}, std::pair{"isolated", isolated()}}) {
    const JobOutcome o = run_job(spec, tmp.path() / name, launcher, 0.5);
    EXPECT_EQ(o.status, JobOutcome::Status::kFailed) << name;
    EXPECT_NE(o.message.find("time limit"), std::string::npos) << name << ": " << o.message;
    EXPECT_FALSE(o.refusal) << name;
    EXPECT_FALSE(fs::exists(tmp.path() / name / "summary.json")) << name;
  }
}

}  // namespace
}  // namespace beamimpact::jobs
