// The plug-in protocol end to end (docs/protocol.md): methods files on the command line, a
// stand-in external solver (testdata/standin_solver.py) through run, verify and conform, broken
// copies of it failing conform with the rule named, and bad methods files refused with exit 2.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

struct Result {
  int code;
  std::string out;
};

class Protocol : public ::testing::Test {
 protected:
  void SetUp() override {
    src_ = BEAMIMPACT_SOURCE;
    exe_ = BEAMIMPACT_EXE;
    tmp_ = fs::temp_directory_path() / fmt::format("beamimpact_protocol_{}", ::getpid());
    fs::remove_all(tmp_);
    fs::create_directories(tmp_);
  }
  void TearDown() override { fs::remove_all(tmp_); }

  Result run(const std::string& args) {
    const fs::path log = tmp_ / "out.txt";
    const int rc = std::system(
        fmt::format("cd '{}' && '{}' {} > '{}' 2>&1", src_.string(), exe_.string(), args, log.string())
            .c_str());
    return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, read(log)};
  }

  static std::string read(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }

  /// A methods file declaring the stand-in as `name`, breaking the rule `broken` ("" none).
  fs::path standin(const std::string& name, const std::string& broken = "") {
    const fs::path f = tmp_ / (name + ".toml");
    std::ofstream(f) << fmt::format(
        "[[method]]\nname = \"{}\"\nsummary = \"protocol stand-in\"\n"
        "command = [\"/usr/bin/python3\", \"{}/tools/beamimpact/testdata/standin_solver.py\", \"{{scene}}\", "
        "\"--out\", \"{{out}}\", \"--dt\", \"{{dt}}\"{}]\n"
        "check = [\"/usr/bin/python3\", \"-c\", \"import tomllib\"]\n"
        "accepts = {{ dt = true, rotation = true, rigid = true, several_contacts = true }}\n",
        name, src_.string(), broken.empty() ? "" : fmt::format(", \"--break\", \"{}\"", broken));
    return f;
  }

  fs::path src_, exe_, tmp_;
};

