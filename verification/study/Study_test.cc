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
  auto message = [](const std::string& name, const std::string& text) -> std::string {
    try {
      (void)Study::load(write_study(name, text));
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
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

}  // namespace
}  // namespace beamimpact::study
