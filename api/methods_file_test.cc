// Methods files (docs/protocol.md): what a good file gives the registry, each kind of bad file
// refused with the file and the key named, the placeholders of a run, and the one acceptance check.
#include <api/accepts.hpp>
#include <api/external_method.hpp>
#include <api/methods_file.hpp>

#include <fstream>

#include <gtest/gtest.h>

#include <solver/scene/SceneError.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

class MethodsFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("beamimpact_methods_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "solver.py") << "print('stand-in')\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& text) {
    const fs::path f = dir_ / "methods.toml";
    std::ofstream(f) << text;
    return f;
  }
  /// The error of reading `text`, as (key, message); ("", "no error") when it reads.
  std::pair<std::string, std::string> error(const std::string& text) {
    try {
      (void)read_methods_file(write(text), "/usr/bin/beamimpact");
    } catch (const SceneError& e) {
      EXPECT_EQ(e.file(), (dir_ / "methods.toml").string());
      return {e.key(), e.what()};
    }
    return {"", "no error"};
  }

  fs::path dir_;
  const std::string good_ =
      "[[method]]\nname = \"standin\"\nsummary = \"a stand-in\"\n"
      "command = [\"/bin/sh\", \"{here}/solver.py\", \"{scene}\", \"--out\", \"{out}\", \"--dt\", \"{dt}\", "
      "\"--mesh={mesh}\", \"{beamimpact}\"]\n"
      "accepts = { dt = true, friction = true }\n";
};

TEST_F(MethodsFile, ReadsAMethodWithItsFolderAndProgramExpanded) {
  const std::vector<Method> ms = read_methods_file(write(good_), "/usr/bin/beamimpact");
  ASSERT_EQ(ms.size(), 1u);
  const Method& m = ms[0];
  EXPECT_EQ(m.name, "standin");
  EXPECT_EQ(m.origin, (dir_ / "methods.toml").string());
  EXPECT_EQ(m.options_table, "standin");  // a scene's [standin] table is its options
  EXPECT_FALSE(m.in_process());
  EXPECT_EQ(m.command[1], (dir_ / "solver.py").string());
  EXPECT_EQ(m.command.back(), "/usr/bin/beamimpact");
  EXPECT_TRUE(m.accepts.dt);
  EXPECT_TRUE(m.accepts.friction);
  // Keys left out are false: the method takes only what it declares.
  EXPECT_FALSE(m.accepts.rotation || m.accepts.rigid || m.accepts.search || m.accepts.several_contacts ||
               m.accepts.mesh_factor || m.accepts.timoshenko || m.accepts.hertz);
  EXPECT_FALSE(m.slow);
}

// Each bad file: one message naming the file (checked in error()) and the key.
TEST_F(MethodsFile, RefusesBadFilesNamingTheKey) {
  const struct {
    const char* what;
    std::string text, key, says;
  } bad[] = {
      {"unknown key", good_ + "colour = \"red\"\n", "method[0].colour", "unknown key"},
      {"unknown accepts key",
       "[[method]]\nname = \"x\"\ncommand = [\"/bin/sh\", \"{scene}\", \"{out}\"]\n"
       "accepts = { wings = true }\n",
       "method[0].accepts.wings", "unknown key"},
      {"missing command", "[[method]]\nname = \"x\"\n", "method[0].command", "missing"},
      {"empty command", "[[method]]\nname = \"x\"\ncommand = []\n", "method[0].command", "non-empty"},
      {"program that does not exist",
       "[[method]]\nname = \"x\"\ncommand = [\"/no/such/solver\", \"{scene}\", \"{out}\"]\n",
       "method[0].command", "/no/such/solver does not exist"},
      {"program not on PATH",
       "[[method]]\nname = \"x\"\ncommand = [\"no-such-solver-xyz\", \"{scene}\", \"{out}\"]\n",
       "method[0].command", "not on PATH"},
      {"script that does not exist",
       "[[method]]\nname = \"x\"\ncommand = [\"/bin/sh\", \"{here}/missing.py\", \"{scene}\", \"{out}\"]\n",
       "method[0].command", "missing.py does not exist"},
      {"unknown placeholder",
       "[[method]]\nname = \"x\"\ncommand = [\"/bin/sh\", \"{scene}\", \"{out}\", \"{steps}\"]\n",
       "method[0].command", "unknown placeholder {steps}"},
      {"no {out}", "[[method]]\nname = \"x\"\ncommand = [\"/bin/sh\", \"{scene}\"]\n", "method[0].command",
       "{out}"},
      {"duplicate name", good_ + good_, "method[1].name", "declared twice"},
      {"dt accepted but not passed",
       "[[method]]\nname = \"x\"\ncommand = [\"/bin/sh\", \"{scene}\", \"{out}\"]\naccepts = { dt = true }\n",
       "method[0].accepts.dt", "no {dt}"},
      {"accepts not a boolean",
       "[[method]]\nname = \"x\"\ncommand = [\"/bin/sh\", \"{scene}\", \"{out}\"]\n"
       "accepts = { friction = \"yes\" }\n",
       "method[0].accepts.friction", "true or false"},
      {"no method at all", "name = \"x\"\n", "method", ""},
  };
  for (const auto& b : bad) {
    const auto [key, message] = error(b.text);
    EXPECT_EQ(key, b.key) << b.what << ": " << message;
    EXPECT_NE(message.find(b.says), std::string::npos) << b.what << ": " << message;
  }
}

