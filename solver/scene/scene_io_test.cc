// Scene files: the shipped scenes load, --set overrides work, and every kind of bad input gives
// a InputError naming the file, the key and what was expected.
#include <solver/scene/scene_io.hpp>

#include <fstream>

#include <gtest/gtest.h>

#include <solver/scene/TableReader.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

using testing::paper_scene;

TEST(SceneIo, LoadsThePaperScenes) {
  const Scene s1 = load_scene(paper_scene("s1_central"));
  EXPECT_EQ(s1.name, "s1_central");
  ASSERT_EQ(s1.bodies.size(), 2u);
  EXPECT_EQ(s1.bodies[1].start, (Vec2{10.5, 0.0}));
  EXPECT_EQ(s1.contacts[0].node, 10);  // "end" of a 10-element body
  EXPECT_EQ(s1.sha256.size(), 64u);
  const Scene s2 = load_scene(paper_scene("s2_transverse"));
  ASSERT_EQ(s2.bodies[1].supports.size(), 2u);
  EXPECT_TRUE(s2.bodies[1].supports[0].fix_x && s2.bodies[1].supports[0].fix_y);
  EXPECT_TRUE(!s2.bodies[1].supports[1].fix_x && s2.bodies[1].supports[1].fix_y);
  const Scene s4 = load_scene(paper_scene("s4_oblique_45"));
  EXPECT_FALSE(s4.time.dt.has_value());  // "auto"
  EXPECT_DOUBLE_EQ(s4.contacts[0].friction, 0.3);
}

// KeyLog lists the keys the readers asked about by their full path: the keys S2 gives, the ones
// it leaves to their defaults, and the sub-table keys of the entries it has (B's two supports; A
// has none). The innermost log alive receives them.
TEST(SceneIo, KeyLogListsTheKeysAskedAbout) {
  const KeyLog outer;
  {
    const KeyLog inner;
    (void)load_scene(paper_scene("s2_transverse"));
    const std::set<std::string>& k = inner.keys();
    for (const char* key :
         {"name", "time.dt", "time.fraction", "model.rayleigh_mass", "bodies[1].supports[1].fix",
          "contacts[0].law", "output.field_precision", "effects.bending", "loads"})
      EXPECT_TRUE(k.count(key)) << key;
    EXPECT_FALSE(k.count("bodies[0].supports[0].at"));
    EXPECT_TRUE(outer.keys().empty());
  }
  (void)load_scene(paper_scene("s1_central"));
  EXPECT_TRUE(outer.keys().count("bodies[1].elements"));
}

TEST(SceneIo, RecordsAssumedDefaults) {
  const Scene s = load_scene(paper_scene("s1_central"));
  EXPECT_EQ(s.assumed.at("time.allow_above_critical"), "false");
  EXPECT_EQ(s.assumed.at("model.rayleigh_mass"), "0");
  EXPECT_EQ(s.assumed.at("output.fields"), "false");
  EXPECT_EQ(s.assumed.at("output.history"), "true");
  EXPECT_FALSE(s.output.fields);
}

