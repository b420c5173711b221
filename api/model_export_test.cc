// The exported model checked against theory: masses rho A L, rigid-body modes in the null space
// of K, a free rod's first frequency pi c / L, gaps that close under the displacement that
// geometry says closes them. Everything is read back from the written files, as an outside
// solver reads them.
#include <api/model_export.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

/// A Matrix Market coordinate file as a dense matrix (the files here are small).
Eigen::MatrixXd read_mtx(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line) && line.rfind('%', 0) == 0) {
  }
  std::istringstream head(line);
  int rows = 0, cols = 0, nnz = 0;
  head >> rows >> cols >> nnz;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(rows, cols);
  for (int k = 0; k < nnz; ++k) {
    int i = 0, j = 0;
    double v = 0.0;
    in >> i >> j >> v;
    A(i - 1, j - 1) += v;
  }
  return A;
}

/// A CSV file as rows of numbers (header dropped).
std::vector<std::vector<double>> read_csv(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

/// The exported model of a paper scene, read back.
struct Exported {
  json doc;
  Eigen::MatrixXd M, K;
  std::vector<std::vector<double>> dofs, state;
  fs::path dir;

  /// A displacement vector: `value` on component c (0 x, 1 y) of every node of body b listed in
  /// dofs.csv (rod layout: c = 0 is along the axis), plus theta * (rotation mode about the origin).
  Eigen::VectorXd mode(int b, int c, double value, double theta = 0.0) const {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(M.rows());
    for (const auto& r : dofs) {
      if (static_cast<int>(r[0]) != b) continue;
      const double x = r[2], y = r[3];
      const double comp[3] = {(c == 0 ? value : 0.0) - theta * y, (c == 1 ? value : 0.0) + theta * x, theta};
      for (int k = 0; k < 3; ++k)
        if (r[4 + k] >= 0) u(static_cast<int>(r[4 + k])) = comp[k];
    }
    return u;
  }
  /// The gap of contact k at displacement u from its exported normal row.
  double gap(int k, const Eigen::VectorXd& u) const {
    const json& c = doc["contacts"][k];
    double g = c["g0"].get<double>();
    for (const auto& term : c["rows"]["normal"]) g += term[1].get<double>() * u(term[0].get<int>());
    return g;
  }
};

Exported export_scene(const std::string& name, const std::vector<std::string>& sets, const std::string& tag) {
  Exported e;
  e.dir = testing::temp_path(tag);
  e.doc = export_model(testing::load_paper_scene(name, sets), e.dir);
  std::ifstream in(e.dir / "model.json");
  EXPECT_EQ(json::parse(in), e.doc);  // the file holds what was returned
  e.M = read_mtx(e.dir / "M.mtx");
  e.K = read_mtx(e.dir / "K.mtx");
  e.dofs = read_csv(e.dir / "dofs.csv");
  e.state = read_csv(e.dir / "initial_state.csv");
  return e;
}

TEST(ModelExport, CentralRodsMassStiffnessAndGap) {
  const Exported e = export_scene("s1_central", {}, "s1");
  EXPECT_EQ(e.doc["layout"], "rod");  // all collinear: 1 DOF per node, 11 per body
  ASSERT_EQ(e.M.rows(), 22);
  for (int b = 0; b < 2; ++b) {
    const Eigen::VectorXd one = e.mode(b, 0, 1.0);
    // Mass of a body = rho A L = 1 * 0.4 * 10 kg; a translation strains nothing.
    EXPECT_NEAR(one.dot(e.M * one), 4.0, 1e-12);
    EXPECT_LT((e.K * one).norm(), 1e-12 * e.K.norm());
  }
  // Moving A 0.5 m along +x closes the 0.5 m gap to B's start.
  EXPECT_NEAR(e.gap(0, Eigen::VectorXd::Zero(22)), 0.5, 1e-15);
  EXPECT_NEAR(e.gap(0, e.mode(0, 0, 0.5)), 0.0, 1e-14);
  EXPECT_NEAR(e.gap(0, e.mode(1, 0, -0.5)), 0.0, 1e-14);
  EXPECT_EQ(e.doc["contacts"][0]["kind"], "end_to_end");
  // Initial velocity: A at 1 m/s, B at rest; A's momentum 4 kg m/s through its covector.
  Eigen::VectorXd v0(22);
  for (const auto& r : e.state) v0(static_cast<int>(r[0])) = r[2];
  EXPECT_NEAR(v0.dot(e.mode(0, 0, 1.0)), 11.0, 1e-15);  // 11 nodes at 1 m/s
  EXPECT_NEAR(v0.dot(e.M * e.mode(0, 0, 1.0)), 4.0, 1e-12);
  EXPECT_EQ(e.doc["time"]["dt"], 0.01);
  EXPECT_EQ(e.doc["time"]["end"], 4.0);
}

// Gravity's load is each body's weight: e_y^T F = -m g for the bar (rho A L = 10 kg, g = 10
// m/s^2 down), none along x; the immovable ground carries no equation. A scene without loads
// exports F = 0 (S1 above has none).
TEST(ModelExport, GravityLoadIsTheWeightOfTheBar) {
  Exported e;
  e.dir = testing::temp_path("bouncing_bar");
  e.doc = export_model(load_scene(testing::source_dir() / "verification/scenes/benchmarks/bouncing_bar.toml"),
                       e.dir);
  e.M = read_mtx(e.dir / "M.mtx");
  e.dofs = read_csv(e.dir / "dofs.csv");
  Eigen::VectorXd F = Eigen::VectorXd::Zero(e.M.rows());
  for (const auto& r : read_csv(e.dir / "load.csv")) F(static_cast<int>(r[0])) = r[1];
  // The bar is vertical: the rod layout's axis is y, so mode(0, 0, .) moves it along its axis.
  ASSERT_EQ(e.doc["layout"], "rod");
  const double g_along_axis = -10.0 * e.doc["rod_axis"][1].get<double>();  // g . axis, m/s^2
  EXPECT_NEAR(F.dot(e.mode(0, 0, 1.0)), 10.0 * g_along_axis, 1e-12);
  const Exported s1 = export_scene("s1_central", {}, "s1_load");
  EXPECT_EQ(read_csv(s1.dir / "load.csv").size(), static_cast<std::size_t>(s1.M.rows()));
  for (const auto& r : read_csv(s1.dir / "load.csv")) EXPECT_EQ(r[1], 0.0);
}

TEST(ModelExport, FreeRodFirstFrequencyIsPiCOverL) {
  // A free-free rod's first elastic mode: omega = pi c / L, c = sqrt(E / rho) = 10 m/s, L = 10 m.
  // Lumped mass on N elements: omega_1 = (2 c / le) sin(pi / (2 N)), relative error
  // (pi / 2N)^2 / 6 = 1.6e-4 for N = 50: the tolerance is twice that.
  const Exported e = export_scene("s1_central", {"bodies.A.elements=50"}, "s1_50");
  std::vector<int> eqs;
  for (const auto& r : e.dofs)
    if (r[0] == 0) eqs.push_back(static_cast<int>(r[4]));
  ASSERT_EQ(eqs.size(), 51u);
  Eigen::MatrixXd KA(51, 51), MA(51, 51);
  for (int i = 0; i < 51; ++i)
    for (int j = 0; j < 51; ++j) KA(i, j) = e.K(eqs[i], eqs[j]), MA(i, j) = e.M(eqs[i], eqs[j]);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(KA, MA);
  const double pi = std::acos(-1.0);
  EXPECT_NEAR(eig.eigenvalues()(0), 0.0, 1e-9);  // the rigid translation
  EXPECT_NEAR(std::sqrt(eig.eigenvalues()(1)) / pi, 1.0, 3.2e-4);
}

TEST(ModelExport, ConsistentMassKeepsTotalMass) {
  // Any consistent element mass integrates rho A over the element: a translation sees rho A L.
  const Exported e = export_scene("s1_central", {"model.mass=\"consistent\""}, "s1_consistent");
  EXPECT_EQ(e.doc["mass"], "consistent");
  const Eigen::VectorXd one = e.mode(1, 0, 1.0);
  EXPECT_NEAR(one.dot(e.M * one), 4.0, 1e-12);
  EXPECT_GT((e.M - Eigen::MatrixXd(e.M.diagonal().asDiagonal())).norm(), 0.1);  // not lumped
}

TEST(ModelExport, TransverseFrameRigidModesAndNodeToNodeGap) {
  const Exported e = export_scene("s2_transverse", {}, "s2");
  EXPECT_EQ(e.doc["layout"], "frame");
  // A: free, vertical, 5 m, rho A L = 2 kg in x and in y; its three rigid-body modes strain nothing.
  for (int c = 0; c < 2; ++c) {
    const Eigen::VectorXd u = e.mode(0, c, 1.0);
    EXPECT_NEAR(u.dot(e.M * u), 2.0, 1e-12);
    EXPECT_LT((e.K * u).norm(), 1e-12 * e.K.norm());
  }
  EXPECT_LT((e.K * e.mode(0, 0, 0.0, 0.3)).norm(), 1e-12 * e.K.norm());
  // A's lower end hangs 0.1 m above B's midspan node: lowering A by 0.1 m closes the gap.
  const json& c = e.doc["contacts"][0];
  EXPECT_EQ(c["kind"], "node_to_node");
  EXPECT_NEAR(c["g0"].get<double>(), 0.1, 1e-12);
  EXPECT_NEAR(e.gap(0, e.mode(0, 1, -0.1)), 0.0, 1e-12);
}

TEST(ModelExport, MidElementStrikeSplitsTheTargetHalfAndHalf) {
  // S3 with 10 elements: the striker faces the middle of B's element 4 (x = 4.5).
  const Exported e = export_scene("s3_surface_10", {}, "s3");
  const json& c = e.doc["contacts"][0];
  EXPECT_EQ(c["kind"], "node_to_surface");
  EXPECT_NEAR(c["xi1"].get<double>(), 0.5, 1e-12);
  // Raising B's two nodes of that element by 0.1 m closes the 0.1 m gap; raising one by 0.1 m
  // closes half of it (linear interpolation between the nodes).
  Eigen::VectorXd u = Eigen::VectorXd::Zero(e.M.rows());
  for (const auto& r : e.dofs)
    if (r[0] == 1 && (r[1] == 4 || r[1] == 5)) u(static_cast<int>(r[5])) = 0.1;
  EXPECT_NEAR(e.gap(0, u), 0.0, 1e-12);
  for (const auto& r : e.dofs)
    if (r[0] == 1 && r[1] == 5) u(static_cast<int>(r[5])) = 0.0;
  EXPECT_NEAR(e.gap(0, u), 0.05, 1e-12);
}

TEST(ModelExport, RigidRodMassInertiaAndLeverArm) {
  // A rigid rod of 1 m and 1 kg (rho A L) at 30 deg: its centre's DOFs carry m = 1 kg along x and
  // y and J = m L^2 / 12 about the centre; the immovable surface has no equations.
  Exported e;
  e.dir = testing::temp_path("rigid");
  e.doc = export_model(load_scene(testing::source_dir() / "verification/scenes/extra/rigid_rod_oblique.toml"),
                       e.dir);
  e.M = read_mtx(e.dir / "M.mtx");
  e.dofs = read_csv(e.dir / "dofs.csv");
  ASSERT_EQ(e.dofs.size(), 2u);  // one row per rigid body: its centre (node -1)
  const auto& a = e.dofs[0];
  EXPECT_EQ(a[1], -1.0);
  EXPECT_NEAR(a[2], 0.8660254037844387 / 2, 1e-15);
  for (int k = 4; k < 7; ++k) EXPECT_GE(a[k], 0.0);
  for (int k = 4; k < 7; ++k) EXPECT_EQ(e.dofs[1][k], -1.0);  // immovable
  const int ex = static_cast<int>(a[4]), ey = static_cast<int>(a[5]), et = static_cast<int>(a[6]);
  EXPECT_NEAR(e.M(ex, ex), 1.0, 1e-12);
  EXPECT_NEAR(e.M(ey, ey), 1.0, 1e-12);
  EXPECT_NEAR(e.M(et, et), 1.0 / 12.0, 1e-12);
  // The lower end sits 0.01 m above the surface, 0.5 m from the centre along the rod: lowering the
  // centre by 0.01 m closes the gap, and so does turning by theta with 0.01 = theta * 0.5 cos 30.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(e.M.rows());
  u(ey) = -0.01;
  EXPECT_NEAR(e.gap(0, u), 0.0, 1e-12);
  u.setZero();
  u(et) = 0.01 / (0.5 * std::cos(std::acos(-1.0) / 6));
  EXPECT_NEAR(e.gap(0, u), 0.0, 1e-12);
}

// A Timoshenko body's exported K is the Timoshenko element's: B of S2 (simply supported, L = 10 m,
// E = 100 N/m^2, I = 0.4^3/12 m^4, A = 0.4 m^2) under a unit load at midspan deflects
// P L^3 / (48 E I) + P L / (4 kappa G A) (kappa 5/6, G = E / (2 (1 + 0.3))): 39.0625 + 0.195 m.
// The interdependent-interpolation element is exact for nodal loads, so only the solve's
// roundoff separates the two (1e-9 relative); the Euler-Bernoulli export gives 39.0625 m.
double midspan_deflection(const Exported& e) {
  std::vector<int> eqs;
  int mid = -1;
  for (const auto& r : e.dofs)
    if (r[0] == 1)
      for (int k = 4; k < 7; ++k)
        if (r[k] >= 0) {
          if (r[1] == 5 && k == 5) mid = static_cast<int>(eqs.size());
          eqs.push_back(static_cast<int>(r[k]));
        }
  const int n = static_cast<int>(eqs.size());
  Eigen::MatrixXd KB(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) KB(i, j) = e.K(eqs[i], eqs[j]);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  f(mid) = -1.0;  // N, downwards
  return -KB.ldlt().solve(f)(mid);
}

TEST(ModelExport, TimoshenkoBodyExportsItsShearFlexibility) {
  const double L = 10.0, E = 100.0, I = 0.0053333333333333, A = 0.4, G = E / (2.0 * 1.3);
  const double bending = L * L * L / (48.0 * E * I), shear = L / (4.0 * 5.0 / 6.0 * G * A);
  const Exported eb = export_scene("s2_transverse", {}, "s2_eb");
  EXPECT_EQ(eb.doc["bodies"][1]["theory"], "euler-bernoulli");
  EXPECT_NEAR(midspan_deflection(eb), bending, 1e-9 * bending);
  const Exported t = export_scene("s2_transverse", {"bodies.B.theory=timoshenko"}, "s2_timoshenko");
  EXPECT_EQ(t.doc["bodies"][1]["theory"], "timoshenko");
  EXPECT_NEAR(t.doc["bodies"][1]["shear_coefficient"].get<double>(), 5.0 / 6.0, 1e-15);
  EXPECT_NEAR(t.doc["bodies"][1]["poisson"].get<double>(), 0.3, 1e-15);
  EXPECT_NEAR(midspan_deflection(t), bending + shear, 1e-9 * (bending + shear));
}

// The exported contact rows are the hard law's (gap >= 0, no spring): a Hertz contact is refused
// naming the scene file and contacts[k].law, and no model.json is left behind.
TEST(ModelExport, RefusesTheHertzLawNamingFileAndKey) {
  const fs::path dir = testing::temp_path("refused_hertz");
  export_model(testing::load_paper_scene("s2_transverse"), dir);
  ASSERT_TRUE(fs::exists(dir / "model.json"));
  const Scene hertz =
      testing::load_paper_scene("s2_transverse", {"contacts[0].law=hertz", "contacts[0].stiffness=50"});
  try {
    export_model(hertz, dir);
    FAIL() << "a Hertz contact was exported as hard contact rows";
  } catch (const InputError& err) {
    EXPECT_EQ(err.key(), "contacts[0].law");
    EXPECT_NE(std::string(err.what()).find("s2_transverse.toml"), std::string::npos) << err.what();
    EXPECT_NE(std::string(err.what()).find("hard law"), std::string::npos) << err.what();
  }
  EXPECT_FALSE(fs::exists(dir / "model.json"));
}

TEST(ModelExport, RefusesWhatItCannotWriteOnceAndLeavesNoModelJson) {
  const fs::path dir = testing::temp_path("refused");
  export_model(testing::load_paper_scene("s1_central"), dir);
  ASSERT_TRUE(fs::exists(dir / "model.json"));
  const Scene corot = load_scene(testing::hard_scene("rotation_corotational"));
  try {
    export_model(corot, dir);
    FAIL() << "a corotational scene was exported";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("model.kinematics"), std::string::npos) << err.what();
  }
  EXPECT_FALSE(fs::exists(dir / "model.json"));  // the earlier export no longer vouches for anything
  EXPECT_THROW(export_model(testing::load_paper_scene("s2_transverse", {"contacts[0].node=\"all\""}), dir),
               InputError);
}

