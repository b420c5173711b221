// The third test: with a penalty set for (near) zero restitution and a large kn, the IDA
// reference approaches the paper's discrete model (plastic closure of the contact nodes, then
// persistent contact). On S1-S4 at the same mesh, paper and IDA must agree on impulse, contact
// intervals and the contact points' displacement histories within bounds that follow from the
// paper's first-order event timing, and the difference must shrink as the paper's dt falls.
// S4 runs both methods with linear kinematics here (the corotational striker: ida_corotational_test).
//
// Built twice: the quick variant (paper dt0, dt0/2, dt0/4, shortened end times) and, with
// BEAMIMPACT_IDA_FULL, the "full" variant (dt0 ... dt0/16, the scenes' end times).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include <references/ida/solve.hpp>
#include <solver/paper/solve.hpp>
#include <solver/record/ContactIntervals.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact::ida {
namespace {

#ifdef BEAMIMPACT_IDA_FULL
constexpr int kHalvings = 4;
constexpr bool kFull = true;
#else
constexpr int kHalvings = 2;
constexpr bool kFull = false;
#endif

struct Case {
  const char* scene;
  double quick_end;  ///< s, end time of the quick variant
  /// s, the impacts are compared one by one (count, displacement bound) before this time; 0: the
  /// whole run. S4's chatter after its first impact phase (0.03 s) is a sequence of grazing
  /// re-contacts whose count converges in no step or penalty ladder (docs/s4.md): the full run's
  /// impulse and displacements there are held to shrink, not to one sequence.
  double sequence_end;
  std::vector<std::string> extra;  ///< overrides for both methods
  bool auto_dt;                    ///< dt = fraction x critical (S4)
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.scene; }

/// Largest |a - b| over the striker node's displacement (all rows) and the struck point's
/// displacement (rows where both methods are in contact: when open, the paper re-locates the
/// struck point on the deformed chord, a definition that differs from IDA's reference normal).
double displacement_difference(const SimulationResult& p, const SimulationResult& i,
                               double t_end = INFINITY) {
  const std::size_t n = std::min(p.history.size(), i.history.size());
  double d = 0.0;
  for (std::size_t k = 0; k < n && i.history[k].t < t_end; ++k) {
    const ContactSample& a = p.history[k].contacts[0];
    const ContactSample& b = i.history[k].contacts[0];
    // Rows line up on the common grid; only the paper's final row (its step N = ceil(end/dt)
    // need not be a multiple of output_every) may fall off it.
    if (std::abs(p.history[k].t - i.history[k].t) > 1e-9 * (1 + i.history[k].t)) {
      EXPECT_EQ(k + 1, n) << "rows out of step at t = " << i.history[k].t;
      break;
    }
    for (int c = 0; c < 2; ++c) {
      d = std::max(d, std::abs(a.ua[c] - b.ua[c]));
      if (a.R > 0 && b.R > 0) d = std::max(d, std::abs(a.ub[c] - b.ub[c]));
    }
  }
  return d;
}

using Intervals = std::vector<std::array<double, 2>>;

/// Intervals separated by less than gap seconds joined into one (the rule of every summary), those
/// starting before t_end.
Intervals merged(const Intervals& in, double gap, double t_end) {
  ContactIntervals out(gap);
  for (const auto& iv : in) {
    if (iv[0] >= t_end) break;
    out.begin(iv[0]);
    out.extend(iv[1]);
  }
  return out.intervals();
}

/// The contact intervals as "[start, end] s" pairs, for failure messages.
std::string interval_list(const Intervals& list) {
  std::string s;
  for (const auto& iv : list) s += "[" + std::to_string(iv[0]) + ", " + std::to_string(iv[1]) + "] ";
  return s.empty() ? "(none)" : s;
}

class IdaVsPaper : public ::testing::TestWithParam<Case> {};

TEST_P(IdaVsPaper, AgreeAndConvergeAsPaperDtFalls) {
  const Case& c = GetParam();
  std::vector<std::string> common = c.extra;
  if (!kFull) common.push_back("time.end=" + std::to_string(c.quick_end));
  const Scene base = testing::load_paper_scene(c.scene, common);
  const double f0 = c.auto_dt ? base.time.fraction : *base.time.dt;
  const std::string key = c.auto_dt ? "time.fraction=" : "time.dt=";

  // IDA: restitution 0.001 (the plastic closure's limit) and kn = 1e4 EA/le; rtol 1e-8.
  std::vector<std::string> io = common;
  io.insert(io.end(), {"ida.restitution=0.001", "ida.kn_factor=1e4"});
  const SimulationResult ida = ida::solve(testing::load_paper_scene(c.scene, io));
  const ContactSummary& ci = ida.contacts.at(0);
  ASSERT_FALSE(ci.intervals.empty());
  const double period = ci.extra.at("contact_period").get<double>();
  const std::size_t events = std::max<std::size_t>(4, ci.extra.at("events").size());
  double v0 = 0.0;
  for (const Body& b : base.bodies) v0 = std::max(v0, std::hypot(b.velocity[0], b.velocity[1]));

  double first_dI = 0, first_du = 0, dI = 0, du = 0;
  for (int k = 0; k <= kHalvings; ++k) {
    const long every = 1L << k;
    std::vector<std::string> po = common;
    po.push_back(key + std::to_string(f0 / static_cast<double>(every)));
    po.push_back("time.output_every=" + std::to_string(every));
    const SimulationResult paper = paper::solve(testing::load_paper_scene(c.scene, po));
    const ContactSummary& cp = paper.contacts.at(0);
    ASSERT_FALSE(cp.intervals.empty());
    const double dt = paper.dt;
    dI = std::abs(cp.impulse_normal - ci.impulse_normal);
    const double ds = std::abs(cp.intervals[0][0] - ci.intervals[0][0]);
    const double de = std::abs(cp.intervals[0][1] - ci.intervals[0][1]);
    du = displacement_difference(paper, ida);
    const double t_seq = c.sequence_end > 0.0 ? c.sequence_end : INFINITY;
    std::printf(
        "%s dt=%.4e: |dI| %.3e N s (rel %.2e), first interval start %.2e end %.2e s, "
        "max|du| %.3e m, intervals paper/ida %zu/%zu\n",
        c.scene, dt, dI, dI / ci.impulse_normal, ds, de, du, cp.intervals.size(), ci.intervals.size());
    // Bounds from the paper's first-order event timing: its closure is detected at the step
    // where the predicted gap turns negative (up to one dt early) and its interval ends at the
    // last step with R > 0, while its forward multiplier releases up to half a step early
    // (references.md 4): up to 1.5 dt before IDA's located release, which itself lags the
    // constraint's by the penalty's release offset (below one penalty period). A shift of one
    // step changes the impulse by at most dt x the contact force after closure, and the contact
    // points' displacements by at most (relative speed <= v0) x dt per event (at least 4: two
    // closures and releases). Those two bounds assume the same sequence of impacts, so they hold
    // before the case's sequence_end: over S4's full 0.1 s the paper merges or adds late grazing
    // re-contacts (at 90 deg 5 against IDA's 7 intervals at dt0, 8 against 7 at dt0/16; at 45 deg
    // 9 against 7 at dt0/4), which only the shrinking sequence below can judge.
    EXPECT_LE(ds, dt + 1e-9);
    EXPECT_LE(de, 2.0 * dt + period);
    // The same semi-discrete model must give the same sequence of impacts (before sequence_end):
    // a count mismatch is a failure (both lists printed), never a reason to skip the bounds below. Both lists
    // are merged with one gap in seconds, 5 paper steps at dt0 for every rung: at dt0 the paper's event
    // timing (closure up to 1 dt early, release up to 1.5 dt early) splits a contact that IDA
    // keeps closed (S4_60: a 4-step separation at 0.0197 s, gone at dt0/2).
    const double merge_gap = 5.0 * dt * static_cast<double>(every);  // s, 5 x dt0
    const auto mp = merged(cp.intervals, merge_gap, t_seq), mi = merged(ci.intervals, merge_gap, t_seq);
    EXPECT_EQ(mp.size(), mi.size()) << c.scene << " dt=" << dt << " (merge gap " << merge_gap
                                    << " s): paper intervals " << interval_list(mp) << ", IDA intervals "
                                    << interval_list(mi);
    EXPECT_LE(dI, 2.0 * dt * cp.peak_R_excluding_closure);
    EXPECT_LE(displacement_difference(paper, ida, t_seq), static_cast<double>(events) * v0 * dt);
    if (k == 0) {
      first_dI = dI;
      first_du = du;
    }
  }
  // The difference shrinks as the paper's dt falls (dt0 -> dt0/4 or /16): at least 2x.
  EXPECT_LT(dI, first_dI / 2);
  EXPECT_LT(du, first_du / 2);
}

INSTANTIATE_TEST_SUITE_P(
    PaperScenes, IdaVsPaper,
    ::testing::Values(Case{"s1_central", 4.0, 0.0, {}, false}, Case{"s2_transverse", 1.5, 0.0, {}, false},
                      Case{"s3_surface_10", 1.5, 0.0, {}, false}, Case{"s3_surface_20", 1.5, 0.0, {}, false},
                      Case{"s4_oblique_90", 0.03, 0.03, {"model.kinematics=linear"}, true},
                      Case{"s4_oblique_60", 0.03, 0.03, {"model.kinematics=linear"}, true},
                      Case{"s4_oblique_45", 0.03, 0.03, {"model.kinematics=linear"}, true}),
    [](const ::testing::TestParamInfo<Case>& i) { return std::string(i.param.scene); });

// A stiff penalty on S4 (linear kinematics) meets the hard-contact answer of the paper integrator
// and never pulls. The penalty law's force is compressive or zero by definition (a contact releases
// when its trial force reaches zero), so a tensile force in any row is a contact switch gone wrong:
// S4-60 without friction at 1e4 EA/le closed its contact at a gap of roundoff size while the gap
// rose, with a tensile dashpot force that the release root never saw (held for 1.4 ms, -1.9 MN;
// impulse 6 % low over the scene's 0.1 s); S4-90 at 1e5 EA/le re-closed a receding contact on the
// trial force and stepped through the sliding mode on R = 0 by roundoff-sized events until the
// event guard stopped the run. Both methods approximate the same hard-contact limit: the impulses
// agree within 0.1 % (IDA's penalty ladder 1e3 -> 1e5 EA/le moves them by 2e-5 and 4e-4, the
// paper's step ladder 1/16 -> 1/64 by 3e-4 at 90 degrees; measured 1e-6 and 2e-4).
TEST(IdaVsPaperS4, StiffPenaltyMeetsTheHardContactAndNeverPulls) {
  struct Run {
    const char* scene;
    std::vector<std::string> sets;  ///< both methods
    const char* kn_factor;          ///< EA/le
  };
  for (const Run& run : {Run{"s4_oblique_60", {"contacts[0].friction=0", "time.end=0.025"}, "1e4"},
                         Run{"s4_oblique_90", {"time.end=0.065"}, "1e5"}}) {
    std::vector<std::string> common = run.sets;
    common.push_back("model.kinematics=linear");
    std::vector<std::string> io = common, po = common;
    io.insert(io.end(), {std::string("ida.kn_factor=") + run.kn_factor, "ida.rtol=1e-10", "ida.atol=1e-13"});
    po.push_back("time.fraction=0.015625");
    SimulationResult ida;
    ASSERT_NO_THROW(ida = ida::solve(testing::load_paper_scene(run.scene, io))) << run.scene;
    const SimulationResult paper = paper::solve(testing::load_paper_scene(run.scene, po));
    double least = 0.0;
    for (const HistoryRow& row : ida.history) least = std::min(least, row.contacts[0].R);
    EXPECT_GE(least, 0.0) << run.scene << ": a tensile contact force";
    const double J = paper.contacts.at(0).impulse_normal;
    EXPECT_NEAR(ida.contacts.at(0).impulse_normal, J, 1e-3 * J) << run.scene;
  }
}

// The Hertz law in both methods: IDA integrates the spring (no dashpot) to its tolerance and keeps
// the energy; the paper integrator's secant force keeps it at any step (hertz_law.hpp). S1 with a
// Hertz spring of k = 3e6 N/m^1.5 at the paper's dt = 0.01 s (the end nodes' contact lasts about
// 0.1 s: ten steps) and the rigid drop at dt = 1 ms (longer than its 0.81 ms contact): the paper's
// final energy is IDA's within the row energy's band (the physical velocity V^p of the bars'
// modes, (omega dt)^2 / 8 of their energy: 2e-3 on S1) and its impulse within 2 % (S1's chattering
// end nodes: each re-closure's timing moves by a step); on the drop both are exact but for IDA's
// own tolerance (rtol 1e-8: measured 6.7e-8 of E0 and 1.5e-8 of the impulse; 1e-6). The
// trapezoidal force this replaced ended S1 at 2.13 J and the drop at 0.682 J.
TEST(IdaVsPaperHertz, BothKeepTheEnergyOfAStiffSpringAtALongStep) {
  struct Run {
    const char* file;
    std::vector<std::string> sets;
    double band, impulse_tol;
  };
  const std::string s1 = (testing::source_dir() / "verification/scenes/paper/s1_central.toml").string();
  const std::string drop = (testing::source_dir() / "verification/scenes/extra/hertz_drop.toml").string();
  for (const Run& run : {Run{s1.c_str(), {"contacts[0].law=hertz", "contacts[0].stiffness=3e6"}, 2e-3, 0.02},
                         Run{drop.c_str(), {"time.dt=1e-3", "time.end=0.01"}, 1e-6, 1e-6}}) {
    const SimulationResult ida = ida::solve(load_scene(run.file, run.sets));
    const SimulationResult paper = paper::solve(load_scene(run.file, run.sets));
    EXPECT_NEAR(ida.energy_final, ida.energy_initial, 1e-5 * ida.energy_initial) << run.file;
    EXPECT_NEAR(paper.energy_final, ida.energy_final, run.band * ida.energy_initial) << run.file;
    const double J = ida.contacts.at(0).impulse_normal;
    EXPECT_NEAR(paper.contacts.at(0).impulse_normal, J, run.impulse_tol * J) << run.file;
  }
}

}  // namespace
}  // namespace beamimpact::ida
