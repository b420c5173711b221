#include <references/ida/solve.hpp>

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include <solver/record/output_files.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::ida {
namespace {

using testing::load_paper_scene;

SimulationResult s1(const std::vector<std::string>& o = {}) {
  return ida::solve(load_paper_scene("s1_central", o));
}

// S1 exact (1D waves, references.md 1): contact [0.5, 2.5] s, impulse rho c A v0/2 x 2L/c = 4 N s.
constexpr double kExactImpulse = 4.0, kExactStart = 0.5, kExactEnd = 2.5;

TEST(RunIda, S1AgreesWithExactWithinTheMeshError) {
  // The lumped 10-element chain is a discrete model: its end nodes close plastically
  // (energy rho A h v0^2/8 = 0.05 J is lost, references.md 4) and its wave front disperses.
  // Mesh error of the model, measured by this reference (h = 1, 0.5, 0.25, 0.125, 0.0625 m):
  // impulse 3.856, 3.915, 3.948, 3.968, 3.980 N s; release 2.549, 2.532, 2.521, 2.513, 2.509 s
  // (both converge like h^0.7). So: 5% on the impulse and 0.06 s on the release at h = 1 m,
  // and the error must fall when the mesh is refined (that it is a mesh error, not a time error).
  const SimulationResult r10 = s1();
  const SimulationResult r20 = s1({"bodies[0].elements=20", "bodies[1].elements=20"});
  const ContactSummary& c10 = r10.contacts.at(0);
  const ContactSummary& c20 = r20.contacts.at(0);
  ASSERT_EQ(c10.intervals.size(), 1u);
  ASSERT_EQ(c20.intervals.size(), 1u);
  // Free flight closes the 0.5 m gap at exactly 0.5 s; the root is located to ~rtol.
  EXPECT_NEAR(c10.intervals[0][0], kExactStart, 1e-9);
  EXPECT_NEAR(c10.impulse_normal, kExactImpulse, 0.05 * kExactImpulse);
  EXPECT_NEAR(c10.intervals[0][1], kExactEnd, 0.06);
  EXPECT_LT(std::abs(c20.impulse_normal - kExactImpulse),
            0.75 * std::abs(c10.impulse_normal - kExactImpulse));
  EXPECT_LT(std::abs(c20.intervals[0][1] - kExactEnd), 0.75 * std::abs(c10.intervals[0][1] - kExactEnd));
  // Momentum: the impulse is what A lost (free bodies, m_A = 4 kg, v0 = 1 m/s), to IDA's tolerance.
  EXPECT_NEAR(c10.impulse_normal, 4.0 * (1.0 - r10.final_velocity.at("A")[0]), 1e-6);
  std::printf("S1 h=1: impulse %.6f N s, interval [%.9f, %.6f] s; h=0.5: %.6f, [%.9f, %.6f]\n",
              c10.impulse_normal, c10.intervals[0][0], c10.intervals[0][1], c20.impulse_normal,
              c20.intervals[0][0], c20.intervals[0][1]);
}

TEST(RunIda, S1ConvergesAsRtolFalls) {
  // Against rtol = 1e-10: the error of impulse and release time must fall with rtol, and at
  // rtol = 1e-8 be below 1e-6 relative (100 x rtol: BDF's global error over ~2e3 steps).
  const SimulationResult ref = s1({"ida.rtol=1e-10"});
  const double I = ref.contacts[0].impulse_normal, te = ref.contacts[0].intervals.back()[1];
  double prev_i = INFINITY, prev_t = INFINITY;
  for (const char* rtol : {"1e-4", "1e-6", "1e-8"}) {
    const SimulationResult r = s1({std::string("ida.rtol=") + rtol});
    const double ei = std::abs(r.contacts[0].impulse_normal - I) / I;
    const double et = std::abs(r.contacts[0].intervals.back()[1] - te);
    std::printf("S1 rtol %s: impulse %.9f (rel. err %.2e), release %.9f (err %.2e s), %ld steps\n", rtol,
                r.contacts[0].impulse_normal, ei, r.contacts[0].intervals.back()[1], et, r.steps);
    EXPECT_LT(ei, prev_i) << rtol;
    EXPECT_LE(et, prev_t) << rtol;
    prev_i = ei;
    prev_t = et;
  }
  EXPECT_LT(prev_i, 1e-6);
  EXPECT_LT(prev_t, 1e-6);
}

TEST(RunIda, S1ConvergesAsPenaltyStiffens) {
  // kn = f x EA/le. The penalty's compliance shifts the contact by O(sqrt(m_red/kn)) (half a
  // penalty period): the differences to the stiffest run must fall by at least 2 per decade.
  const SimulationResult ref = s1({"ida.kn_factor=1e5"});
  const double I = ref.contacts[0].impulse_normal, te = ref.contacts[0].intervals.back()[1];
  double prev_i = INFINITY, prev_t = INFINITY;
  for (const char* f : {"1e2", "1e3", "1e4"}) {
    const SimulationResult r = s1({std::string("ida.kn_factor=") + f});
    const double ei = std::abs(r.contacts[0].impulse_normal - I) / I;
    const double et = std::abs(r.contacts[0].intervals.back()[1] - te);
    std::printf("S1 kn_factor %s: impulse %.9f (diff %.2e), release %.9f (diff %.2e s)\n", f,
                r.contacts[0].impulse_normal, ei, r.contacts[0].intervals.back()[1], et);
    EXPECT_LT(ei, prev_i / 2) << f;
    EXPECT_LT(et, prev_t / 2) << f;
    prev_i = ei;
    prev_t = et;
  }
}

TEST(RunIda, S1ConservesMomentumAndBalancesEnergy) {
  const SimulationResult r = s1();
  // Free bodies: the contact forces are equal and opposite in the residual, and BDF preserves
  // linear invariants: momentum holds to roundoff (1e-10 N s of 4 N s).
  EXPECT_LT(r.momentum_drift_max, 1e-10);
  // Kinetic + strain (incl. penalty spring) + dissipated = initial energy, to ~rtol.
  for (const HistoryRow& row : r.history)
    EXPECT_NEAR(row.kinetic + row.strain + row.dissipated, r.energy_initial, 1e-6) << row.t;
  // The plastic-like closure (restitution 0.01) loses about rho A h v0^2/8 = 0.05 J.
  EXPECT_NEAR(r.history.back().dissipated, 0.05, 0.005);
  EXPECT_EQ(r.method, "ida");
  EXPECT_EQ(r.extra["ida"]["linear_solver"], "klu");  // auto: KLU above 16 unknowns
  EXPECT_GT(r.extra["ida"]["residual_evals"].get<long>(), r.steps);
  EXPECT_EQ(r.history.size(), 401u);  // rows at 0, 0.01, ..., 4 s like the paper's run
}

TEST(RunIda, KluMatchesDenseOnASlidingFrictionalContact) {
  // S4 at 45 deg (linear kinematics) with the striker moved 10.1 mm to the right: it touches
  // at x = 5.0001 m and slides across B's midspan node during contact, so the Jacobian's pattern
  // changes and KLU re-analyses. Both solvers solve the same Newton systems: results agree to
  // far below the tolerance (1e-6 relative).
  const std::vector<std::string> o = {"time.end=0.02", "model.kinematics=linear",
                                      "bodies[0].start=[8.545633905932738, 3.545533905932737]",
                                      "bodies[0].end=[5.0101, 0.01]"};
  auto with = [&](const char* ls) {
    auto v = o;
    v.push_back(std::string("ida.linear_solver=\"") + ls + "\"");
    return ida::solve(load_paper_scene("s4_oblique_45", v));
  };
  const SimulationResult d = with("dense"), k = with("klu");
  EXPECT_EQ(k.extra["ida"]["linear_solver"], "klu");
  EXPECT_GT(k.extra["ida"]["klu_pattern_changes"].get<long>(), 0);
  const double I = d.contacts[0].impulse_normal;
  EXPECT_NEAR(k.contacts[0].impulse_normal, I, 1e-6 * I);
  EXPECT_NEAR(k.contacts[0].impulse_tangential, d.contacts[0].impulse_tangential, 1e-6 * I);
}

TEST(RunIda, FrictionIsBoundedAndDissipative) {
  // S4 at 60 deg: cot(60) = 0.58 > mu = 0.3, the first contact slips (scenes.md).
  const double mu = 0.3;
  const SimulationResult r =
      ida::solve(load_paper_scene("s4_oblique_60", {"time.end=0.03", "model.kinematics=linear"}));
  int closed = 0;
  for (const HistoryRow& row : r.history) {
    const ContactSample& c = row.contacts[0];
    // |tau| <= mu R exactly (the regularised law stays inside the cone); friction power
    // tau * slip velocity <= 0 (B lies along x: the slip velocity is va_x - vb_x).
    EXPECT_LE(std::abs(c.tau), mu * c.R * (1 + 1e-12)) << row.t;
    EXPECT_LE(c.tau * (c.va[0] - c.vb[0]), 1e-12) << row.t;
    closed += c.R > 0;
    // Energy balance (dissipated includes friction work). Not exact here: with linear
    // kinematics the normal stays the reference one while the struck point slides over the
    // deflected target, so the gap changes by slope x slide without work. Bound: normal impulse
    // (~1e4 N s) x slope (~1e-4) x slip speed (~0.5 m/s) ~ 1 J; allowed 5e-4 E0 = 4.2 J.
    EXPECT_NEAR(row.kinetic + row.strain + row.dissipated, r.energy_initial, 5e-4 * r.energy_initial)
        << row.t;
  }
  EXPECT_GT(closed, 10);
  EXPECT_GT(r.contacts[0].slip_steps, 0);
  EXPECT_GT(std::abs(r.contacts[0].impulse_tangential), 0.25 * r.contacts[0].impulse_normal);
}

TEST(RunIda, SlidingOverADeflectedTargetBalancesEnergy) {
  // grazing_slide: a frictionless tip slides ~0.4 m over B while B deflects. dissipated is what
  // the contact force takes from the bodies less what the penalty spring stores, so
  // K + S + D = E0 to IDA's tolerance (rtol 1e-8 on quadratures of ~0.01 J: 1e-5 E0 is
  // generous); booking only the dashpot at n . (v_a - v_b) ended at 1.47 E0. The gap's rate
  // includes the slide over the deflected surface, so a closed contact releases at R = 0 before
  // its gap turns positive: every row closed at its time has gap <= 0 to roundoff (1e-12 m). (A
  // row's R is the mean over the step it begins, which may hold a release: the state is the row's.)
  const SimulationResult r = ida::solve(load_scene(testing::hard_scene("grazing_slide")));
  int closed = 0;
  for (const HistoryRow& row : r.history) {
    EXPECT_NEAR(row.kinetic + row.strain + row.dissipated, r.energy_initial, 1e-5 * r.energy_initial)
        << row.t;
    if (row.contacts[0].state != ContactState::kOpen) {
      ++closed;
      EXPECT_LE(row.contacts[0].gap, 1e-12) << row.t << " R " << row.contacts[0].R;
    }
  }
  EXPECT_GT(closed, 100);  // the slide is in contact for ~0.7 s of rows at 5 ms
}

TEST(RunIda, S4WithoutSlidingBalancesEnergy) {
  // At 90 deg the struck point does not slide: the balance holds to IDA's tolerance
  // (rtol 1e-8 on a contact dissipating ~900 J: 1e-6 E0 = 8.4e-3 J is generous).
  const SimulationResult r =
      ida::solve(load_paper_scene("s4_oblique_90", {"time.end=0.03", "model.kinematics=linear"}));
  for (const HistoryRow& row : r.history)
    EXPECT_NEAR(row.kinetic + row.strain + row.dissipated, r.energy_initial, 1e-6 * r.energy_initial)
        << row.t;
  EXPECT_GT(r.history.back().dissipated, 100.0);
}

TEST(RunIda, FrictionRegularisationConverges) {
  // Tangential impulse of S4 at 60 deg for v_reg = 1e-2, 1e-3, 1e-4 m/s: the differences to
  // v_reg = 1e-5 fall with v_reg (the regularised law tends to Coulomb's).
  auto tau_impulse = [](const char* v) {
    return ida::solve(load_paper_scene("s4_oblique_60", {"time.end=0.02", "model.kinematics=linear",
                                                         std::string("ida.friction_velocity=") + v}))
        .contacts[0]
        .impulse_tangential;
  };
  const double ref = tau_impulse("1e-5");
  double prev = INFINITY;
  for (const char* v : {"1e-2", "1e-3", "1e-4"}) {
    const double d = std::abs(tau_impulse(v) - ref) / std::abs(ref);
    std::printf("S4-60 friction_velocity %s m/s: tangential impulse rel. diff %.2e\n", v, d);
    EXPECT_LT(d, prev) << v;
    prev = d;
  }
  EXPECT_LT(prev, 1e-5);
}

TEST(RunIda, SummaryCarriesIdaStatisticsAndDefaults) {
  // What `beamimpact run --method ida` writes: IDA counters and every default used.
  const Scene sc = load_paper_scene("s1_central", {"time.end=1.0", "ida.rtol=1e-6"});
  const nlohmann::json j = summary_json(sc, ida::solve(sc));
  EXPECT_EQ(j["method"], "ida");
  for (const char* k : {"steps", "residual_evals", "jacobian_evals", "events", "root_evals"})
    EXPECT_GT(j["ida"][k].get<long>(), 0) << k;
  EXPECT_EQ(j["ida"]["rtol"].get<double>(), 1e-6);
  for (const char* k : {"ida.atol", "ida.kn_factor", "ida.restitution", "ida.friction_velocity",
                        "ida.contacts[0].kn", "ida.contacts[0].cn", "ida.kinematics"})
    EXPECT_TRUE(j["assumed"].contains(k)) << k;
  EXPECT_FALSE(j["assumed"].contains("ida.rtol"));  // given, not assumed
}

TEST(RunIda, BadOptionsAreInputErrors) {
  auto expect_error = [](const std::string& set, const std::string& key) {
    try {
      ida::solve(load_paper_scene("s1_central", {set}));
      ADD_FAILURE() << set << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key) << e.what();
    }
  };
  expect_error("ida.rtoll=1e-6", "ida.rtoll");
  expect_error("ida.rtol=-1", "ida.rtol");
  expect_error("ida.rtol=1e-30", "ida.rtol");  // IDA itself stops at t = 0: too much accuracy
  expect_error("ida.restitution=0", "ida.restitution");
  expect_error("ida.linear_solver=\"lu\"", "ida.linear_solver");
  expect_error("ida.kn=-5", "ida.kn");
  expect_error("ida.atol=1e-300", "ida.atol");  // SUNDIALS stopped at t = 0 ("exit 3") before
  expect_error("ida.atol=0", "ida.atol");
  // A striker of vanishing mass under the default penalty: its contact period (2 pi sqrt(m/kn),
  // 2e-17 s here) would take ~1e18 IDA steps over S1; it hung before, now it is refused up front.
  expect_error("bodies.A.area=1e-30", "time.allow_long_run");
}

}  // namespace
}  // namespace beamimpact::ida

