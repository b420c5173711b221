// The scorecard: one benchmark card per scene whoever runs it, the run compared with its
// reference the right way round, ladders whose limit a bias cannot hide in, the round-off slack of
// a tolerance, the overall verdict and exit codes, and the accuracy ratchet.
#include <verification/matrix/scorecard.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <solver/util/InputError.hpp>
#include <verification/compare/StoredRun.hpp>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;
using Status = jobs::JobOutcome::Status;

const fs::path kRoot = BEAMIMPACT_SOURCE;

std::vector<BenchmarkCard> shipped_cards() { return load_cards(kRoot / "verification/cards.toml", kRoot); }

const ScoreItem& item(const std::vector<ScoreItem>& items, const std::string& scene) {
  for (const auto& i : items)
    if (i.run.scene_name() == scene) return i;
  throw std::runtime_error("no scored scene " + scene);
}

TEST(Scorecard, EveryBenchmarkSceneHasOneCardAndEveryQuantityATolerance) {
  const auto cards = shipped_cards();
  std::size_t shipped = 0;
  for (const char* folder : {"paper", "hard"})
    for (const auto& e : fs::directory_iterator(kRoot / "verification/scenes" / folder)) {
      if (e.path().extension() != ".toml") continue;
      ++shipped;
      const fs::path scene = fs::absolute(e.path()).lexically_normal();
      EXPECT_EQ(
          std::count_if(cards.begin(), cards.end(), [&](const BenchmarkCard& c) { return c.scene == scene; }),
          1)
          << scene;
    }
  // The eight other scenes with an exact answer: rigid rod, offset gap, rod on a wall, bouncing
  // bar, two rods with a second contact period, S2 rotated by 37 degrees, the Hertz ball on a beam,
  // the stocky S2 with Timoshenko beams.
  EXPECT_EQ(cards.size(), shipped + 8);
  for (const BenchmarkCard& c : cards) {
    ASSERT_FALSE(c.quantities.empty()) << c.scene;
    for (const Gate& g : c.quantities) {
      EXPECT_TRUE(g.tol.has_value()) << c.scene << " " << g.metric;
      // A reason says where its number comes from: a matrix row, or a derivation.
      EXPECT_TRUE(g.why.rfind("matrix row '", 0) == 0 || g.why.rfind("derived", 0) == 0) << g.why;
    }
    if (c.set == "exact") EXPECT_EQ(c.reference.method, "exact") << c.scene;
  }
}

TEST(Scorecard, TheSameCardHoldsForEveryMethodWhateverItsName) {
  const auto cards = shipped_cards();
  const Method* example = find_method("example");
  ASSERT_NE(example, nullptr);
  Method copy = *example;  // an unchanged copy of the example under another name
  copy.name = "example_copy";
  const auto a = score_items(cards, *example), b = score_items(cards, copy);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].reference.key(), b[i].reference.key());
    EXPECT_EQ(a[i].ladder.kind, b[i].ladder.kind);
    ASSERT_EQ(a[i].gates.size(), b[i].gates.size());
    for (std::size_t k = 0; k < a[i].gates.size(); ++k) {
      EXPECT_EQ(a[i].gates[k].metric, b[i].gates[k].metric);
      EXPECT_EQ(a[i].gates[k].tol, b[i].gates[k].tol);
    }
  }
  // The example has a case of its own in the matrix on S1 (impulse 4 %, impacts): the card holds it
  // to the paper integrator's row like every method, and runs it at the scene's own settings.
  const Method* paper = find_method("paper");
  const ScoreItem& s1 = item(a, "s1_central");
  const auto paper_items = score_items(cards, *paper);
  const ScoreItem& s1_paper = item(paper_items, "s1_central");
  EXPECT_EQ(s1.gates.size(), s1_paper.gates.size());
  EXPECT_EQ(s1.source, "s1_central paper dt=0.01 vs exact");
  EXPECT_FALSE(s1.run.dt);
  EXPECT_TRUE(s1.run.mesh.empty());
}