TEST(SceneIo, SceneTextLoadsAsTheFileDoes) {
  std::ifstream in(paper_scene("s1_central"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const Scene file = load_scene(paper_scene("s1_central"), {"output.fields=true"});
  const Scene mem = load_scene_text(text, "<dict>", {"output.fields=true"});
  EXPECT_EQ(mem.sha256, file.sha256);  // the same bytes
  EXPECT_EQ(mem.file, "<dict>");
  EXPECT_TRUE(mem.output.fields);
  EXPECT_EQ(mem.assumed, file.assumed);
  try {
    load_scene_text("name = 3\n", "<dict>");
    FAIL() << "a bad scene text loaded";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "name");
    EXPECT_NE(std::string(e.what()).find("<dict>"), std::string::npos) << e.what();
  }
}

TEST(SceneIo, SetOverridesByPathIndexAndName) {
  const Scene s =
      load_scene(paper_scene("s1_central"), {"time.dt=0.005", "bodies[1].elements=20", "bodies.A.E=200",
                                             "contacts.0.friction=0.1", "model.mass=consistent"});
  EXPECT_DOUBLE_EQ(*s.time.dt, 0.005);
  EXPECT_EQ(s.bodies[1].elements, 20);
  EXPECT_DOUBLE_EQ(s.bodies[0].E, 200.0);
  EXPECT_DOUBLE_EQ(s.contacts[0].friction, 0.1);
  EXPECT_EQ(s.model.mass, MassKind::kConsistent);  // a bare word is read as a string
  EXPECT_EQ(s.overrides.at("time.dt"), "0.005");
}

TEST(SceneIo, SetStepInSecondsOnAnAutoScene) {
  // S4-45 has dt = "auto" with fraction = 0.5: a step in seconds from --set replaces "auto" and
  // its fraction (no --set can remove a key); a file that gives both is still refused.
  const Scene s = load_scene(paper_scene("s4_oblique_45"), {"time.dt=0.001"});
  ASSERT_TRUE(s.time.dt.has_value());
  EXPECT_DOUBLE_EQ(*s.time.dt, 0.001);
  const Scene back = load_scene(paper_scene("s4_oblique_45"), {"time.dt=0.001", "time.dt=\"auto\""});
  EXPECT_FALSE(back.time.dt.has_value());
  EXPECT_DOUBLE_EQ(back.time.fraction, 0.5);  // the file's fraction stays with "auto"
  EXPECT_THROW(load_scene(paper_scene("s4_oblique_45"), {"time.dt=0.001", "time.fraction=0.25"}), InputError);
}

// Writes `text` to a temporary scene file and returns the InputError it raises.
InputError error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  const std::string path = testing::temp_path("bad_scene.toml").string();
  std::ofstream(path) << text;
  try {
    load_scene(path, sets);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError("", "", "");
}

std::string good() {
  std::ifstream in(paper_scene("s2_transverse"));
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

struct BadCase {
  const char* what;
  std::string text;
  const char* key;
  const char* says;
};

TEST(SceneIo, BadInputNamesFileKeyAndExpectation) {
  const std::string g = good();
  const std::vector<BadCase> cases = {
      {"missing key", replace(g, "end = 3.0", ""), "time.end", "missing"},
      {"unknown key", replace(g, "output_every = 1", "output_every = 1\nsteps = 3"), "time.steps",
       "unknown key"},
      {"wrong type", replace(g, "elements = 5", "elements = \"five\""), "bodies[0].elements",
       "expected a whole number"},
      {"negative area", replace(g, "area = 0.4", "area = -0.4"), "bodies[0].area", "positive"},
      {"zero modulus", replace(g, "E = 100.0", "E = 0.0"), "bodies[0].E", "positive"},
      {"zero density", replace(g, "rho = 1.0", "rho = 0"), "bodies[0].rho", "positive"},
      {"zero length", replace(g, "end = [5.0, 0.1]", "end = [5.0, 5.1]"), "bodies[0].end",
       "length must be positive"},
      {"missing support node", replace(g, "{ at = \"end\", fix = [\"y\"] }", "{ at = 11, fix = [\"y\"] }"),
       "bodies[1].supports[1].at", "node index 0..10"},
      {"missing contact node", replace(g, "node = \"end\"", "node = 6"), "contacts[0].node",
       "node index 0..5"},
      {"unknown body", replace(g, "target = \"B\"", "target = \"C\""), "contacts[0].target",
       "name of a body"},
      {"overlap", replace(g, "end = [5.0, 0.1]", "end = [5.0, -0.1]"), "bodies[1].start", "overlap at t = 0"},
      {"bad choice", replace(g, "mass = \"lumped\"", "mass = \"heavy\""), "model.mass",
       "one of \"lumped\" \"consistent\""},
      {"syntax", replace(g, "[time]", "[time"), "", "TOML syntax error at line"},
      {"bad dt", replace(g, "dt = 0.01", "dt = \"fast\""), "time.dt", "\"auto\""},
      {"fields not a boolean", g + "\n[output]\nfields = \"yes\"\n", "output.fields",
       "expected true or false"},
      {"unknown output key", g + "\n[output]\nvtk = true\n", "output.vtk", "unknown key"},
      {"unknown fix", replace(g, "fix = [\"y\"]", "fix = [\"transverse\"]"), "bodies[1].supports[1].fix",
       "\"x\", \"y\", \"theta\", \"axial\", \"normal\""},
      {"fix not a string", replace(g, "fix = [\"y\"]", "fix = [1]"), "bodies[1].supports[1].fix",
       "\"normal\""},
      {"empty fix", replace(g, "fix = [\"y\"]", "fix = []"), "bodies[1].supports[1].fix", "non-empty array"},
  };
  for (const BadCase& c : cases) {
    const InputError e = error_of(c.text);
    EXPECT_EQ(e.key(), c.key) << c.what << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << c.what << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find("bad_scene.toml"), std::string::npos) << c.what;
  }
}

// Supports in the body's own axes: "axial" along start -> end, "normal" across it. A roller in
// global axes on an inclined body is legal but another problem than the roller across it: the
// scene carries a warning naming the file and the key and pointing at fix = ["normal"].
TEST(SceneIo, BodyAxisSupportsAndTheGlobalRollerWarning) {
  const std::string g = good();
  const std::string path = testing::temp_path("axes_scene.toml").string();
  const auto load_text = [&](const std::string& text) {
    std::ofstream(path) << text;
    return load_scene(path);
  };
  const Scene s2 = load_text(replace(g, "fix = [\"y\"]", "fix = [\"normal\", \"axial\"]"));
  const Support& r = s2.bodies[1].supports[1];
  EXPECT_TRUE(r.fix_normal && r.fix_axial && !r.fix_x && !r.fix_y && !r.fix_theta);
  EXPECT_TRUE(s2.warnings.empty());
  EXPECT_TRUE(load_scene(paper_scene("s2_transverse")).warnings.empty());  // a y roller on a beam along x
  // B inclined (end at (8, -6): atan(-0.75) = -36.8699 deg): its y roller is named in a warning; its pin is
  // not.
  const std::string inclined = replace(g, "end = [10.0, 0.0]", "end = [8.0, -6.0]");
  const Scene w = load_text(inclined);
  ASSERT_EQ(w.warnings.size(), 1u);
  for (const char* says :
       {"axes_scene.toml", "bodies[1].supports[1].fix", "36.8699 deg", "fix = [\"normal\"]"})
    EXPECT_NE(w.warnings[0].find(says), std::string::npos) << says << " in: " << w.warnings[0];
  EXPECT_TRUE(load_text(replace(inclined, "fix = [\"y\"]", "fix = [\"normal\"]")).warnings.empty());
  // A second support at the same node that completes a pin: no roller, no warning.
  EXPECT_TRUE(load_text(replace(inclined, "{ at = \"end\", fix = [\"y\"] }",
                                "{ at = \"end\", fix = [\"y\"] }, { at = \"end\", fix = [\"x\"] }"))
                  .warnings.empty());
}

TEST(SceneIo, BadOverrideIsAnError) {
  const InputError e = error_of(good(), {"bodies.Z.elements=3"});
  EXPECT_NE(std::string(e.what()).find("no entry 'Z'"), std::string::npos) << e.what();
  const InputError typo = error_of(good(), {"time.ddt=0.1"});
  EXPECT_EQ(typo.key(), "time.ddt");  // a typo becomes an unknown key, not a silent default
}

}  // namespace
}  // namespace beamimpact
