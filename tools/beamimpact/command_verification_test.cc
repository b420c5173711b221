// The compare / verify commands end to end: exit codes, skip handling, JUnit naming.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <tools/beamimpact/testing/cli_run.hpp>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

using Result = testing::CliResult;

class Commands : public testing::CliTest {
 protected:
  fs::path matrix(const std::string& body) {
    const fs::path p = tmp_ / "m.toml";
    std::ofstream(p)
        << fmt::format(
               "[settings]\nroot = \"{}\"\n[scenes]\ns1 = \"verification/scenes/paper/s1_central.toml\"\n",
               src_.string())
        << body;
    return p;
  }

  const fs::path src_ = BEAMIMPACT_SOURCE;
};

// The S1 paper rows of the real matrix pass, and the JUnit file names scene, method and dt.
TEST_F(Commands, VerifyNamesCasesBySceneMethodAndDt) {
  const Result r = run(
      fmt::format("verify verification/matrix.toml --only 's1_central paper dt=0.01 vs' --out '{}' --jobs 2",
                  (tmp_ / "v").string()));
  EXPECT_EQ(r.code, 0) << r.output;
  const std::string junit = read(tmp_ / "v" / "junit.xml");
  EXPECT_NE(junit.find("<testsuite name=\"s1_central\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("classname=\"s1_central.paper.dt=0.01\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("name=\"s1_central paper dt=0.01 vs "), std::string::npos) << junit;
  EXPECT_EQ(junit.find("<failure"), std::string::npos) << junit;
  EXPECT_NE(read(tmp_ / "v" / "report.md").find("version: `"), std::string::npos);
  EXPECT_NE(read(tmp_ / "v" / "norms.json").find("\"definition\""), std::string::npos);
}

// A method of the registry that cannot run here is "skipped: <why>": it fails the gate when
// required, not otherwise. Here an external method whose check command fails.
TEST_F(Commands, SkippedRunFailsOnlyWhenRequired) {
  const fs::path methods = tmp_ / "absent.toml";
  std::ofstream(methods) << "[[method]]\nname = \"absent\"\ncommand = [\"/bin/sh\", \"{scene}\", \"{out}\"]\n"
                            "check = [\"/bin/false\"]\n";
  const std::string body = R"(
[[case]]
scene = "s1"
method = "absent"
required = %s
reference = { method = "paper" }
gates = [{ metric = "impulse", tol = 0.01, why = "a method whose program is missing" }]
)";
  for (const bool required : {false, true}) {
    std::string b = body;
    b.replace(b.find("%s"), 2, required ? "true" : "false");
    const fs::path m = matrix(b);
    const Result r = run(fmt::format("verify '{}' --methods '{}' --out '{}'", m.string(), methods.string(),
                                     (tmp_ / "v").string()));
    EXPECT_EQ(r.code, required ? 1 : 0) << r.output;
    const std::string junit = read(tmp_ / "v" / "junit.xml");
    EXPECT_NE(junit.find("its check &apos;/bin/false&apos; exited 1"), std::string::npos) << junit;
    EXPECT_NE(junit.find(required ? "<failure" : "<skipped"), std::string::npos) << junit;
  }
}

// A method that is not in the registry is bad input: exit 2, naming the file, key and the names.
TEST_F(Commands, UnknownMethodIsBadInput) {
  const fs::path m = matrix(R"(
[[case]]
scene = "s1"
method = "nosuch"
reference = { method = "paper" }
gates = [{ metric = "impulse", tol = 0.01, why = "a method that does not exist" }]
)");
  const Result r = run(fmt::format("verify '{}' --out '{}'", m.string(), (tmp_ / "v").string()));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("case[0].method"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("paper, exact, ida, fenicsx"), std::string::npos) << r.output;
}