TEST(Scorecard, LaddersRefineWhatTheMethodAcceptsOnScenesWithAnExactAnswer) {
  const auto cards = shipped_cards();
  const auto paper = score_items(cards, *find_method("paper"));
  // S1 (dt 0.01 s, both accepted): elements x2 and dt / 2 a rung, the first rung the scene itself.
  const LadderPlan& s1 = item(paper, "s1_central").ladder;
  ASSERT_EQ(s1.rungs.size(), 3u);
  EXPECT_EQ(s1.kind, "mesh+dt");
  EXPECT_FALSE(s1.rungs[0].dt);
  EXPECT_EQ(s1.rungs[2].mesh, "4");
  EXPECT_DOUBLE_EQ(*s1.rungs[2].dt, 0.0025);
  // A scene with an automatic step: the mesh alone (the step follows it).
  EXPECT_EQ(item(paper, "ball_on_beam").ladder.kind, "mesh");
  // No exact answer: no ladder.
  EXPECT_TRUE(item(paper, "s4_oblique_45").ladder.rungs.empty());
  // FEniCSx takes neither a dt nor a mesh factor: single runs, said so.
  const auto fenicsx = score_items(cards, *find_method("fenicsx"));
  EXPECT_TRUE(item(fenicsx, "s1_central").ladder.rungs.empty());
  EXPECT_NE(item(fenicsx, "s1_central").ladder.why.find("neither"), std::string::npos);
  ScoreOptions single;
  single.ladder = false;
  const auto single_items = score_items(cards, *find_method("paper"), single);
  EXPECT_TRUE(item(single_items, "s1_central").ladder.rungs.empty());
}

TEST(Scorecard, IdaIsNeverItsOwnReference) {
  for (const ScoreItem& it : score_items(shipped_cards(), *find_method("ida"))) {
    EXPECT_NE(it.run.key(), it.reference.key()) << it.run.label();
  }
  try {
    ScoreOptions o;
    o.references = "matrix";
    score_items(shipped_cards(), *find_method("ida"), o);
    ADD_FAILURE() << "IDA scored against matrix references";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "--references");
  }
}

/// A cards file holding `text`, and the InputError's key it gives.
std::string card_error(const std::string& text) {
  const fs::path f = fs::temp_directory_path() / fmt::format("beamimpact_cards_{}.toml", ::getpid());
  std::ofstream(f) << text;
  try {
    load_cards(f, kRoot);
  } catch (const InputError& e) {
    fs::remove(f);
    return e.key();
  }
  fs::remove(f);
  return "accepted";
}