namespace beamimpact::ida {
namespace {

// IDA's struck point is clamped to the target; past the target's end its surface has ended, so
// the gap is the distance beyond the end and the contact opens. Before the fix IDA pressed on the
// end point's extension: 19 rows with R > 0 (up to 0.11 N) and the tip past B's end. Checked
// from the history (tip and struck-point positions), at both ends of the target.
TEST(IdaHardCases, StrikerSlidingOffEitherEndIsReleased) {
  for (const char* name : {"slide_off_roller", "slide_off_pin"}) {
    const Scene s = load_scene(testing::hard_scene(name));
    const SimulationResult r = solve(s);
    const double tip0 = s.bodies[0].end[0];
    const bool toward_end = s.bodies[0].velocity[0] > 0.0;
    const double end = toward_end ? s.bodies[1].end[0] : s.bodies[1].start[0];
    int beyond = 0, carried = 0;
    for (const HistoryRow& row : r.history) {
      const ContactSample& c = row.contacts[0];
      const double past = (tip0 + c.ua[0]) - (end + c.ub[0]);
      if ((toward_end ? past : -past) <= 1e-3) continue;
      ++beyond;
      carried += c.R > 0.0;
    }
    EXPECT_GT(beyond, 50) << name;
    EXPECT_EQ(carried, 0) << name << ": rows with the tip past the end and R > 0";
  }
}

}  // namespace
}  // namespace beamimpact::ida

