// The Timoshenko frame element against Timoshenko beam theory: the cantilever's tip deflection
// P L^3 / (3 E I) + P L / (kappa G A) (exact at the nodes for this interpolation, any mesh), the
// simply supported beam's two frequency branches from the Timoshenko frequency equation, the
// Euler-Bernoulli limit as the beam gets slender, and the critical step's bound above the
// assembled model's true top eigenvalue.
#include <solver/model/timoshenko_element.hpp>

#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include <solver/model/Model.hpp>
#include <solver/model/critical_dt.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

constexpr double kE = 2.0e11, kRho = 7800.0, kNu = 0.3, kKappa = 5.0 / 6.0, kL = 1.0, kB = 0.02;

/// A steel beam of length kL along x with a b x h rectangular section.
Body beam(double h, int elements, BeamTheory theory) {
  Body b;
  b.name = "beam";
  b.start = {0.0, 0.0};
  b.end = {kL, 0.0};
  b.elements = elements;
  b.E = kE;
  b.rho = kRho;
  b.area = kB * h;
  b.inertia = kB * h * h * h / 12.0;
  b.theory = theory;
  b.shear_coefficient = kKappa;
  b.poisson = kNu;
  return b;
}

Scene scene_of(const Body& b, MassKind mass) {
  Scene s;
  s.file = "test";
  s.bodies = {b};
  s.model.mass = mass;
  return s;
}

double shear_stiffness(const Body& b) { return kKappa * kE / (2.0 * (1.0 + kNu)) * b.area; }  // kappa G A (N)

/// Tip deflection and rotation of a cantilever (start clamped) under a transverse tip force P.
std::array<double, 2> cantilever_tip(const Body& body, double P) {
  Body b = body;
  b.supports = {{0, true, true, true}};
  const Model m(scene_of(b, MassKind::kLumped), true);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.size());
  const int tip = m.node_id(0, b.elements);
  f(m.equation(tip, 1)) = P;
  const Eigen::VectorXd u = Eigen::MatrixXd(m.K()).ldlt().solve(f);
  return {u(m.equation(tip, 1)), u(m.equation(tip, 2))};
}

TEST(TimoshenkoElement, CantileverTipDeflectionIsExactOnAnyMesh) {
  // The interdependent interpolation solves the static Timoshenko equations on each element, so
  // the nodal values are exact: tolerance 1e-9 is the roundoff of the solve (condition ~1e8).
  const double P = 1000.0;
  for (double h : {0.01, 0.1, 0.3})
    for (int ne : {1, 3, 8}) {
      const Body b = beam(h, ne, BeamTheory::kTimoshenko);
      const double ei = kE * b.inertia;
      const auto [v, th] = cantilever_tip(b, P);
      const double exact = P * kL * kL * kL / (3 * ei) + P * kL / shear_stiffness(b);
      EXPECT_NEAR(v, exact, 1e-9 * exact) << "h " << h << " elements " << ne;
      EXPECT_NEAR(th, P * kL * kL / (2 * ei),
                  1e-9 * P * kL * kL / (2 * ei));  // shear does not turn the section
    }
}

TEST(TimoshenkoElement, ReducesToEulerBernoulliAsTheBeamGetsSlender) {
  // Tip deflections differ by the shear term: (T - EB) / EB = 3 E I / (kappa G A L^2), which
  // vanishes as (h / L)^2; no locking: one element of a beam with L / h = 1e4 is still exact.
  const double P = 1.0;
  for (double h : {0.3, 0.03, 1e-4}) {
    const double t = cantilever_tip(beam(h, 1, BeamTheory::kTimoshenko), P)[0];
    const Body e = beam(h, 1, BeamTheory::kEulerBernoulli);
    const double eb = cantilever_tip(e, P)[0];
    const double expected = 3 * kE * e.inertia / (shear_stiffness(e) * kL * kL);
    EXPECT_NEAR((t - eb) / eb, expected, 1e-7 * expected + 1e-12) << "h " << h;
  }
  // The element matrices themselves approach the Hermite ones at rate phi: the largest change
  // is in the 12 E I / L^3 entries, 12 E I / L^3 (1 - 1 / (1 + phi)) < 12 E I phi / L^3.
  const double phi = shear_parameter(1e-9, 1e-3, 1.0, kKappa, kNu);
  const Mat6 dk =
      timoshenko_stiffness_local(kE, 1e-3, 1e-9, 1.0, phi) - frame_stiffness_local(kE, 1e-3, 1e-9, 1.0);
  EXPECT_LT(dk.cwiseAbs().maxCoeff(), 12 * kE * 1e-9 * phi);
  EXPECT_GT(dk.cwiseAbs().maxCoeff(), 0.5 * 12 * kE * 1e-9 * phi);  // and it is that change
}