// The reference of every card and its settings are those the committed scorecards were made with
// (docs/protocol.md: IDA converged to rtol 1e-10, atol 1e-13, friction regularised at 1e-5 m/s,
// penalty 1e4 EA/le, checked at the card's penalty; an exact reference as it is, with a ladder),
// now read from the registry's entries (Method::as_reference) instead of rules on names. The
// order of the settings is part of the reference's key, hence of the reference cache.
TEST(Scorecard, TheReferenceChoiceAndSettingsAreThoseOfTheCommittedScorecards) {
  const std::vector<std::string> converged = {"ida.rtol=1e-10", "ida.atol=1e-13",
                                              "ida.friction_velocity=1e-5"};
  std::vector<std::string> stiffened = converged;
  stiffened.push_back("ida.kn_factor=1e4");
  const auto cards = shipped_cards();
  const auto items = score_items(cards, *find_method("paper"));
  ASSERT_EQ(items.size(), cards.size());
  std::size_t ida = 0, exact = 0;
  for (const ScoreItem& it : items) {
    EXPECT_EQ(it.reference_kind, it.reference.method) << it.run.label();
    if (it.reference.method == "ida") {
      ++ida;
      EXPECT_EQ(it.reference.set, stiffened) << it.run.label();
      ASSERT_TRUE(it.reference_check) << it.run.label();
      EXPECT_EQ(it.reference_check->set, converged) << it.run.label();
      EXPECT_TRUE(it.ladder.rungs.empty()) << it.run.label();
    } else {
      ++exact;
      EXPECT_EQ(it.reference.method, "exact") << it.run.label();
      EXPECT_TRUE(it.reference.set.empty()) << it.run.label();
      EXPECT_FALSE(it.reference_check) << it.run.label();
      EXPECT_FALSE(it.ladder.rungs.empty()) << it.run.label();  // the paper takes dt and mesh: a ladder
    }
  }
  EXPECT_EQ(ida, 15u);    // the cards naming ida (verification/cards.toml)
  EXPECT_EQ(exact, 11u);  // and exact
  // A card's own settings stay: its own tolerance, its own penalty (then no stiffer run and no check).
  BenchmarkCard own = cards.front();
  own.set = "paper";
  own.reference.method = "ida";
  own.reference.set = {"ida.rtol=1e-6", "ida.kn=1e5"};
  const auto mine = score_items({own}, *find_method("paper"));
  ASSERT_EQ(mine.size(), 1u);
  EXPECT_EQ(mine[0].reference.set, (std::vector<std::string>{"ida.rtol=1e-6", "ida.kn=1e5", "ida.atol=1e-13",
                                                             "ida.friction_velocity=1e-5"}));
  EXPECT_FALSE(mine[0].reference_check);
  // With matrix references the card's settings as written.
  ScoreOptions matrix;
  matrix.references = "matrix";
  for (const ScoreItem& it : score_items(cards, *find_method("paper"), matrix)) {
    EXPECT_TRUE(it.reference.set.empty()) << it.run.label();
    EXPECT_FALSE(it.reference_check) << it.run.label();
  }
}

TEST(Scorecard, ACardsReferenceIsARankedReferenceMethod) {
  const std::string card =
      "[[card]]\nscene = \"verification/scenes/paper/s1_central.toml\"\nset = \"paper\"\nsource = \"\"\n"
      "quantities = [{ metric = \"impulse\", tol = 0.04, why = \"derived: a bound\" }]\n";
  EXPECT_EQ(card_error(card + "reference = { method = \"exact\" }\n"), "accepted");
  EXPECT_EQ(card_error(card + "reference = { method = \"ida\" }\n"), "accepted");
  // The paper's integrator has no reference rank; "nothing" is no method.
  EXPECT_EQ(card_error(card + "reference = { method = \"paper\" }\n"), "card[0].reference.method");
  EXPECT_EQ(card_error(card + "reference = { method = \"nothing\" }\n"), "card[0].reference.method");
}

TEST(Scorecard, ABadCardIsInputErrorNamingTheKey) {
  const std::string head =
      "[[card]]\nscene = \"verification/scenes/paper/s1_central.toml\"\nset = \"paper\"\n"
      "reference = { method = \"exact\" }\nsource = \"\"\n";
  const std::string good =
      "quantities = [{ metric = \"impulse\", tol = 0.04, why = \"derived: a bound\" }]\n";
  EXPECT_EQ(card_error(head + good), "accepted");
  EXPECT_EQ(card_error(head + "quantities = [{ metric = \"impulse\", why = \"derived: a bound\" }]\n"),
            "card[0].quantities[0].tol");
  EXPECT_EQ(
      card_error(head + "quantities = [{ metric = \"impluse\", tol = 1, why = \"derived: a bound\" }]\n"),
      "card[0].quantities[0].metric");
  EXPECT_EQ(card_error(head + good + head + good), "card[1].scene");  // one card per scene
  EXPECT_EQ(card_error(head + good + "tier = \"quick\"\n"), "card[0].tier");
  EXPECT_EQ(card_error("[[card]]\nscene = \"nowhere.toml\"\n"), "card[0].scene");
}

