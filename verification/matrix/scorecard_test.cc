// The scorecard's choice of reference and tolerances, read from the shipped matrix: exact where
// the matrix compares a scene with it, else IDA converged beyond its defaults; the method's own
// case first, then the paper's.
#include <verification/matrix/scorecard.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>

#include <solver/util/InputError.hpp>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;

/// What converged_ida adds to an IDA reference that sets none of these keys.
const std::vector<std::string> kConverged = {"ida.rtol=1e-10", "ida.atol=1e-13", "ida.friction_velocity=1e-5",
                                             "ida.kn_factor=1e4"};

/// `set` with each converged setting whose key it does not set appended, in kConverged's order.
std::vector<std::string> with_converged(std::vector<std::string> set, bool stiffen = true) {
  const auto key = [](const std::string& s) { return s.substr(0, s.find('=')); };
  const std::vector<std::string> own = set;
  for (const std::string& c : kConverged) {
    if (!stiffen && key(c) == "ida.kn_factor") continue;
    if (std::none_of(own.begin(), own.end(), [&](const std::string& o) { return key(o) == key(c); }))
      set.push_back(c);
  }
  return set;
}

bool has(const std::vector<std::string>& set, const std::string& s) {
  return std::find(set.begin(), set.end(), s) != set.end();
}

const ScoreItem& item(const std::vector<ScoreItem>& items, const std::string& scene) {
  for (const auto& i : items)
    if (i.run.scene_name() == scene) return i;
  throw std::runtime_error("no scored scene " + scene);
}

TEST(Scorecard, PicksTheBestReferenceAndTheMatrixTolerances) {
  const fs::path root = BEAMIMPACT_SOURCE;
  const VerificationMatrix m = VerificationMatrix::load(root / "verification/matrix.toml");
  const auto fenicsx = score_items(m, "fenicsx", root);
  // Every paper and hard scene, and the eight extra scenes with an exact answer (rigid rod, offset
  // gap, rod on a wall, bouncing bar, two rods with a second contact period, S2 rotated by 37
  // degrees, the Hertz ball on a beam, the stocky S2 with Timoshenko beams).
  std::size_t shipped = 0;
  for (const char* folder : {"paper", "hard"})
    for (const auto& e : fs::directory_iterator(root / "verification/scenes" / folder))
      shipped += e.path().extension() == ".toml";
  EXPECT_EQ(fenicsx.size(), shipped + 8);
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
  // A hard scene the matrix has no case for: converged IDA at the scene's settings, errors without
  // a verdict.
  const ScoreItem& grazing = item(standin, "grazing_1deg");
  EXPECT_EQ(grazing.reference.method, "ida");
  EXPECT_EQ(grazing.reference.set, kConverged);
  EXPECT_TRUE(grazing.gates.empty());
  EXPECT_TRUE(grazing.source.empty());
  EXPECT_EQ(item(standin, "rigid_rod_oblique").reference_kind, "exact");
}

TEST(Scorecard, IdaIsNeverItsOwnReference) {
  const fs::path root = BEAMIMPACT_SOURCE;
  const VerificationMatrix m = VerificationMatrix::load(root / "verification/matrix.toml");
  // Against itself every error would be 0 and every gate a pass that means nothing: IDA is scored
  // against a converged IDA run (or exact), whatever case of the matrix gives the tolerances.
  for (const ScoreItem& it : score_items(m, "ida", root)) {
    EXPECT_NE(it.run.key(), it.reference.key()) << it.run.label();
    if (it.reference_kind == "ida") {
      for (const std::string& c : kConverged) EXPECT_TRUE(has(it.reference.set, c)) << it.reference.label();
    }
  }
  // A case's own reference settings stay (S4-60: IDA's converged friction regularisation).
  const auto ida = score_items(m, "ida", root);
  const auto& s60 = item(ida, "s4_oblique_60").reference.set;
  EXPECT_TRUE(has(s60, "ida.friction_velocity=1e-5"));
  // With matrix references IDA would meet its own runs: refused, naming the option.
  try {
    score_items(m, "ida", root, ScoreOptions{{"paper"}, "matrix"});
    ADD_FAILURE() << "IDA scored against matrix references";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "--references");
  }
}