// S2 rotated by 37 degrees with the target's roller across it exports a rotation of S2's model:
// the same frequencies (a rigid rotation strains nothing), the roller node's translations along
// and across the target (dofs.csv axis_x, axis_y: the target's axis; eq_y, across, held), and a
// gap row that lowering A by 0.1 m along its velocity closes. Tolerances: roundoff of the rotated
// coordinates and of the dense eigen-solve (1e-9 of the largest omega^2), 1e-12 m on the gap.
TEST(ModelExport, RotatedCopyWithABodyAxisRollerIsARotationOfS2) {
  const Exported s2 = export_scene("s2_transverse", {}, "s2_frequencies");
  Exported e;
  e.dir = testing::temp_path("s2_rotated");
  e.doc =
      export_model(load_scene(testing::source_dir() / "verification/scenes/extra/s2_rotated_37.toml"), e.dir);
  e.M = read_mtx(e.dir / "M.mtx");
  e.K = read_mtx(e.dir / "K.mtx");
  e.dofs = read_csv(e.dir / "dofs.csv");
  ASSERT_EQ(e.M.rows(), s2.M.rows());
  const Eigen::VectorXd w2 =
      Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(s2.K, s2.M).eigenvalues();
  const Eigen::VectorXd w = Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(e.K, e.M).eigenvalues();
  EXPECT_LT((w - w2).cwiseAbs().maxCoeff(), 1e-9 * w2.maxCoeff());
  const double c = std::cos(37.0 * M_PI / 180.0), s = std::sin(37.0 * M_PI / 180.0);
  for (const auto& r : e.dofs) {
    const bool roller = r[0] == 1 && r[1] == 10;
    EXPECT_NEAR(r[7], roller ? c : 1.0, 1e-15) << r[0] << " " << r[1];
    EXPECT_NEAR(r[8], roller ? s : 0.0, 1e-15) << r[0] << " " << r[1];
    if (roller) {
      EXPECT_TRUE(r[4] >= 0 && r[5] == -1 && r[6] >= 0);
    }
  }
  const Eigen::VectorXd lower = e.mode(0, 0, 0.1 * s) + e.mode(0, 1, -0.1 * c);  // 0.1 m along (s, -c)
  EXPECT_NEAR(e.gap(0, Eigen::VectorXd::Zero(e.M.rows())), 0.1, 1e-12);
  EXPECT_NEAR(e.gap(0, lower), 0.0, 1e-12);
  EXPECT_EQ(e.doc["format_version"], 2);
}

}  // namespace
}  // namespace beamimpact