TEST(Scorecard, ASettledValueIsOneOfTheCardsScalarQuantities) {
  const std::string card =
      "[[card]]\nscene = \"verification/scenes/paper/s1_central.toml\"\nset = \"paper\"\n"
      "reference = { method = \"ida\" }\nsource = \"\"\n"
      "quantities = [{ metric = \"impulse\", tol = 0.04, why = \"derived: a bound\" },"
      " { metric = \"R.rel_l2\", tol = 0.1, why = \"derived: a bound\" }]\n";
  const auto settled = [&](const std::string& entries) {
    return card_error(card + "settled = [" + entries + "]\n");
  };
  const std::string good =
      "{ metric = \"impulse\", value = 2.5, uncertainty = 0.1, why = \"a settled ladder\" }";
  EXPECT_EQ(settled(good), "accepted");
  EXPECT_EQ(settled(good + ", " + good), "card[0].settled[1].metric");  // one value per quantity
  // A quantity the card does not gate, one with no scalar value of the run's own.
  EXPECT_EQ(settled("{ metric = \"peak_R\", value = 2.5, uncertainty = 0.1, why = \"a settled ladder\" }"),
            "card[0].settled[0].metric");
  EXPECT_EQ(settled("{ metric = \"R.rel_l2\", value = 2.5, uncertainty = 0.1, why = \"a settled ladder\" }"),
            "card[0].settled[0].metric");
  EXPECT_EQ(settled("{ metric = \"impulse\", value = 2.5, uncertainty = -0.1, why = \"a settled ladder\" }"),
            "card[0].settled[0].uncertainty");
  EXPECT_EQ(settled("{ metric = \"impulse\", value = 0, uncertainty = 0.1, why = \"a settled ladder\" }"),
            "card[0].settled[0].value");
  EXPECT_EQ(settled("{ metric = \"impulse\", value = 2.5, uncertainty = 0.1 }"), "card[0].settled[0].why");
}

TEST(Scorecard, ToleranceComparisonsCarryFourUlpsOfSlack) {
  // A contact_end of 2.55 s against an exact 2.5 s: |a - b| carries round-off of a few ulps of
  // 2.55 (4.4e-16 each), so 0.05 + 2.7e-16 is 0.05 to the precision the error has.
  EXPECT_EQ(verdict(0.05 + 2.7e-16, 0.05, std::nullopt, 2.55), QuantityStatus::kPass);
  EXPECT_EQ(verdict(0.05 + 1e-12, 0.05, std::nullopt, 2.55),
            QuantityStatus::kFail);                                           // beyond round-off: a real miss
  EXPECT_EQ(verdict(0.05, 0.08, 0.02), QuantityStatus::kPass);                // 0.07 <= 0.08
  EXPECT_EQ(verdict(0.07, 0.08, 0.02), QuantityStatus::kReferenceUncertain);  // 0.09 > 0.08 >= 0.05
  EXPECT_EQ(verdict(0.13, 0.08, 0.01), QuantityStatus::kFail);                // 0.12 > 0.08
  EXPECT_EQ(verdict(std::nan(""), 0.08, 0.01), QuantityStatus::kFail);        // no number is not a pass
  EXPECT_EQ(verdict(1.0, 0.0, std::nullopt), QuantityStatus::kFail);          // a count off by one
}

/// A run in memory: one contact whose force is `force` N from t = 0.2 to 0.6 s (impulse 0.4 x force).
jobs::JobOutcome memory_run(const jobs::JobSpec& spec, double force) {
  std::map<std::string, std::vector<double>> c;
  for (int i = 0; i <= 100; ++i) {
    const double t = i * 0.01;
    c["t"].push_back(t);
    c["R"].push_back(t > 0.2 - 1e-9 && t < 0.6 + 1e-9 ? force : 0.0);
  }
  jobs::JobOutcome o{spec, {}, Status::kOk, "", 0.1, 0.1, 100, 0.01, nullptr};
  o.run =
      std::make_shared<const StoredRun>(StoredRun::from_columns(c, nlohmann::json::object(), spec.label()));
  return o;
}