TEST(Scorecard, IdaReferencesAreConvergedUnlessMatrixReferencesAreAsked) {
  const fs::path root = BEAMIMPACT_SOURCE;
  const VerificationMatrix m = VerificationMatrix::load(root / "verification/matrix.toml");
  // Each IDA reference of the paper's scorecard is an IDA reference the matrix writes for that
  // scene (or IDA at the scene's settings where it has none), with the three converged settings
  // added; --references matrix takes it as written.
  const auto converged = score_items(m, "paper", root, ScoreOptions{{"paper", "hard"}, "converged"});
  const auto written = score_items(m, "paper", root, ScoreOptions{{"paper", "hard"}, "matrix"});
  ASSERT_EQ(converged.size(), written.size());
  int ida = 0;
  for (std::size_t i = 0; i < converged.size(); ++i) {
    if (written[i].reference.method != "ida") continue;
    ++ida;
    EXPECT_EQ(converged[i].reference.set, with_converged(written[i].reference.set))
        << converged[i].run.label();
    // Its check: the same converged run at the case's penalty (no case here sets one).
    ASSERT_TRUE(converged[i].reference_check) << converged[i].run.label();
    EXPECT_EQ(converged[i].reference_check->set, with_converged(written[i].reference.set, false));
    EXPECT_FALSE(written[i].reference_check) << "matrix references have no check";
    const bool in_matrix = std::any_of(m.cases.begin(), m.cases.end(), [&](const Case& c) {
      return fs::absolute(c.run.scene).lexically_normal() == written[i].run.scene &&
             c.reference.method == "ida" && c.reference.set == written[i].reference.set;
    });
    EXPECT_TRUE(in_matrix || (written[i].source.empty() && written[i].reference.set.empty()))
        << written[i].run.label();
  }
  EXPECT_GE(ida, 10);  // S3 at 10 elements, S4 x3 and the hard scenes without exact answers
  // An exact reference is taken as exact: no check.
  for (const ScoreItem& it : converged) {
    if (it.reference_kind == "exact") {
      EXPECT_FALSE(it.reference_check) << it.run.label();
    }
  }
}

TEST(Scorecard, AVerdictTheReferenceSpreadCouldReverseIsReferenceUncertain) {
  // The true error lies within error +- spread when the reference's own error is within its
  // spread: pass needs error + spread <= tol, fail needs error - spread > tol.
  EXPECT_EQ(verdict(0.05, 0.08, std::nullopt), "pass");  // no spread: the reference taken as exact
  EXPECT_EQ(verdict(0.09, 0.08, std::nullopt), "fail");
  EXPECT_EQ(verdict(0.05, 0.08, 0.02), "pass");                 // 0.07 <= 0.08
  EXPECT_EQ(verdict(0.07, 0.08, 0.02), "reference uncertain");  // 0.09 > 0.08 >= 0.05
  EXPECT_EQ(verdict(0.13, 0.08, 0.10), "reference uncertain");  // 0.03 <= 0.08 < 0.23
  EXPECT_EQ(verdict(0.13, 0.08, 0.01), "fail");                 // 0.12 > 0.08
  EXPECT_EQ(verdict(0.08, 0.08, 0.0), "pass");                  // the tolerance is inclusive
  EXPECT_EQ(verdict(std::nan(""), 0.08, 0.01), "fail");         // no number is not a pass
  EXPECT_EQ(verdict(0.01, 0.08, std::numeric_limits<double>::infinity()), "reference uncertain");
}

TEST(Scorecard, SetsSelectTheScenesInOrderAndBadOptionsNameTheOption) {
  const fs::path root = BEAMIMPACT_SOURCE;
  const VerificationMatrix m = VerificationMatrix::load(root / "verification/matrix.toml");
  std::size_t paper_files = 0;
  for (const auto& e : fs::directory_iterator(root / "verification/scenes/paper"))
    paper_files += e.path().extension() == ".toml";
  const auto paper = score_items(m, "paper", root, ScoreOptions{{"paper"}, "converged"});
  EXPECT_EQ(paper.size(), paper_files);
  for (const ScoreItem& it : paper) EXPECT_EQ(it.run.scene.parent_path().filename(), "paper");
  // The exact set: the eight extra scenes with an exact answer, none of the paper's (S1 has one too).
  const auto exact = score_items(m, "paper", root, ScoreOptions{{"exact"}, "converged"});
  EXPECT_EQ(exact.size(), 8u);
  for (const ScoreItem& it : exact) EXPECT_EQ(it.reference_kind, "exact") << it.run.label();
  const auto key_of = [&](const ScoreOptions& o) {
    try {
      score_items(m, "paper", root, o);
    } catch (const InputError& e) {
      return e.key();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(key_of(ScoreOptions{{"papers"}, "converged"}), "--sets");
  EXPECT_EQ(key_of(ScoreOptions{{"paper", "paper"}, "converged"}), "--sets");
  EXPECT_EQ(key_of(ScoreOptions{{}, "converged"}), "--sets");
  EXPECT_EQ(key_of(ScoreOptions{{"hard"}, "tight"}), "--references");
}

}  // namespace
}  // namespace beamimpact::verification
