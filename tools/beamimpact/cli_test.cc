// End-to-end: the `beamimpact` binary's exit codes, messages and outputs for good and bad input.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <solver/testing/test_scenes.hpp>
#include <tools/beamimpact/testing/cli_run.hpp>

namespace {

namespace fs = std::filesystem;
using beamimpact::testing::paper_scene;
using Result = beamimpact::testing::CliResult;
using beamimpact::testing::cores_of_this_process;
using beamimpact::testing::fresh_dir;
using beamimpact::testing::run_cli;

std::string bad_scene(const std::string& from, const std::string& to) {
  std::ifstream in(paper_scene("s2_transverse"));
  std::string s(std::istreambuf_iterator<char>(in), {});
  s.replace(s.find(from), from.size(), to);
  static int count = 0;  // one file per case: all cases are built before any runs
  const std::string path =
      beamimpact::testing::temp_path("cli_bad_" + std::to_string(++count) + ".toml").string();
  std::ofstream(path) << s;
  return path;
}

TEST(Cli, RunWritesHistoryAndSummary) {
  const fs::path out = fresh_dir("ok");
  const Result r = run_cli("run " + paper_scene("s1_central") + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream h(out / "history.csv");
  std::string header;
  std::getline(h, header);
  EXPECT_EQ(header.rfind("t,R,tau,gap,ua_x,ua_y,va_x,va_y,ub_x,ub_y,vb_x,vb_y", 0), 0u) << header;
  const auto j = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(j["method"], "paper");
  EXPECT_EQ(j["steps"], 400);
  EXPECT_EQ(j["effects"], nlohmann::json::array({"axial"}));
  EXPECT_TRUE(j["complete"].get<bool>());
  EXPECT_EQ(j["contacts"][0]["intervals"].size(), 1u);
  EXPECT_NEAR(j["contacts"][0]["impulse_normal"].get<double>(), 4.0, 0.16);  // exact 4 N s, 4 % mesh error
}

TEST(Cli, ThreadsUsedAndWhyFewerAreInTheSummary) {
  // summary.json "threads" is the count used: the default 1 for S1's 66 equations (below the
  // size where threads pay, written into assumed), 2 when asked on S2 refined (the fused step),
  // by --threads or by the scene's [paper] threads, --threads taken over the scene's, 1 with the
  // reason on S4-45 (corotational: its step is not split).
  struct Case {
    std::string args;
    int used;
    bool note;
  };
  const std::string s2_refined =
      paper_scene("s2_transverse") +
      " --set bodies.A.elements=20 --set bodies.B.elements=40 --set 'time.dt=\"auto\"'";
  const int two = std::min(2, cores_of_this_process());  // 2 asked: capped to the cores
  for (const Case& c : {Case{"run " + paper_scene("s1_central"), 1, false},
                        Case{"run " + s2_refined + " --threads 2", two, false},
                        Case{"run " + s2_refined + " --set paper.threads=2", two, false},
                        Case{"run " + s2_refined + " --set paper.threads=1 --threads 2", two, false},
                        Case{"run " + s2_refined + " --set paper.threads=2 --threads 1", 1, false},
                        Case{"run " + paper_scene("s4_oblique_45") + " --threads 2", 1, true}}) {
    const fs::path out = fresh_dir("threads");
    const Result r = run_cli(c.args + " --quiet --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.output;
    const auto j = nlohmann::json::parse(std::ifstream(out / "summary.json"));
    EXPECT_EQ(j["threads"], c.used) << c.args;
    EXPECT_EQ(j.contains("threads_note"), c.note) << c.args;
    if (c.args.find("threads") == std::string::npos) {
      EXPECT_EQ(j["assumed"]["paper.threads"].get<std::string>().rfind("1: the machine's", 0), 0u) << c.args;
    }
  }
}

// More threads than cores (64, or the most a run takes on a machine with 64 cores or more):
// the run takes the cores (std::thread::hardware_concurrency, fewer under the CPU affinity mask),
// says so in one warning line on stderr and in summary.json's settings.threads (asked, cores,
// used, why), and its history is the same bytes as on one thread (the split sweep sums every
// equation in the one thread's order: docs/threads.md).
TEST(Cli, ThreadsAboveTheCoresAreCappedAndChangeNoBit) {
  const int cores = cores_of_this_process();
  const int asked = cores < 64 ? 64 : 1024;
  const std::string s2_refined =
      paper_scene("s2_transverse") +
      " --set bodies.A.elements=20 --set bodies.B.elements=40 --set 'time.dt=\"auto\"' --quiet";
  const fs::path many = fresh_dir("threads_many"), one = fresh_dir("threads_one");
  const Result r =
      run_cli("run " + s2_refined + " --threads " + std::to_string(asked) + " --out " + many.string());
  ASSERT_EQ(r.code, 0) << r.output;
  ASSERT_EQ(run_cli("run " + s2_refined + " --threads 1 --out " + one.string()).code, 0);
  const auto j = nlohmann::json::parse(std::ifstream(many / "summary.json"));
  const auto& t = j["settings"]["threads"];
  EXPECT_EQ(t["asked"], asked);
  EXPECT_EQ(t["cores"], cores);
  EXPECT_EQ(t["used"], cores);  // 60 elements: two a thread at least for up to 30 cores
  EXPECT_EQ(j["threads"], cores);
  const std::string why = t["why"].get<std::string>();
  EXPECT_NE(why.find(std::to_string(asked) + " threads asked for; cores available: " + std::to_string(cores)),
            std::string::npos)
      << why;
  EXPECT_NE(why.find("capped to " + std::to_string(cores)), std::string::npos) << why;
  const std::string line = "warning: " + why + "\n";
  EXPECT_NE(r.output.find(line), std::string::npos) << r.output;  // one line on stderr
  EXPECT_EQ(r.output.find("warning:"), r.output.rfind("warning:")) << r.output;
  const std::string h = beamimpact::testing::read_file(many / "history.csv");
  EXPECT_FALSE(h.empty());
  EXPECT_EQ(h, beamimpact::testing::read_file(one / "history.csv"));
}

struct Bad {
  const char* what;
  std::string args;
  const char* says;
};

/// Each case exits 2 with one message saying c.says, and writes no result.
void expect_refused(const std::vector<Bad>& cases) {
  for (const Bad& c : cases) {
    const fs::path out = fresh_dir("bad");
    const Result r = run_cli(c.args + " --out " + out.string());
    EXPECT_EQ(r.code, 2) << c.what << ": " << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << c.what << ": " << r.output;
    EXPECT_EQ(r.output.find("error:"), r.output.rfind("error:")) << c.what << ": one message";
    EXPECT_FALSE(fs::exists(out / "summary.json")) << c.what;
    EXPECT_FALSE(fs::exists(out / "history.csv")) << c.what;
  }
}

TEST(Cli, BadInputExitsTwoWithOneMessageAndNoResult) {
  const std::vector<Bad> cases = {
      {"missing file", "run /nonexistent/scene.toml", "cannot open the scene file"},
      {"malformed", "run " + bad_scene("[time]", "[time"), "TOML syntax error"},
      {"unknown key", "run " + bad_scene("output_every = 1", "output_evry = 1"),
       "key 'time.output_evry': unknown key"},
      {"negative length area", "run " + bad_scene("area = 0.4", "area = -1"),
       "key 'bodies[0].area': expected a positive number (m^2)"},
      {"contact node", "run " + bad_scene("node = \"end\"", "node = 9"), "key 'contacts[0].node'"},
      {"overlap", "run " + bad_scene("end = [5.0, 0.1]", "end = [5.0, -0.5]"), "overlap at t = 0"},
      {"zero initial gap", "run " + bad_scene("end = [5.0, 0.1]", "end = [5.0, 0.0]"),
       "key 'contacts[0].node': the striker node of 'A' at (5, 0) m touches target 'B' at t = 0 (zero "
       "initial gap)"},
      {"zero initial gap, ida", "run " + bad_scene("end = [5.0, 0.1]", "end = [5.0, 0.0]") + " --method ida",
       "(zero initial gap)"},
      {"zero initial gap, exact",
       "run " + bad_scene("end = [5.0, 0.1]", "end = [5.0, 0.0]") + " --method exact", "(zero initial gap)"},
      {"dt above critical", "run " + paper_scene("s2_transverse") + " --set time.dt=0.1",
       "key 'time.dt': expected at most the critical step"},
      {"unknown method", "run " + paper_scene("s1_central") + " --method magic", "key '--method'"},
      {"unknown support direction", "run " + bad_scene("fix = [\"y\"]", "fix = [\"across\"]"),
       "key 'bodies[1].supports[1].fix': expected some of \"x\", \"y\", \"theta\", \"axial\", \"normal\""},
      {"bad --set", "run " + paper_scene("s1_central") + " --set nonsense", "--set expects key=value"},
      // Non-physical magnitudes: each ended in a zero mass or an infinite energy, exit 3.
      {"denormal rho", "run " + paper_scene("s1_central") + " --set bodies[0].rho=5e-324",
       "key 'bodies[0].rho': expected a positive number between 1e-30 and 1e30 (kg/m^3)"},
      {"huge velocity", "run " + paper_scene("s1_central") + " --set bodies[0].velocity=[1e308,0]",
       "key 'bodies[0].velocity': expected velocities (m/s) of magnitude at most 1e30"},
      {"huge damping", "run " + paper_scene("s1_central") + " --set model.rayleigh_mass=1e308",
       "key 'model.rayleigh_mass'"},
      // Step counts that overflowed a long (paper, IDA: -9223372036854775808 steps, exit 0) or hung (exact).
      {"dt 1e-300 paper", "run " + paper_scene("s1_central") + " --set time.dt=1e-300", "key 'time.dt'"},
      {"dt 1e-300 ida", "run " + paper_scene("s1_central") + " --method ida --set time.dt=1e-300",
       "key 'time.dt'"},
      {"dt 1e-300 exact", "run " + paper_scene("s1_central") + " --method exact --set time.dt=1e-300",
       "key 'time.dt'"},
      {"1e16 steps paper",
       "run " + paper_scene("s1_central") + " --allow-long --set time.dt=1e-13 --set time.end=1e3",
       "key 'time.dt': expected a step that divides time.end = 1000 s into at most 1e+15 steps"},
      {"1e16 steps ida",
       "run " + paper_scene("s1_central") +
           " --method ida --allow-long --set time.dt=1e-13 --set time.end=1e3",
       "into at most 1e+15 steps"},
      {"1e16 steps exact",
       "run " + paper_scene("s1_central") +
           " --method exact --allow-long --set time.dt=1e-13 --set time.end=1e3",
       "into at most 1e+15 steps"},
      // Runs that cannot finish: the estimate is printed, the flag is named. 1e7 elements of 1e-6 m,
      // axial wave speed sqrt(E / rho) = 10 m/s: transit 1e-7 s, 4e7 wave steps in 4 s; 3e7 DOFs.
      {"1e7 elements", "run " + paper_scene("s1_central") + " --set bodies[0].elements=10000000",
       "key 'time.allow_long_run': this run is far beyond an ordinary one: 400 steps (the fastest wave needs "
       "4e+07) x 3e+07 DOFs"},
      {"end 4.3e9 s", "run " + paper_scene("s1_central") + " --set time.end=4.3e9",
       "4.3e+11 steps (the fastest wave needs 4.3e+10) x 66 DOFs"},
      // E = 1e30 N/m^2: wave speed 1e15 m/s, transit 1e-15 s: IDA and exact ran for hours.
      {"stiff ida", "run " + paper_scene("s1_central") + " --method ida --set bodies[0].E=1e30",
       "400 steps (the fastest wave needs 4e+15) x 66 DOFs"},
      {"stiff exact", "run " + paper_scene("s1_central") + " --method exact --set bodies[0].E=1e30",
       "key 'time.allow_long_run'"},
  };
  expect_refused(cases);
}

TEST(Cli, BadThreadsExitTwoNamingTheOption) {
  expect_refused({
      {"--threads 0", "run " + paper_scene("s1_central") + " --threads 0",
       "--threads: expected a whole number of threads 1..1024, got '0'"},
      {"--threads -2", "run " + paper_scene("s1_central") + " --threads -2",
       "--threads: expected a whole number"},
      {"--threads two", "run " + paper_scene("s1_central") + " --threads two",
       "--threads: expected a whole number of threads 1..1024, got 'two'"},
      {"--threads 1.5", "run " + paper_scene("s1_central") + " --threads 1.5",
       "--threads: expected a whole number"},
      {"verify --threads 0", "verify verification/matrix.toml --threads 0",
       "--threads: expected a whole number of threads 1..1024, got '0'"},
      {"sweep --threads x", "sweep " + paper_scene("s1_central") + " --dt 0.01 --threads x",
       "--threads: expected a whole number of threads 1..1024, got 'x'"},
      {"paper.threads 0", "run " + paper_scene("s1_central") + " --set paper.threads=0",
       "key 'paper.threads': expected a whole number of threads 1..1024, got 0"},
  });
}

// A roller in global axes under an inclined target runs (legal) with one warning on stderr that
// names the file and the key and points at the body-axis roller; in body axes there is none.
TEST(Cli, GlobalRollerOnAnInclinedBodyWarns) {
  const std::string inclined = bad_scene("end = [10.0, 0.0]", "end = [8.0, -6.0]");
  const Result r = run_cli("run " + inclined + " --quiet --out " + fresh_dir("roller").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("warning: " + inclined + ": key 'bodies[1].supports[1].fix'"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("fix = [\"normal\"] is the body-axis roller"), std::string::npos) << r.output;
  std::ifstream in(inclined);
  std::string text(std::istreambuf_iterator<char>(in), {});
  text.replace(text.find("fix = [\"y\"]"), 11, "fix = [\"normal\"]");
  const std::string across = beamimpact::testing::temp_path("cli_roller_across.toml").string();
  std::ofstream(across) << text;
  const Result body = run_cli("run " + across + " --quiet --out " + fresh_dir("roller_across").string());
  ASSERT_EQ(body.code, 0) << body.output;
  EXPECT_EQ(body.output.find("warning"), std::string::npos) << body.output;
}

TEST(Cli, LongValuesAreCutInTheMessage) {
  // A 5000-character value was echoed whole; the message keeps 80 characters of it.
  const Result r = run_cli("run " + paper_scene("s1_central") + " --out " + fresh_dir("long").string() +
                           " --set contacts[0].node=" + std::string(5000, 'x'));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("key 'contacts[0].node'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("xxxxxxxxxx..."), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find(std::string(78, 'x')), std::string::npos) << r.output;
}

TEST(Cli, QuietPrintsNothingAndAllowLongRuns) {
  // 5e5 steps x 66 DOFs = 3.3e7 DOF-steps is ordinary and passes with --allow-long too. A run
  // over 1 s shows progress: the sanitizer build (checked: progress lines before the fix), not
  // always the release build (0.5 s), where this checks the flags only.
  const Result r = run_cli("run " + paper_scene("s1_central") + " --out " + fresh_dir("quiet").string() +
                           " --quiet --allow-long --set time.end=5000");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(r.output, "");
}

TEST(Cli, FailedRerunRemovesAStaleSummary) {
  // A directory that held a complete result must not look complete after a failed run into it.
  const fs::path out = fresh_dir("stale");
  ASSERT_EQ(run_cli("run " + paper_scene("s1_central") + " --out " + out.string()).code, 0);
  ASSERT_TRUE(fs::exists(out / "summary.json"));
  // dt = 0.2 s is twice the critical step: allowed by the flag, the run diverges -> exit 3.
  const Result r = run_cli("run " + paper_scene("s1_central") + " --out " + out.string() +
                           " --set time.dt=0.2 --set time.allow_above_critical=true --set time.end=400");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("diverged"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}

TEST(Cli, StaleFieldsGoWithTheRunThatDoesNotWriteThem) {
  // A run without --fields into a directory that holds an earlier run's fields: no .vtu of that
  // run may stand beside the new summary.json; a diverged run with fields leaves none either.
  const fs::path out = fresh_dir("stale_fields");
  ASSERT_EQ(run_cli("run " + paper_scene("s1_central") + " --fields --out " + out.string()).code, 0);
  ASSERT_TRUE(fs::exists(out / "fields.pvd"));
  ASSERT_EQ(run_cli("run " + paper_scene("s1_central") + " --out " + out.string()).code, 0);
  EXPECT_FALSE(fs::exists(out / "fields.pvd"));
  EXPECT_FALSE(fs::exists(out / "fields"));
  const Result r = run_cli("run " + paper_scene("s1_central") + " --fields --out " + out.string() +
                           " --set time.dt=0.2 --set time.allow_above_critical=true --set time.end=400");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_FALSE(fs::exists(out / "fields"));
}

TEST(Cli, ModelIsCheckedForCostAndARefusalLeavesNoEarlierModel) {
  // 1e7 elements per bar: `run` refuses it at once (exit 2); `model` grew to 7.1 GB and ran out
  // of memory (exit 3). It now refuses it as `run` does, and a refused export leaves no model.json.
  const fs::path out = fresh_dir("model_cost");
  ASSERT_EQ(run_cli("model " + paper_scene("s1_central") + " --out " + out.string()).code, 0);
  ASSERT_TRUE(fs::exists(out / "model.json"));
  const Result r = run_cli("model " + paper_scene("s1_central") + " --out " + out.string() +
                           " --set bodies.A.elements=10000000 --set bodies.B.elements=10000000");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("time.allow_long_run"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out / "model.json"));
}

TEST(Cli, SmallSlipsAreRefusedOrStated) {
  const fs::path out = fresh_dir("slips");
  // A typo beside a missing required key is named.
  const Result typo = run_cli("run " + bad_scene("dt = 0.01", "dtt = 0.01") + " --out " + out.string());
  EXPECT_EQ(typo.code, 2) << typo.output;
  EXPECT_NE(typo.output.find("time.dtt"), std::string::npos) << typo.output;
  // A missing file says why.
  const Result missing = run_cli("run /no/such/scene.toml --out " + out.string());
  EXPECT_EQ(missing.code, 2) << missing.output;
  EXPECT_NE(missing.output.find("No such file or directory"), std::string::npos) << missing.output;
  // Option ranges: jobs >= 1, a finite time limit > 0.
  for (const std::string& bad :
       {"verify verification/matrix.toml --jobs 0 --out " + out.string(),
        "sweep " + paper_scene("s1_central") + " --jobs -1 --out " + out.string(),
        "score paper --jobs 0 --out " + out.string(), "score paper --timeout nan --out " + out.string(),
        "conform paper --timeout 0 --out " + out.string()}) {
    const Result r = run_cli(bad);
    EXPECT_EQ(r.code, 2) << bad << "\n" << r.output;
  }
  // The last row's time is the end time summary.json states (dt 0.03 s: 34 steps to 1.02 s).
  ASSERT_EQ(run_cli("run " + paper_scene("s1_central") + " --set time.dt=0.03 --set time.end=1 --out " +
                    out.string())
                .code,
            0);
  const auto j = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_NEAR(j["end_time"].get<double>(), 34 * 0.03, 1e-12);
}

}  // namespace