/// One scene scored in memory: `forces` the method's rung forces (one: no ladder), reference 1 N.
/// `held` keeps the scored item (the row points to it).
ScoreRow score_memory(const std::vector<double>& forces, double tol, std::vector<ScoreItem>& held) {
  ScoreItem it;
  it.run = jobs::JobSpec{kRoot / "verification/scenes/paper/s1_central.toml", "m", std::nullopt, "", {}};
  it.reference = it.run;
  it.reference.method = "exact";
  it.reference_kind = "exact";
  it.gates = {Gate{"impulse", tol, std::nullopt, "derived: a test bound", std::nullopt}};
  std::map<std::string, jobs::JobOutcome> runs;
  runs.emplace(it.reference.key(), memory_run(it.reference, 1.0));
  for (std::size_t k = 0; k < forces.size(); ++k) {
    jobs::JobSpec s = it.run;
    if (k > 0) s.mesh = std::to_string(1 << k);
    if (forces.size() > 1) it.ladder.rungs.push_back(s);
    runs.emplace(s.key(), memory_run(s, forces[k]));
  }
  held = {it};
  return score_rows(held, runs).front();
}

TEST(Scorecard, TheRunIsComparedWithItsReferenceNotTheOtherWayRound) {
  // Run impulse 0.5 N s, reference 0.4 N s: the relative error is |0.5 - 0.4| / 0.4 = 0.25; swapped
  // it would be 0.1 / 0.5 = 0.2.
  std::vector<ScoreItem> it;
  const ScoreRow row = score_memory({1.25}, 0.3, it);
  ASSERT_TRUE(row.quantities.front().error);
  EXPECT_NEAR(*row.quantities.front().error, 0.25, 1e-12);
  EXPECT_EQ(row.quantities.front().judged, "single run");
  EXPECT_EQ(row.quantities.front().status, QuantityStatus::kPass);
}

// The S4 cards' settled impulses are the committed ones (reports/s4/corotational.json, made by
// reports/s4_corotational.py from reports/s4/settled.json), rounded to 0.05 N s, the uncertainty
// rounded up by at most 0.1 N s; score carries them to its items.
TEST(Scorecard, TheS4CardsHoldTheCommittedSettledImpulses) {
  std::ifstream in(kRoot / "reports/s4/corotational.json");
  ASSERT_TRUE(in) << "reports/s4/corotational.json";
  const nlohmann::json doc = nlohmann::json::parse(in);
  const auto items = score_items(shipped_cards(), *find_method("paper"));
  for (const char* angle : {"45", "60", "90"}) {
    const ScoreItem& it = item(items, std::string("s4_oblique_") + angle);
    ASSERT_EQ(it.settled.size(), 1u) << angle;
    EXPECT_EQ(it.settled[0].metric, "impulse");
    const nlohmann::json& s = doc.at("angles").at(angle).at("settled_corotational").at("impulse_normal");
    EXPECT_NEAR(it.settled[0].value, s.at("value").get<double>(), 0.05) << angle;
    EXPECT_GE(it.settled[0].uncertainty, s.at("uncertainty").get<double>()) << angle;
    EXPECT_LE(it.settled[0].uncertainty, s.at("uncertainty").get<double>() + 0.1) << angle;
  }
}

TEST(Scorecard, ASettledValueTakesThePlaceOfTheReferenceRun) {
  // The memory runs' impulse is 0.41 x force (0.4 s of force and the rows' two half-step ramps):
  // reference run 0.41 N s, run 0.615 N s, settled value 0.5 +- 0.01 N s. Judged against the
  // settled value the error is |0.615 - 0.5| / 0.5 = 0.23 with uncertainty 0.01 / 0.5 = 0.02
  // (against the reference run it would be 0.5; the run and the settled value swapped,
  // 0.115 / 0.615 = 0.187 and 0.0163).
  std::vector<ScoreItem> held;
  score_memory({1.5}, 0.25, held);
  held[0].settled = {SettledValue{"impulse", 0.5, 0.01, "a settled ladder"}};
  std::map<std::string, jobs::JobOutcome> runs;
  runs.emplace(held[0].reference.key(), memory_run(held[0].reference, 1.0));
  runs.emplace(held[0].run.key(), memory_run(held[0].run, 1.5));
  const auto judged = [&](double tol) {
    held[0].gates[0].tol = tol;
    return score_rows(held, runs).front().quantities.front();
  };
  const ScoreQuantity q = judged(0.26);
  ASSERT_TRUE(q.error && q.uncertainty && q.exact);
  EXPECT_NEAR(*q.error, 0.23, 1e-12);
  EXPECT_NEAR(*q.uncertainty, 0.02, 1e-12);
  EXPECT_EQ(*q.exact, 0.5);
  EXPECT_EQ(q.status, QuantityStatus::kPass);  // 0.25 <= 0.26
  EXPECT_EQ(judged(0.24).status,
            QuantityStatus::kReferenceUncertain);  // 0.21 <= 0.24 < 0.25: the uncertainty decides
  EXPECT_EQ(judged(0.20).status,
            QuantityStatus::kFail);  // 0.21 > 0.20 (swapped: 0.171 <= 0.20 < 0.203, uncertain)
}