namespace beamimpact::ida {
namespace {

// Gravity in IDA: the bouncing bar's scene before its first touch (t < 1 s) is a free fall of a
// stress-free bar, u = -g t^2 / 2 at every node; IDA's BDF integrates the quadratic exactly up to
// its error control (rtol 1e-8 of 5 m plus atol). The energy account K + S + D - W = E0 = 0 then
// holds to the same tolerance. Then the first impact: the exact solution touches at 1 s (root
// located to ~rtol) and carries 800/3 N s; the 10-element lumped bar's closure and dispersion
// make the mesh error (a few %, as S1's 3.7 % at the same 10 elements).
TEST(RunIda, BouncingBarFallsUnderGravityAndBounces) {
  const Scene s = load_scene(testing::source_dir() / "verification/scenes/benchmarks/bouncing_bar.toml",
                             {"time.end=2.0"});
  const SimulationResult r = ida::solve(s);
  for (const HistoryRow& row : r.history) {
    if (row.t >= 1.0) break;
    EXPECT_NEAR(row.contacts[0].ua[1], -5.0 * row.t * row.t, 1e-7) << row.t;
    EXPECT_NEAR(row.kinetic + row.strain + row.dissipated - row.load_work, 0.0, 1e-6) << row.t;
  }
  ASSERT_EQ(r.contacts[0].intervals.size(), 1u);
  EXPECT_NEAR(r.contacts[0].intervals[0][0], 1.0, 1e-6);
  EXPECT_NEAR(r.contacts[0].impulse_normal, 800.0 / 3.0, 0.05 * 800.0 / 3.0);
  ASSERT_EQ(r.contacts[0].interval_impulses.size(), 1u);
  EXPECT_NEAR(r.contacts[0].interval_impulses[0], r.contacts[0].impulse_normal, 1e-9 * 800.0);
  EXPECT_TRUE(r.extra.contains("loads"));
  // A free fall keeps momentum up to the loads' impulse: the drift is net of m g t (it reported
  // the loads' impulse itself, m g t = 10 kg x 10 m/s^2 x 1 s = 100 N s before the touch); the
  // contact's impulse then changes the momentum, so only the rows before the touch (t < 1 s)
  // bound it: a whole run's drift includes the ground's impulse (800/3 N s).
  const SimulationResult fall = ida::solve(load_scene(
      testing::source_dir() / "verification/scenes/benchmarks/bouncing_bar.toml", {"time.end=0.99"}));
  EXPECT_LT(fall.momentum_drift_max, 1e-6 * 100.0);  // IDA's tolerance (rtol 1e-8) on 100 N s
}

/// The trapezoid integral of contact 0's R over the rows (N s): what compare, score and conform
/// read from a history without an impulse column.
double rows_impulse(const SimulationResult& r) {
  double J = 0.0;
  for (std::size_t k = 1; k < r.history.size(); ++k)
    J += 0.5 * (r.history[k].contacts[0].R + r.history[k - 1].contacts[0].R) *
         (r.history[k].t - r.history[k - 1].t);
  return J;
}

// history.csv's R is the protocol's force (docs/protocol.md, "The time R belongs to"): the mean over
// the output step the row begins, as the paper integrator's rows. On evenly spaced rows that begin
// and end open, the trapezoid rule on such rows is their step sum, which is the impulse the steps
// carry: the rows' impulse equals summary.json's (IDA's own quadrature) to rounding, bound 1e-12
// relative (400 rows of 1e-16). The instantaneous penalty force the rows held before missed the
// closure's transient between rows: 3.755 against 3.856 N s on S1.
//
// S1 exact (references.md 1): a plateau of rho c A v0 / 2 = 2 N. The lumped mesh overshoots the
// wave front at its cutoff frequency by 9.2 % whatever the mesh (2.1844 N at 10 and at 40
// elements; the paper integrator's own rows the same), so no row is above 1.1 x 2 N but the
// closure row. That row, [0.5, 0.51] s (the gap closes at 0.5 s exactly), carries the plastic
// closure of the two end nodes (mass rho A le / 2 = 0.2 kg each, reduced mass 0.1 kg, closing at
// v0 = 1 m/s): an impulse m_red v0 = 0.1 N s, so a mean of m_red v0 / h = 10 N, plus the contact's
// own force over the row, at most 1.1 x 2 N. The dashpot's jump (608 N, cn v0) is no force of the
// rows: it is stated apart, with the instantaneous force's peak.
TEST(RunIda, S1HistoryCarriesTheStepMeanForce) {
  const SimulationResult r = s1();
  const ContactSummary& c = r.contacts.at(0);
  EXPECT_NEAR(rows_impulse(r), c.impulse_normal, 1e-12 * c.impulse_normal);
  ASSERT_EQ(c.intervals.size(), 1u);
  const double h = 0.01, m_red = 0.1, v0 = 1.0, plateau = 2.0;
  for (const HistoryRow& row : r.history) {
    const double R = row.contacts[0].R;
    if (std::abs(row.t - 0.5) < 1e-9) {
      EXPECT_GE(R, m_red * v0 / h) << "the closure row";
      EXPECT_LE(R, m_red * v0 / h + 1.1 * plateau) << "the closure row";
    } else {
      EXPECT_LE(R, 1.1 * plateau) << row.t;
    }
  }
  // The summary's peaks are the rows': the closure row, then the rows after the closure window.
  EXPECT_EQ(c.peak_R, c.first_step_R);
  EXPECT_GE(c.peak_R, m_red * v0 / h);
  EXPECT_GE(c.peak_R_excluding_closure, plateau);  // the overshoot is above the plateau
  EXPECT_LE(c.peak_R_excluding_closure, 1.1 * plateau);
  EXPECT_GT(c.extra.at("closure_dashpot_jump").get<double>(), 100.0);  // stated apart
  EXPECT_GT(c.extra.at("peak_R_with_closure").get<double>(), 100.0);
}

// The same on a finer mesh (40 elements): the closure row's share m_red v0 / h falls with le
// (m_red = rho A le / 4: 0.025 N s, 2.5 N), the overshoot keeps its 9.2 %. So peak_R, the largest
// row, tends to 2.18 N, not to the exact 2 N: the lumped mesh's wave front, which no mesh removes
// (measured: 10.15 / 5.21 / 2.89 N at 10 / 20 / 40 elements). The force the mesh resolves, the
// largest mean over its shortest period 2 pi / omega_max (0.314 s at 10 elements), leaves the
// overshoot out and keeps the plateau: 2.0304 N at 10 and 40 elements, the same 1.5 % of the
// ringing (it keeps its shape in units of le / c), so 5 % holds it and fails the 9.2 % overshoot.
TEST(RunIda, S1PeakForceOnAFinerMeshIsTheMeshsWaveFront) {
  const SimulationResult r = s1({"bodies[0].elements=40", "bodies[1].elements=40"});
  const ContactSummary& c = r.contacts.at(0);
  EXPECT_NEAR(rows_impulse(r), c.impulse_normal, 1e-12 * c.impulse_normal);
  const double m_red = 0.025, v0 = 1.0, h = 0.01, plateau = 2.0;
  EXPECT_GE(c.first_step_R, m_red * v0 / h);
  EXPECT_LE(c.first_step_R, m_red * v0 / h + 1.1 * plateau);
  EXPECT_LE(c.peak_R, m_red * v0 / h + 1.1 * plateau);
  EXPECT_GE(c.peak_R_excluding_closure, plateau);
  EXPECT_LE(c.peak_R_excluding_closure, 1.1 * plateau);
  const SimulationResult r10 = s1();
  for (const SimulationResult* run : {&r, &r10})
    EXPECT_NEAR(run->contacts[0].extra.at("peak_R_resolved").get<double>(), plateau, 0.05 * plateau);
  // The window is 2 pi / omega_max = pi le / c (c = 10 m/s; le = 1 and 0.25 m), to 1 %.
  EXPECT_NEAR(r10.contacts[0].extra.at("resolved_window").get<double>(), M_PI * 1.0 / 10.0,
              0.01 * M_PI / 10.0);
  EXPECT_NEAR(r.contacts[0].extra.at("resolved_window").get<double>(), M_PI * 0.25 / 10.0,
              0.01 * M_PI / 40.0);
}

// The bouncing bar (RodOnWall.hpp, exact): its first impact carries 800/3 N s and its force rises
// linearly from 300 N to 500 N. At 80 elements the rows' impulse equals the summary's to rounding
// (rows open at 0 and at 2 s, evenly spaced: 1e-12 relative), no row is above 1.1 x 500 N, and the
// peak, at the impact's end, converges with the mesh from below (measured 460 / 473 / 482 / 487 N
// at 10 / 20 / 40 / 80 elements, the closure rows left out): 5 % at 80 elements. The dashpot's
// jump at the touch (64,492 N) is stated apart.
TEST(RunIda, BouncingBarHistoryCarriesTheStepMeanForce) {
  const SimulationResult bar =
      ida::solve(load_scene(testing::source_dir() / "verification/scenes/benchmarks/bouncing_bar.toml",
                            {"time.end=2.0", "bodies.bar.elements=80"}));
  const ContactSummary& c = bar.contacts.at(0);
  ASSERT_EQ(c.intervals.size(), 1u);
  EXPECT_NEAR(c.impulse_normal, 800.0 / 3.0, 0.05 * 800.0 / 3.0);
  EXPECT_NEAR(rows_impulse(bar), c.impulse_normal, 1e-12 * c.impulse_normal);
  for (const HistoryRow& row : bar.history) EXPECT_LE(row.contacts[0].R, 1.1 * 500.0) << row.t;
  EXPECT_NEAR(c.peak_R, 500.0, 0.05 * 500.0);
  EXPECT_NEAR(c.extra.at("peak_R_resolved").get<double>(), 500.0, 0.05 * 500.0);
  EXPECT_GT(c.extra.at("closure_dashpot_jump").get<double>(), 1e4);
}

}  // namespace
}  // namespace beamimpact::ida