/// The Timoshenko simply supported beam's frequencies of wavenumber k = n pi / L: the two roots
/// omega^2 of (kGA k^2 - rho A w^2)(E I k^2 + kGA - rho I w^2) = (kGA k)^2 (from w = W sin kx,
/// psi = Psi cos kx in the two field equations), lower (bending) branch first.
std::array<double, 2> timoshenko_ss_omegas(const Body& b, int n) {
  const double k = n * M_PI / kL, s = shear_stiffness(b), ra = kRho * b.area, ri = kRho * b.inertia;
  const double a = ra * ri, bb = -(ra * (kE * b.inertia * k * k + s) + ri * s * k * k);
  const double c = s * k * k * kE * b.inertia * k * k;
  const double disc = std::sqrt(bb * bb - 4 * a * c);
  return {std::sqrt((-bb - disc) / (2 * a)), std::sqrt((-bb + disc) / (2 * a))};
}

/// Sorted omegas of a simply supported beam, axial motion held (only transverse modes remain).
Eigen::VectorXd ss_omegas(const Body& body, MassKind mass) {
  Body b = body;
  for (int i = 0; i <= b.elements; ++i) b.supports.push_back({i, true, i == 0 || i == b.elements, false});
  const Model m(scene_of(b, mass), true);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(m.K()),
                                                               Eigen::MatrixXd(m.M()));
  return es.eigenvalues().cwiseSqrt();
}

double nearest_relative(const Eigen::VectorXd& w, double target) {
  return (w.array() - target).abs().minCoeff() / target;
}

TEST(TimoshenkoElement, SimplySupportedFrequenciesMatchBothBranches) {
  // A stocky beam (L / h = 5): modes 1..3 of both branches. The interdependent element's
  // constant shear strain makes it converge as le^2 in frequency (the ratio check: halving the
  // mesh divides the error by 3..5); at 64 elements the error is below 3e-3 (observed 2.4e-3 for
  // the shear branch of mode 3, the largest).
  const double h = 0.2;
  for (int n = 1; n <= 3; ++n) {
    const auto exact = timoshenko_ss_omegas(beam(h, 64, BeamTheory::kTimoshenko), n);
    const Eigen::VectorXd w64 = ss_omegas(beam(h, 64, BeamTheory::kTimoshenko), MassKind::kConsistent);
    const Eigen::VectorXd w32 = ss_omegas(beam(h, 32, BeamTheory::kTimoshenko), MassKind::kConsistent);
    for (int br = 0; br < 2; ++br) {
      const double e64 = nearest_relative(w64, exact[br]), e32 = nearest_relative(w32, exact[br]);
      EXPECT_LT(e64, 3e-3) << "mode " << n << " branch " << br;
      EXPECT_GT(e32 / e64, 3.0) << "mode " << n << " branch " << br;
      EXPECT_LT(e32 / e64, 5.0) << "mode " << n << " branch " << br;
    }
  }
  // The Euler-Bernoulli element misses the shear branch and overestimates the first bending mode
  // of this stocky beam by the shear and rotary-inertia correction (~ 6 % at L / h = 5).
  const Body eb = beam(h, 64, BeamTheory::kEulerBernoulli);
  const double w1_eb = ss_omegas(eb, MassKind::kConsistent)(0);
  const double w1_t = timoshenko_ss_omegas(eb, 1)[0];
  EXPECT_GT(w1_eb / w1_t - 1.0, 0.03);
}