TEST_F(Protocol, MethodsListsEveryMethodWithItsOriginAndWhetherItRunsHere) {
  const fs::path f = standin("standin");
  const Result r = run(fmt::format("methods --methods '{}'", f.string()));
  ASSERT_EQ(r.code, 0) << r.out;
  for (const char* name : {"paper ", "exact ", "ida ", "fenicsx ", "standin "})
    EXPECT_NE(r.out.find(name), std::string::npos) << name << "\n" << r.out;
  EXPECT_NE(r.out.find("from: built-in"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("from: " + f.string()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("from: " + (src_ / "verification/methods.toml").string()), std::string::npos) << r.out;
  // A method whose check fails is listed as one that cannot run here, with its check named.
  std::ofstream(tmp_ / "absent.toml")
      << "[[method]]\nname = \"absent\"\ncommand = [\"/bin/sh\", \"{scene}\", "
         "\"{out}\"]\ncheck = [\"/bin/false\"]\n";
  const Result a = run(fmt::format("methods --methods '{}'", (tmp_ / "absent.toml").string()));
  EXPECT_NE(a.out.find("cannot run here: absent: its check '/bin/false' exited 1"), std::string::npos)
      << a.out;
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
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string summary = read(out / "summary.json");
  EXPECT_NE(summary.find("\"dt\": 0.02"), std::string::npos) << summary;        // {dt} reached the program
  EXPECT_NE(r.out.find("standin run: 200 steps"), std::string::npos) << r.out;  // 4 s / 0.02 s
  const Result fr =
      run(fmt::format("run verification/scenes/paper/s1_central.toml --method standin --methods '{}' "
                      "--out '{}' --set contacts[0].friction=0.3",
                      f.string(), out.string()));
  EXPECT_EQ(fr.code, 2) << fr.out;
  EXPECT_NE(fr.out.find("not applicable: method 'standin' does not take friction"), std::string::npos)
      << fr.out;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  // What it did not declare is refused before it starts: a mesh.
  const Result mr =
      run(fmt::format("run verification/scenes/paper/s1_central.toml --method standin --methods '{}' "
                      "--out '{}' --mesh 2",
                      f.string(), out.string()));
  EXPECT_EQ(mr.code, 2) << mr.out;
  EXPECT_NE(mr.out.find("accepts.mesh_factor = false"), std::string::npos) << mr.out;
}

// In the matrix a refused case is "not applicable": a skipped gate, never a pass or a crash.
TEST_F(Protocol, ARefusedCaseIsNotApplicableInVerify) {
  const fs::path f = standin("standin");
  const fs::path m = tmp_ / "m.toml";
  std::ofstream(m) << fmt::format(
      "[settings]\nroot = \"{}\"\n[scenes]\ns1 = \"verification/scenes/paper/s1_central.toml\"\n"
      "[[case]]\nscene = \"s1\"\nmethod = \"standin\"\nrequired = false\nset = "
      "[\"contacts[0].friction=0.3\"]\n"
      "reference = {{ method = \"paper\" }}\n"
      "gates = [{{ metric = \"impulse\", tol = 0.01, why = \"a method that does not model friction\" }}]\n",
      src_.string());
  const Result r = run(
      fmt::format("verify '{}' --methods '{}' --out '{}'", m.string(), f.string(), (tmp_ / "v").string()));
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("0 passed, 0 failed, 1 skipped"), std::string::npos) << r.out;
  const std::string junit = read(tmp_ / "v" / "junit.xml");
  EXPECT_NE(junit.find("<skipped"), std::string::npos) << junit;
  EXPECT_NE(junit.find("not applicable"), std::string::npos) << junit;
}

// The conforming stand-in passes every rule; each broken copy fails with its rule named.
TEST_F(Protocol, ConformPassesTheStandInAndNamesTheRuleABrokenCopyBreaks) {
  const Result ok = run(fmt::format("conform standin --methods '{}' --out '{}'", standin("standin").string(),
                                    (tmp_ / "c").string()));
  EXPECT_EQ(ok.code, 0) << ok.out;
  EXPECT_NE(ok.out.find("conform passed"), std::string::npos) << ok.out;
  EXPECT_NE(read(tmp_ / "c" / "junit.xml").find("failures=\"0\""), std::string::npos);
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
    EXPECT_EQ(r.code, 1) << b.broken << "\n" << r.out;
    EXPECT_NE(r.out.find(fmt::format("[FAIL] {}", b.rule)), std::string::npos) << b.broken << "\n" << r.out;
    const std::string junit = read(out / "junit.xml");
    EXPECT_NE(junit.find(fmt::format("<failure message=\"{}: ", b.rule)), std::string::npos) << junit;
    EXPECT_NE(junit.find(b.file), std::string::npos) << junit;
  }
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
    for (const char* sub : {"methods", "run verification/scenes/paper/s1_central.toml --out x"}) {
      const Result r = run(fmt::format("{} --methods '{}'", sub, f.string()));
      EXPECT_EQ(r.code, 2) << b.what << ": " << r.out;
      EXPECT_NE(r.out.find(fmt::format("error: {}: key '{}'", f.string(), b.key)), std::string::npos)
          << b.what << ": " << r.out;
    }
  }
  // The environment variable is read as the option is.
  std::ofstream(f) << bad[0].text;
  const Result env = run(fmt::format("methods"));
  EXPECT_EQ(env.code, 0) << env.out;
  const int rc = std::system(fmt::format("cd '{}' && BEAMIMPACT_METHODS='{}' '{}' methods > /dev/null 2>&1",
                                         src_.string(), f.string(), exe_.string())
                                 .c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 2);
}

}  // namespace
}  // namespace beamimpact