// Bad matrix: one message naming the file and the key, exit code 2, no report presented.
TEST_F(Commands, BadMatrixExitsTwo) {
  const fs::path m = matrix(R"(
[[case]]
scene = "s1"
method = "paper"
reference = { method = "ida" }
gates = [{ metric = "impluse", tol = 0.01, why = "misspelt metric name" }]
)");
  const Result r = run(fmt::format("verify '{}' --out '{}'", m.string(), (tmp_ / "v").string()));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(m.string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("case[0].gates[0].metric"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(tmp_ / "v" / "report.md"));
}

// An output directory holds a complete result or visibly none: a refused re-run into the
// directory of a finished one removes that run's outputs first (they would vouch for the refused
// command), and a refused verify removes an earlier PASS report; nothing else there is touched.
TEST_F(Commands, ARefusedRerunLeavesNoEarlierResultBehind) {
  const fs::path out = tmp_ / "run";
  ASSERT_EQ(
      run(fmt::format("run verification/scenes/paper/s1_central.toml --out '{}' --quiet", out.string())).code,
      0);
  ASSERT_TRUE(fs::exists(out / "summary.json") && fs::exists(out / "history.csv"));
  std::ofstream(out / "notes.txt") << "the user's own file\n";
  const Result refused = run(fmt::format(
      "run verification/scenes/paper/s1_central.toml --out '{}' --quiet --set bodies.A.E=-1", out.string()));
  EXPECT_EQ(refused.code, 2) << refused.output;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  EXPECT_FALSE(fs::exists(out / "history.csv"));
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
  const fs::path v = tmp_ / "v";
  fs::create_directories(v);
  std::ofstream(v / "report.md") << "verify passed\n";
  std::ofstream(v / "junit.xml") << "<testsuites failures=\"0\"/>\n";
  const Result bad =
      run(fmt::format("verify '{}' --out '{}'", matrix("[[case]]\nscene = \"nope\"\n").string(), v.string()));
  EXPECT_EQ(bad.code, 2) << bad.output;
  EXPECT_FALSE(fs::exists(v / "report.md"));
  EXPECT_FALSE(fs::exists(v / "junit.xml"));
}

// Matrix values out of range are refused at load (exit 2 naming the key), never run: a timeout
// <= 0 killed every run, a mesh multiplier 0 reached the launcher.
TEST_F(Commands, MatrixTimeoutAndMeshOutOfRangeExitTwo) {
  struct Bad {
    const char* body;
    const char* key;
  } bad[] = {
      {"[settings]\ntimeout = -5\n", "settings.timeout"},
      {"[[case]]\nscene = \"s1\"\nmethod = \"paper\"\nmesh = 0\nreference = { method = \"exact\" }\n"
       "gates = [{ metric = \"impulse\", tol = 0.04, why = \"x\" }]\n",
       "case[0].mesh"},
  };
  for (const Bad& b : bad) {
    // The [settings] table of the helper comes first; a second one would be a TOML error, so the
    // timeout case writes its own file.
    fs::path m = tmp_ / "bad.toml";
    if (std::string(b.key) == "settings.timeout")
      std::ofstream(m) << b.body << "root = \"" << src_.string() << "\"\n";
    else
      m = matrix(b.body);
    const Result r = run(fmt::format("verify '{}' --out '{}'", m.string(), (tmp_ / "v").string()));
    EXPECT_EQ(r.code, 2) << b.key << ": " << r.output;
    EXPECT_NE(r.output.find(fmt::format("key '{}'", b.key)), std::string::npos) << b.key << ": " << r.output;
  }
}

// A verify of nothing would pass: an --only that matches no item is bad input.
TEST_F(Commands, VerifyOfAnEmptySelectionExitsTwo) {
  const Result r =
      run(fmt::format("verify verification/matrix.toml --only NOMATCH --out '{}'", (tmp_ / "v").string()));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--only"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("passed"), std::string::npos) << r.output;
}

// sweep: a fraction above the critical step and an --out that is a file are refused before any
// run (a file as --out aborted with an uncaught filesystem_error in a worker thread).
TEST_F(Commands, SweepRefusesFractionAboveOneAndAFileAsOut) {
  const std::string s4 = "verification/scenes/paper/s4_oblique_90.toml";
  Result r = run(fmt::format("sweep {} --fraction 0.5,2 --out '{}'", s4, (tmp_ / "f").string()));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("expected fractions of the critical step in (0, 1], got 2"), std::string::npos)
      << r.output;
  const fs::path file = tmp_ / "a_file";
  std::ofstream(file) << "not a directory\n";
  r = run(fmt::format("sweep verification/scenes/paper/s1_central.toml --dt 0.01 --out '{}'", file.string()));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("key '--out'"), std::string::npos) << r.output;
}