TEST(Scorecard, ABiasCannotHideInTheDiscretisationError) {
  // Rungs with a first-order discretisation error of -3 %, -1.5 %, -0.75 % (mesh x2 a rung): a
  // single run of the coarsest has error 3 % under a 4 % tolerance. Richardson removes the h term
  // exactly: the limit is the method's own answer.
  const auto rungs = [](double bias) {
    return std::vector<double>{bias * 0.97, bias * 0.985, bias * 0.9925};
  };
  std::vector<ScoreItem> honest_item, biased_item, slight_item;
  const ScoreQuantity honest = score_memory(rungs(1.0), 0.04, honest_item).quantities.front();
  EXPECT_EQ(honest.judged, "limit");
  EXPECT_EQ(honest.status, QuantityStatus::kPass) << honest.note;
  ASSERT_TRUE(honest.ladder && honest.ladder->order);
  EXPECT_NEAR(*honest.ladder->order, 1.0, 1e-6);  // e ~ h: order 1
  EXPECT_NEAR(*honest.error, 0.0, 1e-9);
  // Force x 1.03: the coarse run's error is 0.1 % (the bias cancels the mesh error), but the limit
  // is 3 % off with an uncertainty near 0: fail.
  const ScoreQuantity biased = score_memory(rungs(1.03), 0.04, biased_item).quantities.front();
  EXPECT_NEAR(std::abs(1.03 * 0.97 - 1.0), 0.0009, 1e-12);
  EXPECT_EQ(biased.status, QuantityStatus::kFail) << biased.note;
  EXPECT_NEAR(*biased.error, 0.03, 1e-9);
  // Force x 1.01: 1 % off, beyond 1.25 U + tol / 10 = 0.4 %: fail.
  EXPECT_EQ(score_memory(rungs(1.01), 0.04, slight_item).quantities.front().status, QuantityStatus::kFail);
}

TEST(Scorecard, AMethodThatDoesNotConvergeGetsThatVerdict) {
  // Differences that grow (order < 0): no asymptotic range, no limit.
  std::vector<ScoreItem> a, b;
  const ScoreQuantity q = score_memory({0.99, 0.98, 0.95}, 0.04, a).quantities.front();
  EXPECT_EQ(q.status, QuantityStatus::kNotConverged) << q.note;
  // Order 0.4 (differences shrinking by 2^0.4 a rung): below 0.5, not converged.
  const double d = 0.01, s = std::pow(2.0, -0.4);
  EXPECT_EQ(score_memory({1 - d - d * s, 1 - d * s, 1.0}, 0.04, b).quantities.front().status,
            QuantityStatus::kNotConverged);
  // The Richardson arithmetic is the matrix's: its limit and order for these rungs.
  const LadderResult r = ladder_limit({0.97, 0.985, 0.9925});
  const auto matrix = richardson_limit(0.97, 0.985, 0.9925, 2.0);
  ASSERT_TRUE(r.limit && matrix);
  EXPECT_DOUBLE_EQ(*r.limit, matrix->first);
}