TEST(TimoshenkoElement, LumpedMassConvergesToTheBendingBranch) {
  // Lumped mass (m/2 and rho I le / 2 per node): the first bending mode within 1e-3 at 64
  // elements (le^2 error of the lumped element).
  for (double h : {0.2, 0.02}) {
    const double exact = timoshenko_ss_omegas(beam(h, 64, BeamTheory::kTimoshenko), 1)[0];
    const double w = ss_omegas(beam(h, 64, BeamTheory::kTimoshenko), MassKind::kLumped)(0);
    EXPECT_NEAR(w / exact, 1.0, 1e-3) << "h " << h;
  }
}

TEST(TimoshenkoElement, SlenderBeamFrequencyApproachesEulerBernoulli) {
  // First mode ratio Timoshenko / Euler-Bernoulli = 1 - O((h / L)^2): at L / h = 1000 within
  // 1e-5, at L / h = 10 visibly below (about 1.5 %).
  const double slender = timoshenko_ss_omegas(beam(1e-3, 1, BeamTheory::kTimoshenko), 1)[0];
  const Body b = beam(1e-3, 1, BeamTheory::kTimoshenko);
  const double eb = M_PI * M_PI / (kL * kL) * std::sqrt(kE * b.inertia / (kRho * b.area));
  EXPECT_NEAR(slender / eb, 1.0, 1e-5);
  const Eigen::VectorXd w = ss_omegas(beam(1e-3, 32, BeamTheory::kTimoshenko), MassKind::kConsistent);
  EXPECT_NEAR(w(0) / eb, 1.0, 1e-5);  // the element at slenderness 1000: no shear locking
}

TEST(TimoshenkoElement, CriticalStepBoundsTheTrueTopEigenvalue) {
  // The proven bound omega_max must be >= the assembled model's largest omega, and omega_lower
  // <= it, for stocky and slender beams, lumped and consistent mass (relative slack 1e-9: the
  // dense eigen-solve's roundoff).
  for (double h : {0.3, 0.05, 0.005})
    for (MassKind mass : {MassKind::kLumped, MassKind::kConsistent})
      for (int ne : {4, 40}) {
        Body b = beam(h, ne, BeamTheory::kTimoshenko);
        b.supports = {{0, true, true, false}, {ne, false, true, false}};
        const Model m(scene_of(b, mass), true);
        Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(
            Eigen::MatrixXd(m.K()), Eigen::MatrixXd(m.M()), Eigen::EigenvaluesOnly);
        const double top = std::sqrt(es.eigenvalues().maxCoeff());
        const CriticalStep cs = critical_step(m);
        EXPECT_GE(cs.omega_max, top * (1 - 1e-9)) << "h " << h << " ne " << ne;
        EXPECT_LE(cs.omega_lower, top * (1 + 1e-9)) << "h " << h << " ne " << ne;
      }
}

TEST(TimoshenkoElement, SceneKeysAreCheckedAndDefaultsRecorded) {
  auto error_key = [](const std::vector<std::string>& o) -> std::string {
    try {
      testing::load_paper_scene("s2_transverse", o);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error_key({"bodies.B.poisson=0.3"}).find("bodies[1].poisson"), std::string::npos);  // EB body
  EXPECT_NE(error_key({"bodies.B.theory=timoshenko", "bodies.B.poisson=0.6"}).find("bodies[1].poisson"),
            std::string::npos);
  EXPECT_NE(
      error_key({"bodies.B.theory=timoshenko", "bodies.B.shear_coefficient=0"}).find("shear_coefficient"),
      std::string::npos);
  EXPECT_NE(error_key({"bodies.B.theory=shear"}).find("bodies[1].theory"), std::string::npos);
  EXPECT_NE(
      error_key({"bodies.B.theory=timoshenko", "model.kinematics=corotational"}).find("bodies[1].theory"),
      std::string::npos);
  const Scene s = testing::load_paper_scene("s2_transverse", {"bodies.B.theory=timoshenko"});
  EXPECT_EQ(s.bodies[1].theory, BeamTheory::kTimoshenko);
  EXPECT_EQ(s.bodies[0].theory, BeamTheory::kEulerBernoulli);
  EXPECT_EQ(s.assumed.count("bodies[1].shear_coefficient"), 1u);  // the defaults are written out
  EXPECT_EQ(s.assumed.count("bodies[1].poisson"), 1u);
  EXPECT_EQ(s.assumed.count("bodies[0].poisson"), 0u);  // nothing for an Euler-Bernoulli body
}

}  // namespace
}  // namespace beamimpact
