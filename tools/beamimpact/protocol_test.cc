// The plug-in protocol end to end (docs/protocol.md): methods files on the command line, a
// stand-in external solver (testdata/standin_solver.py) through run, verify and conform, broken
// copies of it failing conform with the rule named, and bad methods files refused with exit 2.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <tools/beamimpact/testing/cli_run.hpp>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

using Result = testing::CliResult;

class Protocol : public testing::CliTest {
 protected:
  /// A methods file declaring the stand-in as `name`, breaking the rule `broken` ("" none).
  /// A methods file declaring the stand-in as `name` (with `--break broken`; `accepts_more`: more
  /// accepts keys than the program models, e.g. "friction = true, ").
  fs::path standin(const std::string& name, const std::string& broken = "",
                   const std::string& accepts_more = "") {
    const fs::path f = tmp_ / (name + ".toml");
    std::ofstream(f) << fmt::format(
        "[[method]]\nname = \"{}\"\nsummary = \"protocol stand-in\"\n"
        "command = [\"/usr/bin/python3\", \"{}/tools/beamimpact/testdata/standin_solver.py\", \"{{scene}}\", "
        "\"--out\", \"{{out}}\", \"--dt\", \"{{dt}}\"{}]\n"
        "check = [\"/usr/bin/python3\", \"-c\", \"import tomllib\"]\n"
        "accepts = {{ {}dt = true, rotation = true, rigid = true, several_contacts = true, bending = true, "
        "node_to_surface = true, loads = true }}\n",
        name, src_.string(), broken.empty() ? "" : fmt::format(", \"--break\", \"{}\"", broken),
        accepts_more);
    return f;
  }

  /// A methods file declaring the shipped example behind testdata/broken_copy.py MODE as `name`
  /// (it declares everything the example models, bending included).
  fs::path example_copy(const std::string& name, const std::string& mode) {
    const fs::path f = tmp_ / (name + ".toml");
    std::ofstream(f) << fmt::format(
        "[[method]]\nname = \"{}\"\n"
        "command = [\"/usr/bin/python3\", \"{}/tools/beamimpact/testdata/broken_copy.py\", \"{}\", "
        "\"{{scene}}\", "
        "\"--out\", \"{{out}}\", \"--quiet\", \"--beamimpact\", \"{{beamimpact}}\", \"--dt\", \"{{dt}}\"]\n"
        "check = [\"sh\", \"-c\", \"/usr/bin/python3 -c 'import scipy'\"]\n"  // a bare name: found on PATH
        "accepts = {{ dt = true, several_contacts = true, timoshenko = true, bending = true, "
        "node_to_surface = true, loads = true }}\n",
        name, src_.string(), mode);
    return f;
  }

  /// conform on the given conformance scenes, into tmp_/name.
  Result conform(const std::string& name, const fs::path& methods, const std::string& scenes) {
    return run(fmt::format("conform {} --methods '{}' --out '{}' --scenes {}", name, methods.string(),
                           (tmp_ / name).string(), scenes));
  }

  const fs::path src_ = BEAMIMPACT_SOURCE;
};