TEST(Scorecard, ARefusedSceneIsNotApplicableWithNoReferenceRun) {
  ScoreItem it;
  it.run = jobs::JobSpec{kRoot / "verification/scenes/paper/s1_central.toml", "m", std::nullopt, "", {}};
  it.reference = jobs::JobSpec{it.run.scene, "ida", std::nullopt, "", {}};
  it.gates = {Gate{"impulse", 0.04, std::nullopt, "derived: a test bound", std::nullopt}};
  std::map<std::string, jobs::JobOutcome> runs;  // the reference was never run
  runs.emplace(it.run.key(),
               jobs::JobOutcome{it.run, {}, Status::kNotApplicable, "no friction", 0, 0, 0, 0, nullptr});
  const std::vector<ScoreItem> held = {it};
  const auto rows = score_rows(held, runs);
  EXPECT_EQ(rows.front().quantities.front().status, QuantityStatus::kNotApplicable);
  const ScoreVerdict v = score_verdict("m", rows);
  EXPECT_EQ(v.exit_code, 0) << v.line;  // a refusal is not a failure, and the line says how many
  EXPECT_NE(v.line.find("1 not applicable"), std::string::npos) << v.line;
}

TEST(Scorecard, TheVerdictFailsOnAnyQuantityThatDidNotPass) {
  std::vector<ScoreItem> a, b;
  const std::vector<ScoreRow> pass = {score_memory({1.01}, 0.04, a)};
  EXPECT_EQ(score_verdict("m", pass).exit_code, 0);
  const std::vector<ScoreRow> fail = {score_memory({1.05}, 0.04, b)};
  const ScoreVerdict v = score_verdict("m", fail);
  EXPECT_EQ(v.exit_code, 1);
  EXPECT_EQ(v.line.rfind("score m: FAILED", 0), 0u) << v.line;
}

TEST(Scorecard, EachStatusHasOneWordInTheJsonAndTheReaderTellsFailFromFailed) {
  // The words of scorecard.json are a public format (docs/protocol.md, "Quantity statuses"): the
  // seven words as the format writes them, each read back to its status.
  const std::vector<std::string> words = {"pass",   "fail",    "not converged", "reference uncertain",
                                          "failed", "skipped", "not applicable"};
  ASSERT_EQ(quantity_statuses().size(), words.size());
  for (std::size_t i = 0; i < words.size(); ++i) {
    EXPECT_EQ(to_string(quantity_statuses()[i]), words[i]);
    EXPECT_EQ(parse_quantity_status(words[i], "f", "k"), quantity_statuses()[i]) << words[i];
  }
  try {
    parse_quantity_status("passed", "scorecard.json", "scenes[0].quantities[0].status");
    ADD_FAILURE() << "an unknown status word accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "scenes[0].quantities[0].status");
    EXPECT_NE(std::string(e.what()).find("'not applicable'"), std::string::npos) << e.what();
  }
  // A reader is not shown "fail" beside "failed": a judged miss and a run that did not finish.
  EXPECT_EQ(std::string(describe(QuantityStatus::kFail)), "fail (outside tolerance)");
  EXPECT_EQ(std::string(describe(QuantityStatus::kFailed)), "run failed");
  // The verdict passes on pass and not applicable only.
  for (QuantityStatus q : quantity_statuses())
    EXPECT_EQ(passes(q), q == QuantityStatus::kPass || q == QuantityStatus::kNotApplicable) << to_string(q);
  // A run outcome: its words, read back; a finished run's record of an earlier version (the
  // status as a number) is read too.
  for (const char* w : {"ok", "failed", "skipped", "not applicable"})
    EXPECT_EQ(to_string(jobs::parse_run_status(w, "f", "status")), std::string(w));
  EXPECT_THROW(jobs::parse_run_status("fine", "f", "status"), InputError);
  jobs::JobOutcome o;
  o.status = Status::kNotApplicable;
  nlohmann::json j = jobs::outcome_json(o);
  EXPECT_EQ(j["status"], "not applicable");
  EXPECT_EQ(jobs::outcome_from_json(o.spec, "d", j).status, Status::kNotApplicable);
  j["status"] = 3;  // kNotApplicable's number in records written before the word
  EXPECT_EQ(jobs::outcome_from_json(o.spec, "d", j).status, Status::kNotApplicable);
}

