// Methods files (docs/protocol.md): what a good file gives the registry, each kind of bad file
// refused with the file and the key named, the placeholders of a run, and the one acceptance check.
#include <api/accepts.hpp>
#include <api/external_method.hpp>
#include <api/methods_file.hpp>
#include <api/registry.hpp>

#include <algorithm>
#include <fstream>

#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

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
    } catch (const InputError& e) {
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
      // Listed "runs here" before, then failed to start.
      {"program that is a directory",
       "[[method]]\nname = \"x\"\ncommand = [\"/tmp\", \"{scene}\", \"{out}\"]\n", "method[0].command",
       "not an executable file"},
      {"program that is not executable",
       "[[method]]\nname = \"x\"\ncommand = [\"/etc/passwd\", \"{scene}\", \"{out}\"]\n", "method[0].command",
       "not an executable file"},
      {"check_timeout zero", good_ + "check_timeout = 0\n", "method[0].check_timeout", "> 0"},
      {"check_timeout not a number", good_ + "check_timeout = \"soon\"\n", "method[0].check_timeout",
       "seconds"},
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
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method[0].name");
    EXPECT_NE(std::string(e.what()).find("built-in"), std::string::npos) << e.what();
  }
}

TEST_F(MethodsFile, ANameTakenByABuiltInMethodIsRefusedWhateverItsCase) {
  // "PAPER" was taken beside "paper": two methods whose names differ only in case.
  const fs::path f = write("[[method]]\nname = \"PAPER\"\ncommand = [\"/bin/sh\", \"{scene}\", \"{out}\"]\n");
  try {
    load_methods_file(f);
    FAIL() << "'PAPER' was accepted beside 'paper'";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method[0].name");
    EXPECT_NE(std::string(e.what()).find("built-in"), std::string::npos) << e.what();
  }
  ASSERT_NE(find_method("Paper"), nullptr);  // a name finds its method in any case
  EXPECT_EQ(find_method("Paper")->name, "paper");
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
    } catch (const InputError& e) {
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
  EXPECT_THROW(check_accepts(no_mesh, testing::load_paper_scene("s1_central"), "2"), InputError);
  Method no_friction = m;
  no_friction.accepts.friction = false;
  try {
    check_accepts(no_friction, testing::load_paper_scene("s1_central", {"contacts[0].friction=0.3"}), "");
    FAIL() << "friction accepted by a method that does not model it";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "contacts[0].friction");
    EXPECT_NE(std::string(e.what()).find("not applicable"), std::string::npos) << e.what();
  }
}

// Each accepts key lands in its own field: for every pattern of true and false (each key alone
// true, each alone false, alternating, in blocks), the fields read are exactly the keys written.
// Two keys read into each other's field show as a wrong field in the patterns where they differ.
TEST_F(MethodsFile, EachAcceptsKeyLandsInItsOwnField) {
  const std::vector<std::pair<std::string, bool Method::Accepts::*>> keys = {
      {"dt", &Method::Accepts::dt},
      {"mesh_factor", &Method::Accepts::mesh_factor},
      {"friction", &Method::Accepts::friction},
      {"rigid_friction", &Method::Accepts::rigid_friction},
      {"rotation", &Method::Accepts::rotation},
      {"rigid", &Method::Accepts::rigid},
      {"search", &Method::Accepts::search},
      {"several_contacts", &Method::Accepts::several_contacts},
      {"timoshenko", &Method::Accepts::timoshenko},
      {"hertz", &Method::Accepts::hertz},
      {"bending", &Method::Accepts::bending},
      {"node_to_surface", &Method::Accepts::node_to_surface},
      {"loads", &Method::Accepts::loads},
  };
  // This list is written out here, not read from accepts_keys(), so that a key the code maps to
  // the wrong field shows; it must name every key the code knows, or a new key goes untested.
  ASSERT_EQ(keys.size(), accepts_keys().size());
  for (const AcceptsKey& k : accepts_keys())
    EXPECT_TRUE(std::any_of(keys.begin(), keys.end(), [&](const auto& t) { return t.first == k.key; }))
        << k.key << " is read by the code and missing from this test";
  const std::size_t n = keys.size();
  std::vector<std::vector<bool>> patterns;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<bool> one(n, false), all_but(n, true);
    one[i] = true;
    all_but[i] = false;
    patterns.push_back(one);
    patterns.push_back(all_but);
  }
  for (std::size_t period : {2u, 3u, 4u}) {
    std::vector<bool> p(n);
    for (std::size_t i = 0; i < n; ++i) p[i] = (i / (period / 2)) % 2 == 0 || (period == 3 && i % 3 == 1);
    patterns.push_back(p);
    for (std::size_t i = 0; i < n; ++i) p[i] = !p[i];
    patterns.push_back(p);
  }
  for (const std::vector<bool>& p : patterns) {
    std::string table, shown;
    for (std::size_t i = 0; i < n; ++i) {
      table += keys[i].first + " = " + (p[i] ? "true" : "false") + "\n";
      shown += p[i] ? '1' : '0';
    }
    // {dt} and {mesh} are in the command, so either value of dt and mesh_factor is legal.
    const Method m = read_methods_file(write("[[method]]\nname = \"x\"\ncommand = [\"/bin/sh\", \"{scene}\", "
                                             "\"{out}\", \"{dt}\", \"{mesh}\"]\n[method.accepts]\n" +
                                             table),
                                       "/usr/bin/beamimpact")
                         .at(0);
    for (std::size_t i = 0; i < n; ++i)
      EXPECT_EQ(m.accepts.*keys[i].second, static_cast<bool>(p[i]))
          << keys[i].first << " in pattern " << shown;
  }
}

// bending, node_to_surface and loads against the paper's scenes: S1 is two rods on one line, S2's
// striker node meets B's middle node (x = 5 m on 10 elements of 1 m), S3's meets B at x = 4.5 m,
// inside an element.
TEST_F(MethodsFile, BendingNodeToSurfaceAndLoadsAreRefusedWhenNotDeclared) {
  Method m = read_methods_file(write(good_), "/usr/bin/beamimpact").at(0);  // none of the three
  auto key = [&](const char* scene, const std::vector<std::string>& set = {}) -> std::string {
    try {
      check_accepts(m, testing::load_paper_scene(scene, set), "");
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("not applicable"), std::string::npos) << e.what();
      return e.key();
    }
    return "";
  };
  EXPECT_EQ(key("s1_central"), "");
  EXPECT_EQ(key("s2_transverse"), "bodies");  // bending
  EXPECT_EQ(key("s1_central", {"loads.gravity=[0.0, -10.0]"}), "loads");
  m.accepts.bending = true;
  EXPECT_EQ(key("s2_transverse"), "");             // node to node
  EXPECT_EQ(key("s3_surface_10"), "contacts[0]");  // node to surface
  EXPECT_EQ(key("s1_central", {"effects.bending=true"}), "");
  m.accepts.bending = false;
  EXPECT_EQ(key("s1_central", {"effects.bending=true"}), "bodies");  // frames asked for
  m.accepts.bending = m.accepts.node_to_surface = m.accepts.loads = true;
  EXPECT_EQ(key("s3_surface_10"), "");
  EXPECT_EQ(key("s1_central", {"loads.gravity=[0.0, -10.0]"}), "");
}

}  // namespace
}  // namespace beamimpact