// A scene path the file system refuses (a name longer than NAME_MAX, found by the matrix fuzz
// target: std::filesystem threw "File name too long" through verify) is a missing scene: exit 2
// naming the key, like any other path that does not exist. The same for sweep's scene and run's
// --out.
TEST_F(Commands, ScenePathTooLongIsBadInput) {
  const std::string name = "verification/" + std::string(300, 'x') + ".toml";
  const fs::path m = matrix(fmt::format(R"(
[[case]]
scene = "{}"
method = "paper"
reference = {{ method = "paper" }}
gates = [{{ metric = "impulse", tol = 0.01, why = "a scene that cannot exist" }}]
)",
                                        name));
  Result r = run(fmt::format("verify '{}' --out '{}'", m.string(), (tmp_ / "v").string()));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("case[0].scene"), std::string::npos) << r.output;
  r = run(fmt::format("sweep {} --dt 0.01 --out '{}'", name, (tmp_ / "s").string()));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("scene file not found"), std::string::npos) << r.output;
  // An --out the file system refuses: exit 2, the path cut to 160 characters, no library wording.
  r = run(fmt::format("run verification/scenes/paper/s1_central.toml --out '{}'", (tmp_ / name).string()));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("key '--out': expected a directory that can be written: File name too long"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("filesystem error"), std::string::npos) << r.output;
  EXPECT_LT(r.output.size(), 300u) << r.output;
}

// compare: prints every norm with its definition; a directory that is not a run exits 2.
TEST_F(Commands, CompareRunsAndRejectsNonRuns) {
  const std::string s1 = "verification/scenes/paper/s1_central.toml";
  ASSERT_EQ(run(fmt::format("run {} --out '{}' --quiet", s1, (tmp_ / "a").string())).code, 0);
  ASSERT_EQ(run(fmt::format("run {} --out '{}' --quiet --set time.dt=0.005", s1, (tmp_ / "b").string())).code,
            0);
  const Result r = run(fmt::format("compare '{}' '{}' --json '{}'", (tmp_ / "a").string(),
                                   (tmp_ / "b").string(), (tmp_ / "c.json").string()));
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("I.rel_linf: max_t |a-b| / max_t |b|"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(tmp_ / "c.json"));
  // --json DIR: DIR/compare.json, and no compare.json.partial or DIR.partial left beside it
  fs::create_directories(tmp_ / "cdir");
  EXPECT_EQ(run(fmt::format("compare '{}' '{}' --json '{}'", (tmp_ / "a").string(), (tmp_ / "b").string(),
                            (tmp_ / "cdir").string()))
                .code,
            0);
  EXPECT_EQ(read(tmp_ / "cdir" / "compare.json"), read(tmp_ / "c.json"));
  EXPECT_FALSE(fs::exists(tmp_ / "cdir.partial"));
  const Result bad = run(fmt::format("compare '{}' '{}'", tmp_.string(), (tmp_ / "b").string()));
  EXPECT_EQ(bad.code, 2) << bad.output;
  EXPECT_NE(bad.output.find("summary.json"), std::string::npos) << bad.output;
}