TEST(Scorecard, TheConsoleLineAndTheJsonSayTheStatusesTheirWay) {
  // A run that failed and a quantity outside its tolerance: the verdict line (console and page)
  // says "run failed" and "fail (outside tolerance)"; scorecard.json keeps "failed" and "fail".
  ScoreItem it;
  it.run = jobs::JobSpec{kRoot / "verification/scenes/paper/s1_central.toml", "m", std::nullopt, "", {}};
  it.reference = jobs::JobSpec{it.run.scene, "exact", std::nullopt, "", {}};
  it.gates = {Gate{"impulse", 0.04, std::nullopt, "derived: a test bound", std::nullopt}};
  std::map<std::string, jobs::JobOutcome> runs;
  runs.emplace(it.run.key(), jobs::JobOutcome{it.run, {}, Status::kFailed, "exit 3", 0, 0, 0, 0, nullptr});
  const std::vector<ScoreItem> held = {it};
  std::vector<ScoreItem> b;
  std::vector<ScoreRow> rows = score_rows(held, runs);
  rows.push_back(score_memory({1.05}, 0.04, b));  // 5 % off under 4 %: fail
  ASSERT_EQ(rows[0].quantities.front().status, QuantityStatus::kFailed);
  const ScoreVerdict v = score_verdict("m", rows);
  EXPECT_NE(v.line.find("1 fail (outside tolerance), 1 run failed"), std::string::npos) << v.line;
  ScoreContext ctx;
  ctx.method = "m";
  const nlohmann::json j = scorecard_json(ctx, rows, v);
  EXPECT_EQ(j["scenes"][0]["quantities"][0]["status"], "failed");
  EXPECT_EQ(j["scenes"][1]["quantities"][0]["status"], "fail");
  EXPECT_EQ(j["counts"], (nlohmann::json{{"fail", 1}, {"failed", 1}}));
  EXPECT_EQ(j["statuses"]["failed"], "run failed");
  EXPECT_EQ(j["statuses"]["fail"], "fail (outside tolerance)");
}

/// Writes the scorecard of `rows` as a baseline and returns its path.
fs::path baseline(const std::vector<ScoreRow>& rows, const std::string& method, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("beamimpact_baseline_{}_{}", ::getpid(), name);
  ScoreContext ctx;
  ctx.method = method;
  write_scorecard(dir, ctx, rows, score_verdict(method, rows));
  return dir / "scorecard.json";
}

TEST(Scorecard, TheRatchetCatchesAnErrorThatGrewInsideItsTolerance) {
  std::vector<ScoreItem> a, b, c;
  const std::vector<ScoreRow> before = {score_memory({1.01}, 0.04, a)};  // error 1 %
  const std::vector<ScoreRow> grown = {score_memory({1.02}, 0.04, b)};   // 2 %: still within 4 %
  const std::vector<ScoreRow> same = {score_memory({1.01}, 0.04, c)};
  EXPECT_EQ(score_verdict("m", grown).exit_code, 0);
  const fs::path file = baseline(before, "m", "m");
  const Ratchet r = ratchet(file, "m", ScoreOptions{}, grown);
  EXPECT_EQ(r.grown.size(), 1u);
  EXPECT_TRUE(ratchet(file, "m", ScoreOptions{}, same).grown.empty());
  EXPECT_EQ(ratchet(baseline(grown, "m", "m2"), "m", ScoreOptions{}, before).improved.size(), 1u);
  // A baseline of another method, or of other sets, is bad input.
  try {
    ratchet(file, "other", ScoreOptions{}, same);
    ADD_FAILURE() << "a baseline of another method accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method");
  }
  try {
    ScoreOptions paper_only;
    paper_only.sets = {"paper"};
    ratchet(file, "m", paper_only, same);
    ADD_FAILURE() << "a baseline of other sets accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "sets");
  }
  fs::remove_all(file.parent_path());
}

}  // namespace
}  // namespace beamimpact::verification
