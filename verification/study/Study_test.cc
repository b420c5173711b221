// Study files, designs and the overrides of a point.
#include <verification/study/Study.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include <solver/scene/scene_io.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::study {
namespace {

namespace fs = std::filesystem;
const fs::path kRoot = BEAMIMPACT_SOURCE_DIR_DEFAULT;

fs::path write_study(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("beamimpact_study_test_" + name + ".toml");
  std::ofstream(p) << "name = \"" << name << "\"\nscene = \""
                   << (kRoot / "verification/scenes/paper/s4_oblique_90.toml").string() << "\"\n"
                   << text;
  return p;
}

const std::string kMethods = "methods = [\"paper\"]\nreference = { method = \"ida\" }\n";

/// The message Study::load gives for a study file with `text`, or "no error".
std::string message(const std::string& name, const std::string& text) {
  try {
    (void)Study::load(write_study(name, text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A scene path longer than the file system allows (ENAMETOOLONG, 255 bytes a name) is a missing
// scene, not an error of the file system.
TEST(Study, SceneNameTooLongIsBadInputNamingTheKey) {
  const fs::path p = fs::temp_directory_path() / "beamimpact_study_test_long.toml";
  std::ofstream(p) << "name = \"long\"\nscene = \"" << std::string(300, 'b') << ".toml\"\n" << kMethods;
  try {
    (void)Study::load(p);
    FAIL() << "a missing scene was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scene"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not found"), std::string::npos) << e.what();
  }
}

TEST(Study, GridIsTheFullProductLastParameterFastest) {
  const Study s = Study::load(write_study("grid", kMethods + R"(
[[parameter]]
name = "mu"
key = "contacts[0].friction"
from = 0.0
to = 1.0
count = 5
[[parameter]]
name = "mesh"
mesh = true
values = [1, 2]
)"));
  const auto pts = design_points(s);
  ASSERT_EQ(pts.size(), 10u);
  EXPECT_EQ(pts[0].values, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(pts[1].values, (std::vector<double>{0.0, 2.0}));
  EXPECT_EQ(pts[2].values, (std::vector<double>{0.25, 1.0}));  // from + (to - from) k / (count - 1)
  EXPECT_EQ(pts[9].values, (std::vector<double>{1.0, 2.0}));
}

TEST(Study, LatinHypercubeHasOnePointPerStratumAndIsReproducible) {
  const std::string text = kMethods + R"(
[design]
kind = "lhs"
samples = 40
seed = 7
[[parameter]]
name = "mu"
key = "contacts[0].friction"
from = 0.0
to = 1.0
[[parameter]]
name = "rho"
key = "bodies.A.rho"
from = 7000.0
to = 9000.0
)";
  const Study s = Study::load(write_study("lhs", text));
  const auto a = design_points(s), b = design_points(s);
  ASSERT_EQ(a.size(), 40u);
  for (std::size_t k = 0; k < 2; ++k) {
    std::set<int> strata;  // the defining property: each of the 40 equal strata holds exactly one point
    const double lo = k == 0 ? 0.0 : 7000.0, width = k == 0 ? 1.0 : 2000.0;
    for (const auto& p : a) strata.insert(static_cast<int>(std::floor((p.values[k] - lo) / width * 40.0)));
    EXPECT_EQ(strata.size(), 40u) << "parameter " << k;
    EXPECT_EQ(*strata.begin(), 0);
    EXPECT_EQ(*strata.rbegin(), 39);
  }
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].values, b[i].values);  // fixed seed
  Study other = s;
  other.seed = 8;
  EXPECT_NE(design_points(other)[0].values, a[0].values);
}

TEST(Study, RakeReproducesThePaperGeometryOfTheShippedScenes) {
  // The S4 scenes at 45 and 60 deg were written by hand from the paper's geometry (striker end
  // fixed, 5 m long, 1 m/s along its axis): the rake transform of the 90 deg scene must give them.
  const Study s = Study::load(write_study("rake", kMethods + R"(
[[parameter]]
name = "alpha0"
rake = "A"
values = [45, 60]
)"));
  const auto pts = design_points(s);
  for (int k = 0; k < 2; ++k) {
    const Scene got = load_scene(s.scene, overrides(s, pts[static_cast<std::size_t>(k)]));
    const Scene want = load_scene(kRoot / (k == 0 ? "verification/scenes/paper/s4_oblique_45.toml"
                                                  : "verification/scenes/paper/s4_oblique_60.toml"));
    for (int c = 0; c < 2; ++c) {
      // the scene files carry 16 digits: agreement to 1e-12 m (m/s)
      EXPECT_NEAR(got.bodies[0].start[c], want.bodies[0].start[c], 1e-12);
      EXPECT_NEAR(got.bodies[0].velocity[c], want.bodies[0].velocity[c], 1e-12);
      EXPECT_EQ(got.bodies[0].end[c], want.bodies[0].end[c]);
    }
  }
}

TEST(Study, BadInputNamesTheFileAndTheKey) {
  const std::string mu = "[[parameter]]\nname = \"mu\"\nkey = \"contacts[0].friction\"\nvalues = [0.1]\n";
  EXPECT_NE(
      message("nomethod", "methods = [\"nope\"]\nreference = { method = \"ida\" }\n" + mu).find("methods"),
      std::string::npos);
  EXPECT_NE(message("noparam", kMethods).find("parameter"), std::string::npos);
  EXPECT_NE(message("novalues", kMethods + "[[parameter]]\nname = \"mu\"\nkey = \"contacts[0].friction\"\n")
                .find("parameter[0].values"),
            std::string::npos);
  EXPECT_NE(
      message("badkey", kMethods + "[[parameter]]\nname = \"x\"\nkey = \"bodies.Z.area\"\nvalues = [1]\n")
          .find("bodies.Z.area"),
      std::string::npos);
  EXPECT_NE(message("badnorm", kMethods + "norms = [\"nonorm\"]\n" + mu).find("nonorm"), std::string::npos);
}

// Cost before any run: a grid of 1e10 points is refused before a point is made (it held 2 GB in
// 20 s), and a study whose runs add up beyond an ordinary run's work needs allow_long_run.
TEST(Study, CostBeyondMemoryOrOrdinaryWorkIsRefusedWithTheEstimate) {
  std::string grid;  // ten parameters of ten levels: 10^10 points
  for (int i = 0; i < 10; ++i)
    grid += "[[parameter]]\nname = \"p" + std::to_string(i) +
            "\"\nkey = \"contacts[0].friction\"\nvalues = [0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9]\n";
  const std::string huge = message("huge", kMethods + grid);
  EXPECT_NE(huge.find("parameter"), std::string::npos) << huge;
  EXPECT_NE(huge.find("1e+10 points"), std::string::npos) << huge;
  // S4-90 as shipped: dt = "auto" = 0.5 x le / c = 0.5 x 1 m / 4629 m/s, 926 steps to 0.1 s, 51
  // DOFs: 4.7e4 DOF-steps. Refined 500 and 1000 times (DOFs and steps both scale), each point run
  // by the paper and by IDA: 2 x 4.7e4 x (500^2 + 1000^2) = 1.2e11 DOF-steps, above the ordinary
  // 1e11 (the estimate bounds it by the finest mesh: 1.9e11).
  const std::string mesh = "[[parameter]]\nname = \"mesh\"\nmesh = true\nvalues = [500, 1000]\n";
  const std::string long_study = message("long", kMethods + mesh);
  EXPECT_NE(long_study.find("allow_long_run"), std::string::npos) << long_study;
  EXPECT_NE(long_study.find("DOF-steps"), std::string::npos) << long_study;
  EXPECT_EQ(message("long_allowed", kMethods + "allow_long_run = true\n" + mesh), "no error");
  // The shipped studies are ordinary.
  for (const char* f : {"s4_angle_friction.toml", "s4_throughput.toml"})
    EXPECT_NO_THROW((void)Study::load(kRoot / "verification/studies" / f)) << f;
}

}  // namespace
}  // namespace beamimpact::study