// sweep: one row per dt with wall time and the norms against the reference; bad dt exits 2.
TEST_F(Commands, SweepTabulatesEachStep) {
  const std::string s1 = "verification/scenes/paper/s1_central.toml";
  const Result r = run(fmt::format("sweep {} --dt 0.01,0.005 --reference exact --out '{}' --jobs 2", s1,
                                   (tmp_ / "sw").string()));
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string md = read(tmp_ / "sw" / "sweep.md");
  EXPECT_NE(md.find("| 0.01 | scene | 400 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 0.005 | scene | 800 |"), std::string::npos) << md;
  EXPECT_NE(md.find("Errors against: exact"), std::string::npos) << md;
  const std::string csv = read(tmp_ / "sw" / "sweep.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3) << csv;  // header + 2 steps
  EXPECT_EQ(run(fmt::format("sweep {} --dt -0.01 --out '{}'", s1, (tmp_ / "sw2").string())).code, 2);
}

// Bad options of compare and sweep: exit 2 naming the option, nothing run (not a fall-back to the
// default for --grid 0 or nan, not std::bad_alloc for --grid 1e-9, not exit 3 after starting runs
// for --mesh 0 or an unknown reference).
TEST_F(Commands, BadCompareAndSweepOptionsExitTwo) {
  const std::string s1 = "verification/scenes/paper/s1_central.toml",
                    s2 = "verification/scenes/paper/s2_transverse.toml";
  const std::string a = (tmp_ / "a").string(), b = (tmp_ / "b").string();
  ASSERT_EQ(run(fmt::format("run {} --out '{}' --quiet", s1, a)).code, 0);
  ASSERT_EQ(run(fmt::format("run {} --out '{}' --quiet", s2, b)).code, 0);
  struct Bad {
    std::string args, says;
  };
  const std::vector<Bad> cases = {
      {"--grid 0", "--grid: expected a positive finite time (s), got '0'"},
      {"--grid nan", "--grid: expected a positive finite time (s), got 'nan'"},
      {"--grid inf", "--grid: expected a positive finite time (s)"},
      {"--window -1", "--window: expected a positive finite time (s)"},
      {"--merge inf", "--merge: expected a positive finite time (s)"},
      {"--grid 1e-9", "key '--grid': expected a step giving at most 1e+08 grid points"},
      {"--threshold 1", "--threshold: expected a fraction of the reference's largest R in [0, 1), got '1'"},
      {"--threshold nan", "--threshold: expected a fraction of the reference's largest R in [0, 1)"},
  };
  for (const auto& c : cases) {
    const Result r = run(fmt::format("compare '{}' '{}' {}", a, a, c.args));
    EXPECT_EQ(r.code, 2) << c.args << ": " << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << ": " << r.output;
  }
  // Runs of different scene files compare, with a warning.
  const Result diff = run(fmt::format("compare '{}' '{}' --json '{}'", a, b, (tmp_ / "c.json").string()));
  EXPECT_NE(diff.output.find("warning: the runs are of different scene files (scene_sha256 differs"),
            std::string::npos)
      << diff.output;
  EXPECT_EQ(run(fmt::format("compare '{}' '{}' --json '{}'", a, a, (tmp_ / "c.json").string()))
                .output.find("warning"),
            std::string::npos);
  const Result mesh = run(fmt::format("sweep {} --dt 0.01 --mesh 0 --out '{}'", s1, (tmp_ / "sw").string()));
  EXPECT_EQ(mesh.code, 2) << mesh.output;
  EXPECT_NE(mesh.output.find("key 'mesh': expected an element multiplier 1..64"), std::string::npos)
      << mesh.output;
  EXPECT_FALSE(fs::exists(tmp_ / "sw" / "runs")) << "nothing runs before the input is checked";
  const Result ref =
      run(fmt::format("sweep {} --dt 0.01 --reference bogus --out '{}'", s1, (tmp_ / "sw").string()));
  EXPECT_EQ(ref.code, 2) << ref.output;
  // The list names every method of the registry (the shipped methods file's included).
  EXPECT_NE(ref.output.find("expected a method name (paper, exact, ida, "), std::string::npos) << ref.output;
  EXPECT_NE(ref.output.find("), got 'bogus'"), std::string::npos) << ref.output;
}

// The ratchet: a baseline written from a run holds the next run to its values. Its noise is
// max(1 % of a value, 1e-9) (baseline.hpp): the baseline's first error moved by hand to make the
// run's value 2 % above it must fail (exit 1), 0.5 % must not, 2 % below it is listed as better.
TEST_F(Commands, BaselineHoldsTheRunToItsValues) {
  const fs::path b = tmp_ / "baseline.json";
  const std::string verify = fmt::format(
      "verify verification/matrix.toml --only 's1_central paper dt=0.01 vs' --jobs 2 --baseline '{}' --out ",
      b.string());
  const Result written = run(verify + testing::shell_words({(tmp_ / "v0").string()}) + " --update-baseline");
  ASSERT_EQ(written.code, 0) << written.output;
  ASSERT_NE(written.output.find("baseline: wrote"), std::string::npos) << written.output;
  const nlohmann::json original = nlohmann::json::parse(read(b));
  auto with_first_error_scaled = [&](double factor) {
    nlohmann::json j = original;
    for (auto& g : j["items"][0]["gates"])
      if (g.contains("tol") && !g.contains("min_order") && g["value"].is_number() && g["value"] > 1e-6) {
        g["value"] = g["value"].get<double>() * factor;
        break;
      }
    std::ofstream(b) << j.dump(1);
  };
  int n = 0;
  auto again = [&] {
    return run(verify + testing::shell_words({(tmp_ / fmt::format("v{}", ++n)).string()}));
  };
  const Result same = again();
  EXPECT_EQ(same.code, 0) << same.output;
  EXPECT_NE(same.output.find("baseline: 0 worse, 0 better"), std::string::npos) << same.output;
  with_first_error_scaled(1 / 1.02);  // the run's value 2 % above the baseline's
  const Result worse = again();
  EXPECT_EQ(worse.code, 1) << worse.output;
  EXPECT_NE(worse.output.find("WORSE"), std::string::npos) << worse.output;
  with_first_error_scaled(1 / 1.005);  // 0.5 %: within the noise
  const Result within = again();
  EXPECT_EQ(within.code, 0) << within.output;
  with_first_error_scaled(1.02);  // the run's value 2 % below: better, listed, passes
  const Result better = again();
  EXPECT_EQ(better.code, 0) << better.output;
  EXPECT_NE(better.output.find("  better "), std::string::npos) << better.output;
  const Result missing =
      run(fmt::format("verify verification/matrix.toml --only s1_central --out '{}' --baseline '{}'",
                      (tmp_ / "vm").string(), (tmp_ / "none.json").string()));
  EXPECT_EQ(missing.code, 2) << missing.output;
  EXPECT_FALSE(fs::exists(tmp_ / "vm" / "runs")) << "a missing baseline is refused before any run";
}

// A shipped scene by name from a folder outside the repository; a file of the working folder
// wins over a shipped scene's name (the rule of api/shipped_scenes.hpp).
TEST_F(Commands, ShippedSceneByNameFromAnyFolder) {
  const std::string here = "cd " + testing::shell_words({tmp_.string()}) + " &&";
  const Result listed = run("scenes", here);
  ASSERT_EQ(listed.code, 0) << listed.output;
  EXPECT_NE(listed.output.find((src_ / "verification/scenes/paper/s1_central.toml").string()),
            std::string::npos)
      << listed.output;
  const Result by_name = run("run s1_central --method exact --out by_name --quiet", here);
  ASSERT_EQ(by_name.code, 0) << by_name.output;
  const nlohmann::json s = nlohmann::json::parse(read(tmp_ / "by_name/summary.json"));
  // S1, two equal free rods: the exact impulse is m v0 / 2 = 4 N s.
  EXPECT_NEAR(s["contacts"][0]["impulse_normal"].get<double>(), 4.0, 1e-9);
  fs::copy_file(src_ / "verification/scenes/paper/s2_transverse.toml", tmp_ / "s1_central.toml");
  const Result local = run("run s1_central.toml --method exact --out local --quiet", here);
  ASSERT_EQ(local.code, 0) << local.output;
  // The working folder's file (S2's content under S1's name) ran, not the shipped S1.
  EXPECT_EQ(nlohmann::json::parse(read(tmp_ / "local/summary.json"))["scene"], "s2_transverse");
  const Result unknown = run("run no_such_scene --out x --quiet", here);
  EXPECT_EQ(unknown.code, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("no_such_scene"), std::string::npos) << unknown.output;
}

}  // namespace
}  // namespace beamimpact
