// The scorecard's choice of reference and tolerances, read from the shipped matrix: exact where
// the matrix compares a scene with it, else IDA; the method's own case first, then the paper's.
#include <verification/matrix/scorecard.hpp>

#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;

const ScoreItem& item(const std::vector<ScoreItem>& items, const std::string& scene) {
  for (const auto& i : items)
    if (i.run.scene_name() == scene) return i;
  throw std::runtime_error("no scored scene " + scene);
}

TEST(Scorecard, PicksTheBestReferenceAndTheMatrixTolerances) {
  const fs::path root = BEAMIMPACT_SOURCE;
  const VerificationMatrix m = VerificationMatrix::load(root / "verification/matrix.toml");
  const auto fenicsx = score_items(m, "fenicsx", root);
  // Every paper and hard scene, and the six extra scenes with an exact answer (rigid rod, offset
  // gap, rod on a wall, bouncing bar, two rods with a second contact period, S2 rotated by 37
  // degrees).
  std::size_t shipped = 0;
  for (const char* folder : {"paper", "hard"})
    for (const auto& e : fs::directory_iterator(root / "verification/scenes" / folder))
      shipped += e.path().extension() == ".toml";
  EXPECT_EQ(fenicsx.size(), shipped + 6);
  // S1 has an exact solution and a FEniCSx case of its own: its mesh preset and its gates.
  const ScoreItem& s1 = item(fenicsx, "s1_central");
  EXPECT_EQ(s1.reference_kind, "exact");
  EXPECT_EQ(s1.run.mesh, "coarse");
  EXPECT_FALSE(s1.gates.empty());
  // S4-45 has no exact solution: IDA, with the paper integrator's tolerances and no settings of its.
  const auto standin = score_items(m, "standin", root);
  const ScoreItem& s4 = item(standin, "s4_oblique_45");
  EXPECT_EQ(s4.reference_kind, "ida");
  EXPECT_EQ(s4.run.method, "standin");
  EXPECT_FALSE(s4.run.dt);
  EXPECT_FALSE(s4.gates.empty());
  // A hard scene the matrix has no case for: IDA at the scene's settings, errors without a verdict
  // (IDA's own scorecard shows how far those settings are from converged).
  const ScoreItem& grazing = item(standin, "grazing_1deg");
  EXPECT_EQ(grazing.reference.method, "ida");
  EXPECT_TRUE(grazing.reference.set.empty());
  EXPECT_TRUE(grazing.gates.empty());
  EXPECT_TRUE(grazing.source.empty());
  EXPECT_EQ(item(standin, "rigid_rod_oblique").reference_kind, "exact");
}

TEST(Scorecard, IdaIsNeverItsOwnReference) {
  const fs::path root = BEAMIMPACT_SOURCE;
  const VerificationMatrix m = VerificationMatrix::load(root / "verification/matrix.toml");
  // Against itself every error would be 0 and every gate a pass that means nothing: IDA is scored
  // against a converged IDA run (or exact), whatever case of the matrix gives the tolerances.
  const std::vector<std::string> converged = {"ida.rtol=1e-10", "ida.atol=1e-13", "ida.kn_factor=1e4"};
  for (const ScoreItem& it : score_items(m, "ida", root)) {
    EXPECT_NE(it.run.key(), it.reference.key()) << it.run.label();
    if (it.reference_kind == "ida")
      for (const std::string& c : converged)
        EXPECT_NE(std::find(it.reference.set.begin(), it.reference.set.end(), c), it.reference.set.end())
            << it.reference.label();
  }
  // A case's own reference settings stay (S4-60: IDA's converged friction regularisation).
  const auto ida = score_items(m, "ida", root);
  const auto& s60 = item(ida, "s4_oblique_60").reference.set;
  EXPECT_NE(std::find(s60.begin(), s60.end(), "ida.friction_velocity=1e-5"), s60.end());
}

}  // namespace
}  // namespace beamimpact::verification