TEST_F(Protocol, MethodsListsEveryMethodWithItsOriginAndWhetherItRunsHere) {
  const fs::path f = standin("standin");
  const Result r = run(fmt::format("methods --methods '{}'", f.string()));
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* name : {"paper ", "exact ", "ida ", "fenicsx ", "standin "})
    EXPECT_NE(r.output.find(name), std::string::npos) << name << "\n" << r.output;
  EXPECT_NE(r.output.find("from: built-in"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("from: " + f.string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("from: " + (src_ / "verification/methods.toml").string()), std::string::npos)
      << r.output;
  // A method whose check fails is listed as one that cannot run here, with its check named.
  std::ofstream(tmp_ / "absent.toml")
      << "[[method]]\nname = \"absent\"\ncommand = [\"/bin/sh\", \"{scene}\", "
         "\"{out}\"]\ncheck = [\"/bin/false\"]\n";
  const Result a = run(fmt::format("methods --methods '{}'", (tmp_ / "absent.toml").string()));
  EXPECT_NE(a.output.find("cannot run here: absent: its check '/bin/false' exited 1"), std::string::npos)
      << a.output;
}

// The stand-in runs through `beamimpact run` (the one door): the scene's sha256 is echoed, and a
// scene with friction is refused with exit 2 and its one line of reason.
TEST_F(Protocol, AnExternalMethodRunsAndRefusesThroughRun) {
  const fs::path f = standin("standin");
  const fs::path out = tmp_ / "r";
  const Result r =
      run(fmt::format("run verification/scenes/paper/s1_central.toml --method standin --methods '{}' "
                      "--out '{}' --dt 0.02",
                      f.string(), out.string()));
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string summary = read(out / "summary.json");
  EXPECT_NE(summary.find("\"dt\": 0.02"), std::string::npos) << summary;  // {dt} reached the program
  EXPECT_NE(r.output.find("standin run: 200 steps"), std::string::npos) << r.output;  // 4 s / 0.02 s
  const Result fr =
      run(fmt::format("run verification/scenes/paper/s1_central.toml --method standin --methods '{}' "
                      "--out '{}' --set contacts[0].friction=0.3",
                      f.string(), out.string()));
  EXPECT_EQ(fr.code, 2) << fr.output;
  EXPECT_NE(fr.output.find("not applicable: method 'standin' does not take friction"), std::string::npos)
      << fr.output;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  // What it did not declare is refused before it starts: a mesh.
  const Result mr =
      run(fmt::format("run verification/scenes/paper/s1_central.toml --method standin --methods '{}' "
                      "--out '{}' --mesh 2",
                      f.string(), out.string()));
  EXPECT_EQ(mr.code, 2) << mr.output;
  EXPECT_NE(mr.output.find("accepts.mesh_factor = false"), std::string::npos) << mr.output;
}

// In the matrix a refused case is "not applicable": a skipped gate, never a pass or a crash.
// A scene the method refuses is not applicable, whoever refuses it: the registry (the methods file
// declares no friction) or the program itself (the file claims friction; the program exits 2).
TEST_F(Protocol, ARefusedCaseIsNotApplicableInVerify) {
  for (const auto& [name, accepts_more] :
       {std::pair{"standin", ""}, std::pair{"claims_friction", "friction = true, "}}) {
    SCOPED_TRACE(name);
    const fs::path f = standin(name, "", accepts_more);
    const fs::path m = tmp_ / "m.toml";
    std::ofstream(m) << fmt::format(
        "[settings]\nroot = \"{}\"\n[scenes]\ns1 = \"verification/scenes/paper/s1_central.toml\"\n"
        "[[case]]\nscene = \"s1\"\nmethod = \"{}\"\nrequired = false\nset = "
        "[\"contacts[0].friction=0.3\"]\n"
        "reference = {{ method = \"paper\" }}\n"
        "gates = [{{ metric = \"impulse\", tol = 0.01, why = \"a method that does not model friction\" }}]\n",
        src_.string(), name);
    const fs::path out = tmp_ / (std::string("v_") + name);
    const Result r =
        run(fmt::format("verify '{}' --methods '{}' --out '{}'", m.string(), f.string(), out.string()));
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("0 passed, 0 failed, 1 skipped"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(": not applicable: "), std::string::npos) << r.output;  // the run's outcome
    const std::string junit = read(out / "junit.xml");
    EXPECT_NE(junit.find("<skipped"), std::string::npos) << junit;
    EXPECT_NE(junit.find("not applicable"), std::string::npos) << junit;
  }
}

// The conforming stand-in passes every rule; each broken copy fails with its rule named.
TEST_F(Protocol, ConformPassesTheStandInAndNamesTheRuleABrokenCopyBreaks) {
  const Result ok = run(fmt::format("conform standin --methods '{}' --out '{}'", standin("standin").string(),
                                    (tmp_ / "c").string()));
  EXPECT_EQ(ok.code, 0) << ok.output;
  EXPECT_NE(ok.output.find("conform passed"), std::string::npos) << ok.output;
  EXPECT_NE(read(tmp_ / "c" / "junit.xml").find("failures=\"0\""), std::string::npos);
  // conform.json (the page's data) carries the same verdict as the exit code.
  EXPECT_NE(read(tmp_ / "c" / "conform.json").find("\"verdict\": \"passed\""), std::string::npos);
  const struct {
    const char* broken;
    const char* rule;
    const char* file;
  } broken[] = {
      {"column", "columns", "history.csv"},
      {"summary-on-failure", "no summary after failure", "summary.json"},
      {"exit-code", "exit code", "run.log"},
  };
  for (const auto& b : broken) {
    std::string name = std::string("broken_") + b.broken;
    std::replace(name.begin(), name.end(), '-', '_');
    const fs::path out = tmp_ / name;
    const Result r = run(fmt::format("conform {} --methods '{}' --out '{}'", name,
                                     standin(name, b.broken).string(), out.string()));
    EXPECT_EQ(r.code, 1) << b.broken << "\n" << r.output;
    EXPECT_NE(r.output.find(fmt::format("[FAIL] {}", b.rule)), std::string::npos) << b.broken << "\n"
                                                                                  << r.output;
    const std::string junit = read(out / "junit.xml");
    EXPECT_NE(junit.find(fmt::format("<failure message=\"{}: ", b.rule)), std::string::npos) << junit;
    EXPECT_NE(junit.find(b.file), std::string::npos) << junit;
    EXPECT_NE(read(out / "conform.json").find("\"verdict\": \"failed\""), std::string::npos) << b.broken;
  }
}

// The shipped example passes conform on S1 (end to end); each broken copy of it breaks ONE output
// rule and conform exits 1 naming that rule and no other output rule. The copies wrap the
// example's honest run (testdata/broken_copy.py), so every other rule still holds.
TEST_F(Protocol, EachBrokenCopyOfTheExampleFailsConformWithItsRuleNamed) {
  if (run("methods").output.find("example    program    runs here") == std::string::npos)
    GTEST_SKIP() << "the example needs scipy (/usr/bin/python3)";
  const Result ok = conform("honest", example_copy("honest", "honest"), "end_to_end");
  ASSERT_EQ(ok.code, 0) << ok.output;
  EXPECT_NE(ok.output.find("[ ok ] consistency"), std::string::npos) << ok.output;
  const struct {
    const char* mode;
    const char* rule;
    const char* says;
  } broken[] = {
      {"r-x1.5", "consistency", "impulse_normal"},      // history R x 1.5, honest summary
      {"impulse+10", "consistency", "impulse_normal"},  // summary impulse 10 % above its rows' integral
      {"times", "times", "strictly increasing"},
      {"nan", "finite", "column kinetic"},
      {"incomplete", "complete", "\"complete\": true"},
      {"sha", "scene sha256", "scene_sha256"},
      {"ms", "units", " in s"},  // times in ms, units still saying s: the values are checked
  };
  std::vector<std::string> output_rules;
  for (const char* r :
       {"outputs", "complete", "finite", "times", "summary keys", "units", "scene sha256", "consistency"})
    output_rules.push_back(r);
  for (const auto& b : broken) {
    std::string name = std::string("copy_") + b.mode;
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    const Result r = conform(name, example_copy(name, b.mode), "end_to_end");
    EXPECT_EQ(r.code, 1) << b.mode << "\n" << r.output;
    EXPECT_NE(r.output.find(fmt::format("[FAIL] {}", b.rule)), std::string::npos) << b.mode << "\n"
                                                                                  << r.output;
    EXPECT_NE(r.output.find(b.says), std::string::npos) << b.mode << "\n" << r.output;
    for (const std::string& other : output_rules)  // only its rule is broken
      if (other != b.rule)
        EXPECT_EQ(r.output.find(fmt::format("[FAIL] {}", other)), std::string::npos)
            << b.mode << " also breaks " << other << "\n"
            << r.output;
  }
}

// `beamimpact run --method` applies the same output rules: an inconsistent run exits 3 naming the
// rule, the quantity and both values, and leaves no summary.json behind.
TEST_F(Protocol, RunRefusesAnInconsistentOutsideRunWithExitThree) {
  if (run("methods").output.find("example    program    runs here") == std::string::npos)
    GTEST_SKIP() << "the example needs scipy (/usr/bin/python3)";
  for (const char* mode : {"r-x1.5", "impulse+10", "incomplete"}) {
    const fs::path out = tmp_ / "run";
    const Result r = run(
        fmt::format("run verification/scenes/paper/s1_central.toml --method copy --methods '{}' --out '{}'",
                    example_copy("copy", mode).string(), out.string()));
    EXPECT_EQ(r.code, 3) << mode << "\n" << r.output;
    const std::string rule = std::string(mode) == "incomplete" ? "complete" : "consistency";
    EXPECT_NE(r.output.find("rule '" + rule + "'"), std::string::npos) << mode << "\n" << r.output;
    if (rule == "consistency")
      EXPECT_NE(r.output.find("contacts[0].impulse_normal"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out / "summary.json")) << mode;  // a broken result never looks complete
    EXPECT_TRUE(fs::exists(out / "summary.rejected.json")) << mode;
  }
  const fs::path out = tmp_ / "honest";
  const Result ok = run(
      fmt::format("run verification/scenes/paper/s1_central.toml --method honest --methods '{}' --out '{}'",
                  example_copy("honest", "honest").string(), out.string()));
  EXPECT_EQ(ok.code, 0) << ok.output;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

// A narrow solver: a rod-only copy declares bending but refuses a bending scene with exit 2 and one
// line. conform reports that scene as not applicable and passes; when every scene it ran was
// refused, conform says so and fails (nothing was checked).
TEST_F(Protocol, ARodOnlySolverPassesConformWithBendingScenesNotApplicable) {
  if (run("methods").output.find("example    program    runs here") == std::string::npos)
    GTEST_SKIP() << "the example needs scipy (/usr/bin/python3)";
  const fs::path f = example_copy("rods", "rod-only");
  const Result r = conform("rods", f, "end_to_end,transverse");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("[n/a ] transverse"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("models rods only"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("1 scene(s) not applicable"), std::string::npos) << r.output;
  EXPECT_NE(read(tmp_ / "rods" / "junit.xml").find("<skipped message=\"not applicable: rod-only"),
            std::string::npos);
  const Result none = run(fmt::format("conform rods --methods '{}' --out '{}' --scenes transverse",
                                      f.string(), (tmp_ / "none").string()));
  EXPECT_EQ(none.code, 1) << none.output;
  EXPECT_NE(none.output.find("every one refused or failed"), std::string::npos) << none.output;
  const Result bad = run(fmt::format("conform rods --methods '{}' --out '{}' --scenes sideways", f.string(),
                                     (tmp_ / "bad").string()));
  EXPECT_EQ(bad.code, 2) << bad.output;
  EXPECT_NE(bad.output.find("--scenes"), std::string::npos) << bad.output;
}

// Bad methods files: one message naming the file and the key, exit 2, on any subcommand.
TEST_F(Protocol, BadMethodsFilesExitTwoNamingFileAndKey) {
  const struct {
    const char* what;
    std::string text, key;
  } bad[] = {
      {"unknown key",
       "[[method]]\nname = \"x\"\ncommand = [\"/bin/sh\", \"{scene}\", \"{out}\"]\nspeed = 1\n",
       "method[0].speed"},
      {"missing command", "[[method]]\nname = \"x\"\n", "method[0].command"},
      {"command that does not exist",
       "[[method]]\nname = \"x\"\ncommand = [\"/no/such\", \"{scene}\", \"{out}\"]\n", "method[0].command"},
      {"unknown placeholder",
       "[[method]]\nname = \"x\"\ncommand = [\"/bin/sh\", \"{scene}\", \"{out}\", \"{nodes}\"]\n",
       "method[0].command"},
      {"duplicate name", "[[method]]\nname = \"ida\"\ncommand = [\"/bin/sh\", \"{scene}\", \"{out}\"]\n",
       "method[0].name"},
  };
  const fs::path f = tmp_ / "bad.toml";
  for (const auto& b : bad) {
    std::ofstream(f) << b.text;
    const std::string run_s1 = fmt::format("run verification/scenes/paper/s1_central.toml --out '{}'",
                                           (tmp_ / "x").string());  // never into the source tree
    for (const std::string& sub : {std::string("methods"), run_s1}) {
      const Result r = run(fmt::format("{} --methods '{}'", sub, f.string()));
      EXPECT_EQ(r.code, 2) << b.what << ": " << r.output;
      EXPECT_NE(r.output.find(fmt::format("error: {}: key '{}'", f.string(), b.key)), std::string::npos)
          << b.what << ": " << r.output;
    }
  }
  // The environment variable is read as the option is.
  std::ofstream(f) << bad[0].text;
  const Result env = run(fmt::format("methods"));
  EXPECT_EQ(env.code, 0) << env.output;
  const Result by_env = run("methods", fmt::format("BEAMIMPACT_METHODS='{}'", f.string()));
  EXPECT_EQ(by_env.code, 2) << by_env.output;
}

}  // namespace
}  // namespace beamimpact
