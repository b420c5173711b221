// The field output's section forces (axial_force, bending_moment) and the element end forces they
// come from (InternalForce::end_forces), node by node and element by element, against closed-form
// beam theory, for every beam theory: Euler-Bernoulli frames (linear and corotational
// kinematics), Timoshenko frames, and axial rods.
//
// A cantilever of length L clamped at s = 0 carries a tip force P across its axis, and an axial
// stretch u(s) = e0 s + c s^2 is added. Beam theory gives the exact fields (Timoshenko 1921;
// Euler-Bernoulli the limit kappa G A -> infinity):
//   M(s) = P (L - s)                 (sagging positive: M = EI psi', psi the section's rotation)
//   psi(s) = P (L s - s^2 / 2) / EI
//   v(s) = P (L s^2 / 2 - s^3 / 6) / EI + P s / (kappa G A)
//   shear V = kappa G A (v' - psi) = P, and N = EA u' on a bar element: EA (u_b - u_a) / l.
// Both the Hermite element and the Timoshenko element on the interdependent interpolation are
// exact for end loads, so the fields written at the exact nodal displacements must give M(s)
// at every node (the moment varies by P h between neighbours: a value written for another node,
// or one end's moment given to the other, fails), V = P in every element, and the axial force
// of each element averaged over the elements meeting at a node (FieldWriter's convention).
#include <solver/record/FieldWriter.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include <solver/integrator/InternalForce.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact {
namespace {

using testing::temp_path;

// The stocky section of verification/scenes/extra/s2_stocky_timoshenko.toml: 1 m x 1 m, E = 100,
// kappa = 5/6, nu = 0 (G = E / 2). With 1 m elements the Timoshenko shear parameter is
// phi = 12 EI / (kappa G A l^2) = 2.4: shear matters as much as bending.
constexpr double kE = 100.0, kA = 1.0, kI = 1.0 / 12.0, kKappa = 5.0 / 6.0, kG = kE / 2.0;
constexpr double kL = 4.0, kP = 1e-6;    // m, N: rotations of order 1e-6 rad (small-strain range)
constexpr double kE0 = 1e-6, kC = 1e-7;  // axial strain e0 (-) and its gradient 2 c (1/m)
constexpr int kElements = 4;

/// A cantilever "beam" of kElements elements at `degrees` to the x axis, clamped at its start,
/// and a far, fixed body for the one contact a scene needs.
std::string cantilever(const std::string& theory, const std::string& kinematics, double degrees) {
  const double c = std::cos(degrees * M_PI / 180.0), s = std::sin(degrees * M_PI / 180.0);
  std::ostringstream t;
  t.precision(17);
  t << "name = \"cantilever\"\n[time]\ndt = 0.001\nend = 0.01\n[model]\nkinematics = \"" << kinematics
    << "\"\n[[bodies]]\nname = \"beam\"\nstart = [0.0, 0.0]\nend = [" << kL * c << ", " << kL * s
    << "]\nelements = " << kElements << "\nE = " << kE << "\nrho = 1.0\narea = " << kA << "\ninertia = " << kI
    << "\n";
  if (theory == "timoshenko")
    t << "theory = \"timoshenko\"\nshear_coefficient = " << kKappa << "\npoisson = 0.0\n";
  t << "supports = [{ at = \"start\", fix = [\"x\", \"y\", \"theta\"] }]\n"
    << "[[bodies]]\nname = \"far\"\nstart = [0.0, -10.0]\nend = [4.0, -10.0]\nelements = 1\nE = 100.0\n"
       "rho = 1.0\narea = 1.0\ninertia = 0.01\nsupports = [{ at = \"start\", fix = [\"x\", \"y\", \"theta\"] "
       "}]\n"
       "[[contacts]]\nstriker = \"beam\"\nnode = \"end\"\ntarget = \"far\"\n";
  return t.str();
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The numbers of the DataArray `name` of a .vtu text (ASCII).
std::vector<double> array(const std::string& vtu, const std::string& name) {
  const auto tag = vtu.find("Name=\"" + name + "\"");
  EXPECT_NE(tag, std::string::npos) << name;
  const auto begin = vtu.find('>', tag) + 1, end = vtu.find("</DataArray>", begin);
  std::istringstream in(vtu.substr(begin, end - begin));
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

/// The closed-form fields at arc length s: axial u, transverse v, section rotation psi.
struct Exact {
  bool shear;  ///< Timoshenko: the shear deflection P s / (kappa G A)
  double u(double s) const { return kE0 * s + kC * s * s; }
  double v(double s) const {
    const double EI = kE * kI;
    return kP * (kL * s * s / 2.0 - s * s * s / 6.0) / EI + (shear ? kP * s / (kKappa * kG * kA) : 0.0);
  }
  double psi(double s) const { return kP * (kL * s - s * s / 2.0) / (kE * kI); }
  double moment(double s) const { return kP * (kL - s); }
  /// The bar element's axial force between s_a and s_b: EA (u_b - u_a) / (s_b - s_a).
  double bar(double sa, double sb) const { return kE * kA * (u(sb) - u(sa)) / (sb - sa); }
};

/// The field file of one row at U (ASCII, double: values read back as written).
std::string fields_at(const Model& model, const Eigen::VectorXd& U,
                      const std::vector<std::array<double, 3>>& ends, const std::string& name) {
  const auto dir = temp_path(name);
  {
    FieldWriter w(model, dir, FieldFormat::kAscii, FieldPrecision::kDouble);
    w.write(0.0, U, Eigen::VectorXd::Zero(U.size()),
            std::vector<Vec2>(static_cast<std::size_t>(model.num_nodes()), Vec2{0.0, 0.0}), ends);
    w.finish();
  }
  return read(dir / "fields/step_000000.vtu");
}

/// Checks the cantilever of `theory` and `kinematics` at `degrees`; tol: relative to P L (moments)
/// and to EA e0 (axial forces).
void check_cantilever(const std::string& theory, const std::string& kinematics, double degrees, double tol) {
  SCOPED_TRACE(theory + " " + kinematics + " at " + std::to_string(degrees) + " deg");
  const Scene scene = load_scene_text(cantilever(theory, kinematics, degrees), "cantilever.toml");
  const Model model(scene, true);
  const bool corot = kinematics == "corotational";
  const paper::InternalForce fint(model, {corot, false});
  const Exact x{theory == "timoshenko"};
  const double c = std::cos(degrees * M_PI / 180.0), sn = std::sin(degrees * M_PI / 180.0);
  const double h = kL / kElements;
  Eigen::VectorXd U = Eigen::VectorXd::Zero(model.size());
  for (int i = 0; i <= kElements; ++i) {
    const double s = i * h, u = x.u(s), v = x.v(s);
    const double values[3] = {c * u - sn * v, sn * u + c * v, x.psi(s)};
    const int n = model.node_id(0, i);
    for (int k = 0; k < 3; ++k)
      if (const int q = model.equation(n, k); q >= 0) U(q) = values[k];
  }
  std::vector<std::array<double, 3>> ends;
  fint.end_forces(U, ends);
  ASSERT_EQ(ends.size(), static_cast<std::size_t>(kElements + 1));
  const double m_scale = kP * kL, n_scale = kE * kA * kE0;
  for (int e = 0; e < kElements; ++e) {
    const auto [N, M1, M2] = ends[static_cast<std::size_t>(e)];
    const double sa = e * h, sb = sa + h;
    // The element exerts M1 on its first node's rotation: the section moment there is -M1.
    EXPECT_NEAR(-M1, x.moment(sa), tol * m_scale) << "element " << e << " first end";
    EXPECT_NEAR(M2, x.moment(sb), tol * m_scale) << "element " << e << " second end";
    // Shear by the element's moment equilibrium (no load along it): V = -(M1 + M2) / l = P.
    EXPECT_NEAR(-(M1 + M2) / h, kP, tol * kP) << "element " << e << " shear";
    EXPECT_NEAR(N, x.bar(sa, sb), tol * n_scale) << "element " << e << " axial";
  }
  const std::string vtu = fields_at(model, U, ends, theory + kinematics + std::to_string(int(degrees)));
  const std::vector<double> N = array(vtu, "axial_force"), M = array(vtu, "bending_moment");
  ASSERT_EQ(M.size(), static_cast<std::size_t>(model.num_nodes()));
  ASSERT_EQ(N.size(), M.size());
  for (int i = 0; i <= kElements; ++i) {
    const int n = model.node_id(0, i);
    const double s = i * h;
    EXPECT_NEAR(M[n], x.moment(s), tol * m_scale) << "node " << i;
    // The bar forces of the elements meeting at the node, averaged.
    const double left = i > 0 ? x.bar(s - h, s) : 0.0, right = i < kElements ? x.bar(s, s + h) : 0.0;
    const double expected = (i == 0 || i == kElements) ? left + right : 0.5 * (left + right);
    EXPECT_NEAR(N[n], expected, tol * n_scale) << "node " << i;
  }
  for (int i = 0; i <= 1; ++i) {  // the unloaded far body: nothing
    EXPECT_EQ(M[model.node_id(1, i)], 0.0);
    EXPECT_EQ(N[model.node_id(1, i)], 0.0);
  }
}

// Linear kinematics: both elements are exact, so only the double's rounding remains (values of
// 1e-6 formed from displacements of 1e-6 m: relative 1e-9 is far above it).
TEST(FieldSectionForces, EulerBernoulliCantileverIsBeamTheoryAtEveryNode) {
  for (double deg : {0.0, 30.0}) check_cantilever("euler-bernoulli", "linear", deg, 1e-9);
}

// phi = 2.4: a moment without the 1 / (1 + phi) of the Timoshenko element is 3.4 times too
// large; one with the Euler-Bernoulli split (4, 2) instead of (4 + phi, 2 - phi) misses the shear
// deflection P s / (kappa G A) and is wrong at every node.
TEST(FieldSectionForces, TimoshenkoCantileverIsBeamTheoryAtEveryNode) {
  for (double deg : {0.0, 30.0}) check_cantilever("timoshenko", "linear", deg, 1e-9);
}

// The corotational element measures the stretch and the end rotations from the current chord,
// which turns by alpha (1 - e) where the linear theory has alpha (e = 2e-6 the stretch, alpha =
// 1e-6 rad the chord's turn): each end rotation is off by e alpha = 2e-12 rad, the moments by
// 6 EI / l x 2e-12 = 1e-10 N m (2.5e-5 of P L) and the shear by 1e-10 N (1.6e-4 of P measured);
// the stretch is off by the chord's turn squared (1e-12 of 1e-6). Relative 1e-3 covers these; a
// value of the wrong node is off by P h = 0.25 P L.
TEST(FieldSectionForces, CorotationalCantileverIsBeamTheoryAtEveryNode) {
  for (double deg : {0.0, 30.0}) check_cantilever("euler-bernoulli", "corotational", deg, 1e-3);
}

// S1's rods (the rod layout: one axial DOF per node, no moments): u(s) = c s^2 along each rod
// gives each element N = EA c (s_a + s_b) (the linear bar) and each node the mean of its
// elements': a force that grows along the rod, so a value written for another node fails.
TEST(FieldSectionForces, RodsCarryTheBarForceOfTheirElements) {
  const Scene scene = testing::load_paper_scene("s1_central");
  const Model model(scene, false);
  ASSERT_EQ(model.dofs_per_node(), 1);
  const paper::InternalForce fint(model, std::vector<bool>(model.num_bodies(), false));
  const double c = 1e-3, EA = 100.0 * 0.4, h = 1.0;  // 1/m; N; m (10 m rods, 10 elements)
  Eigen::VectorXd U = Eigen::VectorXd::Zero(model.size());
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i <= 10; ++i)
      if (const int q = model.equation(model.node_id(b, i), 0); q >= 0) U(q) = (b + 1) * c * i * i;
  std::vector<std::array<double, 3>> ends;
  fint.end_forces(U, ends);
  ASSERT_EQ(ends.size(), 20u);
  auto bar = [&](int b, int e) { return EA * (b + 1) * c * (2 * e + 1) * h; };  // EA c (s_a + s_b)
  for (int b = 0; b < 2; ++b)
    for (int e = 0; e < 10; ++e) {
      const auto [N, M1, M2] = ends[static_cast<std::size_t>(10 * b + e)];
      EXPECT_NEAR(N, bar(b, e), 1e-12 * EA) << "body " << b << " element " << e;
      EXPECT_EQ(M1, 0.0);
      EXPECT_EQ(M2, 0.0);
    }
  const std::string vtu = fields_at(model, U, ends, "rods");
  const std::vector<double> N = array(vtu, "axial_force"), M = array(vtu, "bending_moment");
  ASSERT_EQ(N.size(), 22u);
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i <= 10; ++i) {
      const int n = model.node_id(b, i);
      const double expected = i == 0 ? bar(b, 0) : i == 10 ? bar(b, 9) : 0.5 * (bar(b, i - 1) + bar(b, i));
      EXPECT_NEAR(N[n], expected, 1e-12 * EA) << "body " << b << " node " << i;
      EXPECT_EQ(M[n], 0.0) << "body " << b << " node " << i;
    }
}

}  // namespace
}  // namespace beamimpact
