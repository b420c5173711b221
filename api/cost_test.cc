// The cost figures of summary.json ("cost"): DOFs, elements and steps as the scene implies them,
// ns per DOF-step and per element-step positive, and IDA's counters consistent with each other.
// No timing is asserted (speed is measured in benchmarks and reports).
#include <api/run.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <solver/record/output_files.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact {
namespace {

nlohmann::json cost_of(const std::string& method, int elements) {
  const std::vector<std::string> set = {"bodies.A.elements=" + std::to_string(elements),
                                        "bodies.B.elements=" + std::to_string(elements)};
  const Scene scene = testing::load_paper_scene("s1_central", set);
  return summary_json(scene, run(scene, method));
}

// S1's bodies are collinear free rods struck end-on: an axial model, one displacement per node,
// so n elements per body give 2 (n + 1) DOFs (22 at n = 10, 42 at n = 20: doubling the mesh
// doubles the DOFs up to the two end nodes). The paper's dt = 0.01 s over 4 s is 400 steps.
TEST(CostSummary, PaperDofsElementsAndStepsFollowTheScene) {
  for (int n : {10, 20}) {
    const nlohmann::json s = cost_of("paper", n);
    ASSERT_TRUE(s.contains("cost")) << s.dump();
    const nlohmann::json& c = s["cost"];
    EXPECT_EQ(c["dofs"].get<long>(), 2 * (n + 1));
    EXPECT_EQ(c["elements"].get<long>(), 2 * n);
    EXPECT_EQ(c["steps"].get<long>(), 400);
    EXPECT_EQ(c["steps"], s["steps"]);
    for (const char* k : {"ns_per_dof_step", "ns_per_element_step"}) {
      const double v = c[k].get<double>();
      EXPECT_TRUE(std::isfinite(v) && v > 0.0) << k << " = " << v;
    }
  }
}

// IDA on the same beam model: the same DOFs; its counters are SUNDIALS' (every step evaluates the
// residual at least once, the Jacobian at least once in a run, failures are counts).
TEST(CostSummary, IdaCountersAreConsistent) {
  const nlohmann::json s = cost_of("ida", 10);
  ASSERT_TRUE(s.contains("cost"));
  EXPECT_EQ(s["cost"]["dofs"].get<long>(), 22);
  const nlohmann::json& ida = s["ida"];
  EXPECT_EQ(ida["steps"], s["steps"]);
  EXPECT_GT(ida["steps"].get<long>(), 0);
  EXPECT_LE(ida["steps"].get<long>(), ida["residual_evals"].get<long>());
  EXPECT_GE(ida["jacobian_evals"].get<long>(), 1);
  EXPECT_GE(ida["nonlinear_conv_fails"].get<long>(), 0);
  EXPECT_GT(s["cost"]["ns_per_dof_step"].get<double>(), 0.0);
}

// The exact solution has no discrete model: no DOFs, so no cost per DOF-step is claimed.
TEST(CostSummary, ExactHasNoCostBlock) { EXPECT_FALSE(cost_of("exact", 10).contains("cost")); }

}  // namespace
}  // namespace beamimpact
