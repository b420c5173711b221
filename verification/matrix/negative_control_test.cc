// Negative control: a method known to be wrong must fail the benchmark gates, so that a pass
// means something. The flawed method lives only here: explicit central differences on the same
// model (lumped M, K, gravity load) with the contact enforced on the displacement only: a node
// found below the wall is put back on it, its velocity left as it was (no velocity correction,
// so the closure is not an impact: the node keeps its approach speed while held, and the elastic
// force then throws it off with energy the contact created). Its run replaces the paper method's
// in the matrix's bouncing-bar row against the exact solution, which must report FAIL naming the
// failing norm; the paper method's own run passes the same row.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <solver/model/Model.hpp>
#include <solver/model/load_vector.hpp>
#include <solver/record/ResultRecorder.hpp>
#include <solver/record/output_files.hpp>
#include <solver/scene/scene_io.hpp>
#include <verification/jobs/execute_jobs.hpp>
#include <verification/matrix/VerificationMatrix.hpp>
#include <verification/matrix/evaluate.hpp>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;

/// The flawed method on a rod scene (rod layout, lumped mass, one contact of the striker's
/// declared node against an immovable rigid body on its axis).
SimulationResult displacement_only_contact(const Scene& scene) {
  const Model m(scene, false);
  const Eigen::VectorXd F = load_vector(m, scene), M = m.lumped_mass();
  const Contact& c = scene.contacts[0];
  const int node = m.node_id(c.striker, c.node), eq = m.equation(node, 0);
  const Body& wall = scene.bodies[c.target];
  const Vec2 x = scene.bodies[c.striker].node_position(c.node), axis = m.rod_axis();
  // Gap along the axis to the wall's nearer end, and the sign of an approach in U.
  const double s0 = (wall.start[0] - x[0]) * axis[0] + (wall.start[1] - x[1]) * axis[1];
  const double s1 = (wall.end[0] - x[0]) * axis[0] + (wall.end[1] - x[1]) * axis[1];
  const double toward = std::abs(s0) < std::abs(s1) ? (s0 > 0 ? 1.0 : -1.0) : (s1 > 0 ? 1.0 : -1.0);
  const double gap0 = std::min(std::abs(s0), std::abs(s1));
  ResultRecorder rec(scene, "displacement_only", ContactSampling::kFixedSteps);
  const double dt = *scene.time.dt;
  rec.result().dt = dt;
  rec.set_merge_rule(1.5 * dt, "phases fewer than 1 open step apart are merged");
  Eigen::VectorXd U = Eigen::VectorXd::Zero(m.size()), V = m.initial_velocity();
  const auto N = static_cast<long>(std::llround(scene.time.end / dt));
  for (long p = 0; p <= N; ++p) {
    if (p > 0) {
      V += dt * (F - m.K() * U).cwiseQuotient(M);
      U += dt * V;
    }
    double R = 0.0;
    const double pen = toward * U(eq) - gap0;
    if (pen > 0.0) {
      U(eq) -= toward * pen;        // back onto the wall
      R = M(eq) * pen / (dt * dt);  // the force that moved it there in one step
    }
    HistoryRow row;
    row.t = static_cast<double>(p) * dt;
    ContactSample cs;
    cs.R = R;
    cs.gap = gap0 - toward * U(eq);
    cs.ua = {U(eq) * axis[0], U(eq) * axis[1]};
    cs.va = {V(eq) * axis[0], V(eq) * axis[1]};
    cs.state = R > 0.0 ? ContactState::kClosed : ContactState::kOpen;
    row.contacts.push_back(cs);
    row.kinetic = 0.5 * V.dot(M.cwiseProduct(V));
    row.strain = 0.5 * U.dot(m.K() * U);
    row.load_work = F.dot(U);
    rec.sample(0, row.t, R, 0.0, dt, cs.state);
    rec.add_row(std::move(row));
  }
  for (int b = 0; b < m.num_bodies(); ++b)
    rec.set_final_velocity(scene.bodies[b].name, {m.momentum_covector(b, 0).dot(V) / m.body_mass(b),
                                                  m.momentum_covector(b, 1).dot(V) / m.body_mass(b)});
  return rec.finish({ContactKind::kEndToEnd});
}

TEST(NegativeControl, DisplacementOnlyContactFailsTheBouncingBar) {
  const VerificationMatrix matrix =
      VerificationMatrix::load(fs::path(BEAMIMPACT_SOURCE) / "verification" / "matrix.toml");
  const Case* row = nullptr;
  for (const Case& c : matrix.cases)
    if (c.run.scene_name() == "bouncing_bar" && c.run.method == "paper" && c.reference.method == "exact")
      row = &c;
  ASSERT_NE(row, nullptr) << "matrix.toml has no bouncing_bar paper-vs-exact row";
  jobs::Launcher launcher;
  launcher.exe = BEAMIMPACT_EXE;
  const fs::path tmp = fs::temp_directory_path() / fmt::format("beamimpact_negative_control_{}", ::getpid());
  fs::remove_all(tmp);
  auto runs = *jobs::execute_jobs({row->run, row->reference}, tmp / "runs", launcher, 2, 600.0);
  for (const auto& [k, o] : runs)
    ASSERT_EQ(o.status, jobs::JobOutcome::Status::kOk) << k << ": " << o.message;

  // The paper method passes every gate of the row.
  for (const auto& g : evaluate_case(*row, runs).gates)
    EXPECT_EQ(g.status, GateStatus::kPass) << "paper: " << g.gate.metric << ": " << g.message;

  // The flawed method, on the same scene and step, fails it, and the report names the norms.
  std::vector<std::string> set = row->run.set;
  if (row->run.dt) set.push_back(fmt::format("time.dt={:.17g}", *row->run.dt));
  const fs::path file = row->run.scene.is_absolute() ? row->run.scene : matrix.root / row->run.scene;
  const Scene scene = load_scene(file, set);
  write_outputs(scene, displacement_only_contact(scene), tmp / "flawed");
  runs.at(row->run.key()).dir = tmp / "flawed";
  runs.at(row->run.key()).run.reset();  // evaluate reads the flawed run's directory
  std::vector<std::string> failed;
  for (const auto& g : evaluate_case(*row, runs).gates)
    if (g.status == GateStatus::kFail) {
      failed.push_back(g.gate.metric);
      std::printf("flawed method: %s FAIL: %s\n", g.gate.metric.c_str(), g.message.c_str());
      EXPECT_NE(g.message.find(g.gate.metric), std::string::npos)
          << "the message names the norm: " << g.message;
    }
  EXPECT_FALSE(failed.empty()) << "the flawed method passed every gate";
  EXPECT_NE(std::find(failed.begin(), failed.end(), "energy_drift_per_impact"), failed.end())
      << "the energy the contact creates is caught; failed: " << fmt::format("{}", fmt::join(failed, ", "));
  fs::remove_all(tmp);
}

}  // namespace
}  // namespace beamimpact::verification