TEST_F(MethodsFile, ANameTakenByABuiltInMethodIsRefused) {
  const fs::path f = write("[[method]]\nname = \"paper\"\ncommand = [\"/bin/sh\", \"{scene}\", \"{out}\"]\n");
  try {
    load_methods_file(f);
    FAIL() << "a second 'paper' was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key(), "method[0].name");
    EXPECT_NE(std::string(e.what()).find("built-in"), std::string::npos) << e.what();
  }
}

// An argument whose placeholder has no value is left out with the option before it.
TEST_F(MethodsFile, RunArgumentsLeaveOutWhatWasNotAskedFor) {
  const Method m = read_methods_file(write(good_), "/usr/bin/beamimpact").at(0);
  const auto with = external_argv(m, {"s.toml", "out", "0.005", "2", "1"});
  const std::vector<std::string> expected_with = {
      "/bin/sh",  (dir_ / "solver.py").string(), "s.toml", "--out", "out", "--dt", "0.005",
      "--mesh=2", "/usr/bin/beamimpact"};
  EXPECT_EQ(with, expected_with);
  const auto without = external_argv(m, {"s.toml", "out", "", "", "1"});
  const std::vector<std::string> expected_without = {
      "/bin/sh", (dir_ / "solver.py").string(), "s.toml", "--out", "out", "/usr/bin/beamimpact"};
  EXPECT_EQ(without, expected_without);
}

// The one acceptance check: a scene feature the method did not declare is refused (exit 2 in the
// CLI, not applicable in the suite), naming the scene key; what it declared passes.
TEST_F(MethodsFile, AcceptanceIsCheckedAgainstTheScene) {
  const Method m = read_methods_file(write(good_), "/usr/bin/beamimpact").at(0);  // friction, dt only
  auto refusal = [&](const std::vector<std::string>& set, const std::string& mesh = "") -> std::string {
    try {
      check_accepts(m, testing::load_paper_scene("s1_central", set), mesh);
    } catch (const SceneError& e) {
      return e.key() + ": " + e.what();
    }
    return "";
  };
  EXPECT_EQ(refusal({}), "");
  EXPECT_EQ(refusal({"contacts[0].friction=0.3"}), "");  // declared
  EXPECT_EQ(refusal({"time.dt=0.005"}), "");             // declared
  EXPECT_EQ(refusal({}, "coarse"), "");                  // its command has {mesh}: a preset of its own
  EXPECT_NE(refusal({"model.kinematics=\"corotational\""}).find("model.kinematics"), std::string::npos);
  EXPECT_NE(refusal({"bodies[0].rigid=true"}).find("bodies[0].rigid"), std::string::npos);
  EXPECT_NE(refusal({"contacts[0].node=\"all\""}).find("contacts[0].node"), std::string::npos);
  EXPECT_NE(refusal({"bodies.B.theory=timoshenko"}).find("bodies[1].theory"), std::string::npos);
  EXPECT_NE(refusal({"contacts[0].law=hertz", "contacts[0].stiffness=50"}).find("contacts[0].law"),
            std::string::npos);
  EXPECT_EQ(refusal({"ida.rtol=1e-6"}), "");  // another method's options: left to that method
  EXPECT_NE(refusal({"bogus.x=1"}).find("unknown table [bogus]"), std::string::npos);
  Method no_mesh = m;
  no_mesh.command.pop_back();
  no_mesh.command.erase(no_mesh.command.end() - 1);  // "--mesh={mesh}"
  EXPECT_THROW(check_accepts(no_mesh, testing::load_paper_scene("s1_central"), "2"), SceneError);
  Method no_friction = m;
  no_friction.accepts.friction = false;
  try {
    check_accepts(no_friction, testing::load_paper_scene("s1_central", {"contacts[0].friction=0.3"}), "");
    FAIL() << "friction accepted by a method that does not model it";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key(), "contacts[0].friction");
    EXPECT_NE(std::string(e.what()).find("not applicable"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace beamimpact
