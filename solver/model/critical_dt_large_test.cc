// The critical step of 1e5-element rod and frame models against closed forms, and long runs of
// central differences at 0.99 of the reported step that stay bounded.
//
// Closed forms for a uniform body of element length h, wave speed c = sqrt(E/rho), radius of
// gyration r = sqrt(I/A), lumped mass (m = rho A h per element, HRZ rotary inertia m h^2/78 per
// element end):
//  - rod: every element alone has omega^2 = 4 c^2/h^2, and the alternating vector u_i = (-1)^i
//    has exactly that Rayleigh quotient, so omega_max = 2 c/h and dt_crit = h/c;
//  - frame: the single element's largest omega^2 is 516 c^2 r^2/h^4 (the antisymmetric
//    bending mode v1 = -v2, theta1 = theta2; 2x2 eigenproblem (48, 468, off-diagonal^2
//    144 x 156) in units EI/(m h^3)), an upper bound of the assembled omega_max^2 (element
//    bound), and the uniform rotation (theta = 1, u = v = 0) has the Rayleigh quotient
//    12 EI/h / (m h^2/39) = 468 c^2 r^2/h^4, a lower bound. So the true limit lies in
//    [2 h^2/(sqrt(516) c r), 2 h^2/(sqrt(468) c r)] and a safe reported step is at most the right end.
#include <solver/model/critical_dt.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact {
namespace {

using testing::paper_scene;

constexpr int kElements = 50000;  // per body, two bodies: 1e5 elements

Scene refined(const char* scene) {
  const std::string n = std::to_string(kElements);
  return load_scene(paper_scene(scene), {"bodies.A.elements=" + n, "bodies.B.elements=" + n});
}

/// Central differences u_{k+1} = 2 u_k - u_{k-1} - dt^2 M^-1 K u_k from a pseudo-random u_0
/// (every mode excited, u_{-1} = u_0). Returns max ||u_k||_M / ||u_0||_M over the run.
double growth(const Model& m, double dt, int steps) {
  const int n = m.size();
  Eigen::VectorXd u(n), u_prev(n), f(n);
  unsigned s = 7u;
  for (int i = 0; i < n; ++i) {
    s = s * 1103515245u + 12345u;
    u(i) = static_cast<double>((s >> 8) & 0xffff) / 65536.0 - 0.5;
  }
  u_prev = u;
  const Eigen::VectorXd dt2_minv = (dt * dt) * m.lumped_mass().cwiseInverse();
  const Eigen::VectorXd& mass = m.lumped_mass();
  auto m_norm = [&] { return std::sqrt(u.dot(mass.cwiseProduct(u))); };
  const double u0 = m_norm();
  double umax = u0;
  for (int k = 0; k < steps && std::isfinite(umax); ++k) {
    f.noalias() = m.K() * u;
    for (int i = 0; i < n; ++i) {
      const double next = 2 * u(i) - u_prev(i) - dt2_minv(i) * f(i);
      u_prev(i) = u(i);
      u(i) = next;
    }
    umax = std::max(umax, m_norm());
  }
  return std::isfinite(umax) ? umax / u0 : INFINITY;
}

// Bounded: from u_{-1} = u_0 a stable mode oscillates as cos(k phi) - tan(phi/2) sin(k phi),
// cos(phi) = 1 - (omega dt)^2/2, amplitude 1/cos(phi/2) = 1/sqrt(1 - (omega dt/2)^2). Modes are
// M-orthogonal, so at dt = 0.99 x 2/omega_bound, with omega_bound >= every omega, the M-norm
// never exceeds 1/sqrt(1 - 0.99^2) = 7.09 of its start (+1e-6 for roundoff). A bound 0.5 % below
// the true omega_max would already let the top mode reach 10.
const double kBounded = 1.0 / std::sqrt(1.0 - 0.99 * 0.99) * (1 + 1e-6);

TEST(CriticalStepLarge, RodOf1e5ElementsHasTheCourantLimit) {
  const Scene s = refined("s1_central");
  const Model m(s, false);
  const Body& a = s.bodies[0];  // A and B are the same rod
  const double h = a.length() / a.elements, c = std::sqrt(a.E / a.rho);
  const CriticalStep cs = critical_step(m);
  // The element bound equals the exact limit h/c: roundoff of the 2x2 eigen-solve only.
  EXPECT_NEAR(cs.element_bound_dt, h / c, 1e-12 * h / c);
  EXPECT_NEAR(cs.dt, h / c, 1e-12 * h / c);
  EXPECT_LE(cs.dt, h / c * (1 + 1e-12));  // never above the exact limit
  // 1000 steps at 0.99: about 500 periods of the highest mode (period ~ 2 steps).
  EXPECT_LT(growth(m, 0.99 * cs.dt, 1000), kBounded);
  // The same harness detects an unstable step: 1 % above the exact limit the top mode grows by
  // |lambda| = 1.33 per step, past 1e6 well within 200 steps.
  EXPECT_GT(growth(m, 1.01 * h / c, 200), 1e6);
}

TEST(CriticalStepLarge, FrameOf1e5ElementsIsBetweenTheElementAndRotationBounds) {
  const Scene s = refined("s2_transverse");
  const Model m(s, true);
  // Body A (5 m) has the shorter elements: it sets the limit.
  const Body& a = s.bodies[0];
  const double h = a.length() / a.elements, c = std::sqrt(a.E / a.rho), r = std::sqrt(a.inertia / a.area);
  ASSERT_GT(516 * r * r / (h * h), 4.0);  // bending, not the axial 2c/h, is the faster wave
  const double dt_element = 2 * h * h / (std::sqrt(516.0) * c * r);
  const double dt_rotation = 2 * h * h / (std::sqrt(468.0) * c * r);
  const CriticalStep cs = critical_step(m);
  // The closed-form element bound, to the roundoff of a 6x6 generalized eigen-solve.
  EXPECT_NEAR(cs.element_bound_dt, dt_element, 1e-9 * dt_element);
  EXPECT_GE(cs.dt, dt_element * (1 - 1e-9));
  // Never above the true limit, which is at most dt_rotation (Rayleigh quotient).
  EXPECT_LE(cs.dt, dt_rotation);
  EXPECT_LT(growth(m, 0.99 * cs.dt, 500), kBounded);
  // The harness detects an unstable step: 2 % above the rotation bound (above the true limit).
  EXPECT_GT(growth(m, 1.02 * dt_rotation, 200), 1e6);
}

}  // namespace
}  // namespace beamimpact
