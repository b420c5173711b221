// `beamimpact sweep` measures each point against the reference, never the reference against the
// point: runs in memory (stand-in outcomes, no run) whose contact force is (1 + e) times
// the reference's give the relative errors e, where the swapped comparison would give e / (1 + e).
#include <verification/matrix/sweep.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>
#include <verification/compare/test_histories.hpp>

namespace beamimpact::verification {
namespace {

/// A sin^2 pulse of contact force on [1, 2] s.
double pulse(double t) { return t > 1.0 && t < 2.0 ? std::pow(std::sin(M_PI * (t - 1.0)), 2) : 0.0; }

/// The outcomes of every spec "in memory": the reference (the step finest / 4, or another
/// method) has the pulse, a point at dt the pulse times 1 + 100 dt (2 at dt = 0.01, 1.5 at 0.005).
std::map<std::string, jobs::JobOutcome> stand_in(const std::vector<jobs::JobSpec>& specs,
                                                 double reference_dt) {
  std::map<std::string, jobs::JobOutcome> out;
  for (const jobs::JobSpec& s : specs) {
    const bool reference = s.method != "paper" || (s.dt && std::abs(*s.dt - reference_dt) < 1e-15);
    const double scale = reference ? 1.0 : 1.0 + 100.0 * s.dt.value_or(0.0);
    auto run = std::make_shared<const StoredRun>(
        testing::synthetic(0.001, 3.0, [scale](double t) { return scale * pulse(t); }));
    out[s.key()] =
        jobs::JobOutcome{s, {}, jobs::JobOutcome::Status::kOk, "", 0.0, 0.0, 3000, s.dt.value_or(0.0), run};
  }
  return out;
}

void expect_errors_against_reference(const std::string& reference) {
  SCOPED_TRACE("reference " + reference);
  SweepOptions o;
  o.scene = testing::paper_scene("s1_central");
  o.dts = {0.01, 0.005};
  o.reference = reference;
  o.out = testing::temp_path("sweep_" + reference);
  const SweepPlan plan = plan_sweep(o);
  std::vector<jobs::JobSpec> all = plan.points;
  all.push_back(*plan.reference);
  const SweepResult r = judge_sweep(o, plan, stand_in(all, 0.005 / 4));  // "self": finest / 4
  ASSERT_EQ(r.points.size(), 2u);
  const double e[2] = {1.0, 0.5};  // 100 dt
  for (int k = 0; k < 2; ++k) {
    ASSERT_TRUE(r.points[k].comparison) << k;
    // Same pulse, same rows: e to roundoff (swapped: 0.5 and 1/3).
    for (const char* n : {"impulse", "peak_R", "R.rel_l2"}) {
      const Norm* norm = r.points[k].comparison->find(n);
      ASSERT_TRUE(norm && norm->value) << n;
      EXPECT_NEAR(*norm->value, e[k], 1e-12) << n << " at dt " << o.dts[k];
    }
  }
}

TEST(Sweep, EachPointIsMeasuredAgainstTheFinestStepReference) { expect_errors_against_reference("self"); }

TEST(Sweep, EachPointIsMeasuredAgainstAReferenceMethod) { expect_errors_against_reference("exact"); }

}  // namespace
}  // namespace beamimpact::verification
