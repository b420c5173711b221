// Overrides are values put into the parsed scene before it is read: a typed one is the --set of
// its text, method tables stay parsed tables, and a scene given as a table is the file's scene.
#include <solver/scene/Override.hpp>

#include <fstream>

#include <gtest/gtest.h>

#include <solver/scene/TableReader.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

using testing::paper_scene;

std::string s1_text() {
  std::ifstream in(paper_scene("s1_central"));
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A typed step and element count read as the --set of their text: the same numbers and the same
// record. 0.005 is the double nearest 5e-3 either way (TOML reads decimals to nearest).
TEST(Override, TypedIsTheSetOfItsText) {
  const Scene typed = load_scene_with(
      paper_scene("s1_central"), {make_override("time.dt", toml::value<double>(0.005), "0.005"),
                                  make_override("bodies.B.elements", toml::value<std::int64_t>(20), "20")});
  const Scene text = load_scene(paper_scene("s1_central"), {"time.dt=0.005", "bodies.B.elements=20"});
  ASSERT_TRUE(typed.time.dt.has_value());
  EXPECT_EQ(*typed.time.dt, *text.time.dt);
  EXPECT_EQ(*typed.time.dt, 0.005);
  EXPECT_EQ(typed.bodies[1].elements, 20);
  EXPECT_EQ(typed.overrides, text.overrides);
  EXPECT_EQ(typed.overrides.at("time.dt"), "0.005");
  EXPECT_EQ(typed.assumed, text.assumed);
}

// A typed value of the wrong kind is refused as its --set text would be: file, key, expectation.
TEST(Override, TypedBadValueNamesFileAndKey) {
  try {
    (void)load_scene_with(paper_scene("s1_central"),
                          {make_override("time.dt", toml::value<std::string>("soon"), "soon")});
    FAIL() << "dt = \"soon\" loaded";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "time.dt") << e.what();
    EXPECT_NE(std::string(e.what()).find("s1_central.toml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected a positive number (s) or \"auto\""), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parse_override("=3", "f.toml"), InputError);
  EXPECT_THROW((void)load_scene_with(paper_scene("s1_central"),
                                     {make_override("bodies.Z.elements", toml::value<std::int64_t>(2), "2")}),
               InputError);
}

// A method's table is kept parsed, with the overrides of its keys applied, and read in place.
TEST(Override, MethodTablesStayParsed) {
  const Scene s = load_scene_text(s1_text() + "\n[ida]\nrtol = 1e-6\nlinear_solver = \"klu\"\n", "t.toml",
                                  {"ida.rtol=1e-7"});
  const toml::table& ida = s.method_tables.at("ida");
  EXPECT_EQ(ida["rtol"].value<double>(), 1e-7);
  EXPECT_EQ(ida["linear_solver"].value<std::string>(), "klu");
  std::map<std::string, std::string> assumed;
  MethodOptions opts(s, "ida", &assumed);
  EXPECT_EQ(opts.reader().number("rtol", "a tolerance"), 1e-7);
  EXPECT_THROW(opts.reader().finish(), InputError);  // linear_solver was not asked for
  MethodOptions none(s, "exact", &assumed);          // no [exact]: an empty table
  EXPECT_EQ(none.reader().number_or("modes_min", 4.0, "a count"), 4.0);
  none.reader().finish();
}

// A scene given as a table is the scene of the file with that text: the same numbers and record,
// and the SHA-256 of the table written as TOML (what Scene.from_dict's scenes always had).
TEST(Override, TableSceneIsTheFileScene) {
  toml::table root = toml::parse(s1_text());
  std::ostringstream written;
  written << root << "\n";
  const Scene from_table = load_scene_table(root, "<dict>", {parse_override("output.fields=true", "<dict>")});
  const Scene from_text = load_scene_text(written.str(), "<dict>", {"output.fields=true"});
  const Scene from_file = load_scene(paper_scene("s1_central"), {"output.fields=true"});
  EXPECT_EQ(from_table.sha256, from_text.sha256);
  EXPECT_EQ(from_table.file, "<dict>");
  EXPECT_EQ(from_table.assumed, from_file.assumed);
  EXPECT_EQ(from_table.overrides, from_file.overrides);
  EXPECT_TRUE(from_table.output.fields);
  ASSERT_EQ(from_table.bodies.size(), 2u);
  EXPECT_EQ(from_table.bodies[1].start, from_file.bodies[1].start);
  EXPECT_EQ(from_table.bodies[0].inertia, from_file.bodies[0].inertia);
  EXPECT_EQ(*from_table.time.dt, 0.01);
}

}  // namespace
}  // namespace beamimpact
