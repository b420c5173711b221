// `beamimpact sweep` measures each point against the reference, never the reference against the
// point: runs in memory (a stand-in executor, no process) whose contact force is (1 + e) times
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

/// Runs every spec "in memory": the reference (the step finest / 4, or another method) has the
/// pulse, a point at dt the pulse times 1 + 100 dt (2 at dt = 0.01, 1.5 at 0.005).
JobExecutor stand_in(double reference_dt) {
  return [reference_dt](const std::vector<JobSpec>& specs, const std::filesystem::path&, const Launcher&, int,
                        double) {
    std::map<std::string, JobOutcome> out;
    for (const JobSpec& s : specs) {
      const bool reference = s.method != "paper" || (s.dt && std::abs(*s.dt - reference_dt) < 1e-15);
      const double scale = reference ? 1.0 : 1.0 + 100.0 * s.dt.value_or(0.0);
      auto run = std::make_shared<const StoredRun>(
          testing::synthetic(0.001, 3.0, [scale](double t) { return scale * pulse(t); }));
      out[s.key()] = JobOutcome{s, {}, JobOutcome::Status::kOk, "", 0.0, 0.0, 3000, s.dt.value_or(0.0), run};
    }
    return std::optional(out);
  };
}

void expect_errors_against_reference(const std::string& reference) {
  SCOPED_TRACE("reference " + reference);
  SweepOptions o;
  o.scene = testing::paper_scene("s1_central");
  o.dts = {0.01, 0.005};
  o.reference = reference;
  o.out = testing::temp_path("sweep_" + reference);
  o.executor = stand_in(0.005 / 4);  // "self": the finest step / 4
  Launcher launcher;
  launcher.exe = "beamimpact";
  const std::optional<SweepResult> r = execute_sweep(o, launcher);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->points.size(), 2u);
  const double e[2] = {1.0, 0.5};  // 100 dt
  for (int k = 0; k < 2; ++k) {
    ASSERT_TRUE(r->points[k].comparison) << k;
    // Same pulse, same rows: e to roundoff (swapped: 0.5 and 1/3).
    for (const char* n : {"impulse", "peak_R", "R.rel_l2"}) {
      const Norm* norm = r->points[k].comparison->find(n);
      ASSERT_TRUE(norm && norm->value) << n;
      EXPECT_NEAR(*norm->value, e[k], 1e-12) << n << " at dt " << o.dts[k];
    }
  }
}

TEST(Sweep, EachPointIsMeasuredAgainstTheFinestStepReference) { expect_errors_against_reference("self"); }

TEST(Sweep, EachPointIsMeasuredAgainstAReferenceMethod) { expect_errors_against_reference("exact"); }

}  // namespace
}  // namespace beamimpact::verification
