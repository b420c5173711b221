// External loads ([loads], F^P of the paper's Eq. 3) in the paper integrator, against theory:
// free fall, static deflection of beams under a point load, and the energy account.
#include <solver/paper/solve.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include <solver/model/Model.hpp>
#include <solver/model/load_vector.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::paper {
namespace {

// A vertical bar (L = 10 m, E = 900, rho = 1, A = 1: the bouncing bar's data) with its lower end
// 50 m above an immovable rigid block: gravity -10 m/s^2, a fall of 1 s covers 5 m only.
std::string falling_bar(const std::string& mass, const std::string& extra = "") {
  return R"(
name = "free_fall"
[time]
dt = 0.005
end = 1.0
[model]
mass = ")" +
         mass + R"("
[loads]
gravity = [0.0, -10.0]
[[bodies]]
name = "bar"
start = [0.0, 50.0]
end = [0.0, 60.0]
elements = 8
E = 900.0
rho = 1.0
area = 1.0
inertia = 0.01
[[bodies]]
name = "ground"
start = [0.0, -1.0]
end = [0.0, 0.0]
rigid = true
elements = 1
E = 900.0
rho = 1.0
area = 1.0
supports = [{ at = "start", fix = ["x", "y", "theta"] }]
[[contacts]]
striker = "bar"
node = "start"
target = "ground"
)" + extra;
}

// Free fall of a stress-free bar: the load M g T (T the rigid translation) gives every node the
// acceleration g, K T = 0, so explicit Newmark (beta = 0, gamma = 1/2), exact for a constant
// acceleration, gives u = -g t^2/2 and v = -g t at every step (roundoff only: 1e-12 of the
// 5 m fall after 200 steps). The energy account K + S + D - W = E0 closes to roundoff too:
// K = m (g t)^2 / 2 = W = m g (g t^2 / 2).
TEST(Loads, FreeFallIsExactForConstantAcceleration) {
  for (const char* mass : {"lumped", "consistent"}) {
    for (const char* bending : {"false", "true"}) {
      const Scene s =
          load_scene_text(falling_bar(mass), "free_fall.toml", {std::string("effects.bending=") + bending});
      const SimulationResult r = solve(s);
      ASSERT_EQ(r.history.size(), 201u);
      const double m = 10.0, g = 10.0;
      for (const HistoryRow& row : r.history) {
        const double t = row.t;
        EXPECT_NEAR(row.contacts[0].ua[1], -0.5 * g * t * t, 1e-12 * 5.0) << mass << " t " << t;
        EXPECT_NEAR(row.contacts[0].va[1], -g * t, 1e-12 * 10.0) << mass << " t " << t;
        EXPECT_NEAR(row.contacts[0].ua[0], 0.0, 1e-14);
        EXPECT_NEAR(row.kinetic, 0.5 * m * g * g * t * t, 1e-11 * 500.0);
        EXPECT_NEAR(row.load_work, m * g * 0.5 * g * t * t, 1e-11 * 500.0);
        EXPECT_NEAR(row.strain, 0.0, 1e-11 * 500.0);
      }
      EXPECT_TRUE(r.contacts[0].intervals.empty()) << "the bar never reaches the ground";
      ASSERT_TRUE(r.extra.contains("loads"));
      EXPECT_NEAR(r.extra["loads"]["work_final"].get<double>(), 500.0, 1e-9);
      const auto& e = r.effects;
      EXPECT_NE(std::find(e.begin(), e.end(), "loads"), e.end());
    }
  }
}

// A cantilever of four Hermite elements (L = 4 m, EI = 100 * 0.4^3/12) with a tip force P
// across it, and Rayleigh mass damping that brings it to rest: the state at rest solves K u = F,
// and Hermite elements give the exact nodal deflection of Euler-Bernoulli theory under nodal
// loads: tip P L^3 / (3 E I), at x: P x^2 (3 L - x) / (6 E I). Damping a0 = 2 omega_1 (critical
// for the first mode, omega_1 = 1.875^2 sqrt(EI / (rho A L^4)) = 0.2647 rad/s) decays every mode
// at least as e^(-omega_1 t) t: t = 160 s leaves below 1e-15 of the deflection.
// A simply supported span loaded at its middle: P L^3 / (48 E I) under the load.
std::string loaded_beam(const std::string& supports, const std::string& node, double a0, double end) {
  return R"(
name = "static"
[time]
dt = "auto"
end = )" +
         std::to_string(end) + R"(
output_every = 100
[model]
rayleigh_mass = )" +
         std::to_string(a0) + R"(
[[loads.point]]
body = "beam"
node = )" +
         node + R"(
force = [0.0, -0.01]
[[bodies]]
name = "beam"
start = [0.0, 0.0]
end = [4.0, 0.0]
elements = 4
E = 100.0
rho = 1.0
area = 0.4
inertia = 0.005333333333333333
supports = )" +
         supports + R"(
[[bodies]]
name = "far"
start = [0.0, -10.0]
end = [4.0, -10.0]
elements = 1
E = 100.0
rho = 1.0
area = 0.4
inertia = 0.005333333333333333
supports = [{ at = "start", fix = ["x", "y", "theta"] }]
[[contacts]]
striker = "beam"
node = "end"
target = "far"
)";
}

TEST(Loads, StaticDeflectionUnderAPointLoadMatchesBeamTheory) {
  const double EI = 100.0 * 0.4 * 0.4 * 0.4 / 12.0, P = 0.01, L = 4.0;
  const double w1 = 1.875104068711961 * 1.875104068711961 * std::sqrt(EI / (0.4 * L * L * L * L));
  {
    const Scene s = load_scene_text(
        loaded_beam(R"([{ at = "start", fix = ["x", "y", "theta"] }])", "\"end\"", 2.0 * w1, 160.0),
        "cantilever.toml");
    const SimulationResult r = solve(s);
    const double tip = r.history.back().contacts[0].ua[1];
    EXPECT_NEAR(tip, -P * L * L * L / (3.0 * EI), 1e-9 * P * L * L * L / (3.0 * EI));
    // At rest: S = W / 2 (Clapeyron), and K + S + D - W = 0 with the damper's share D.
    const HistoryRow& last = r.history.back();
    EXPECT_NEAR(last.strain, 0.5 * last.load_work, 1e-9 * last.load_work);
    EXPECT_NEAR(last.kinetic + last.strain + last.dissipated - last.load_work, 0.0, 1e-3 * last.load_work);
  }
  {
    // Simply supported: first mode omega_1 = pi^2 sqrt(EI / (rho A L^4)) = 0.7112 rad/s.
    const double w1s = M_PI * M_PI * std::sqrt(EI / (0.4 * L * L * L * L));
    const Scene s =
        load_scene_text(loaded_beam(R"([{ at = "start", fix = ["x", "y"] }, { at = "end", fix = ["y"] }])",
                                    "2", 2.0 * w1s, 60.0),
                        "simple.toml");
    const SimulationResult r = solve(s);
    // The reported contact node is the beam's end (on a support); read the middle from the load work:
    // W = P w_mid at rest.
    const double w_mid = r.history.back().load_work / P;
    EXPECT_NEAR(w_mid, P * L * L * L / (48.0 * EI), 1e-9 * P * L * L * L / (48.0 * EI));
  }
}

// The load vector: gravity is M times the rigid translation (lumped: each node's mass times g;
// the body's total m g either way), a point force lands on its node's equations, and a rod model
// refuses a load across its axis instead of dropping it.
TEST(Loads, LoadVectorSumsToTheWeightAndRefusesACrossAxisLoadOnRods) {
  for (const char* mass : {"lumped", "consistent"}) {
    const Scene s = load_scene_text(falling_bar(mass), "bar.toml", {"effects.bending=true"});
    const Model m(s, true);
    const Eigen::VectorXd F = load_vector(m, s);
    double fy = 0.0;
    for (int n = 0; n < 9; ++n) fy += F(m.equation(m.node_id(0, n), 1));
    EXPECT_NEAR(fy, -100.0, 1e-12) << mass;  // m g = 10 kg x 10 m/s^2
  }
  const Scene rod = load_scene_text(falling_bar("lumped"), "bar.toml", {"loads.gravity=[1.0, -10.0]"});
  const Model m(rod, false);
  try {
    load_vector(m, rod);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "loads.gravity");
  }
  EXPECT_EQ(load_vector(m, load_scene_text(falling_bar("lumped"), "b.toml", {"loads.gravity=[0, 0]"})).size(),
            0);
}

// Bad [loads] input: one message naming the key.
TEST(Loads, BadInputNamesTheKey) {
  const auto key_of = [](const std::string& extra) {
    try {
      load_scene_text(falling_bar("lumped", extra), "bad.toml");
    } catch (const InputError& e) {
      return e.key();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(key_of("[[loads.point]]\nbody = \"nope\"\nnode = 0\nforce = [1, 0]\n"), "loads.point[0].body");
  EXPECT_EQ(key_of("[[loads.point]]\nbody = \"bar\"\nnode = 99\nforce = [1, 0]\n"), "loads.point[0].node");
  EXPECT_EQ(key_of("[[loads.point]]\nbody = \"bar\"\nnode = 1\nforce = [1]\n"), "loads.point[0].force");
  EXPECT_EQ(key_of("[[loads.point]]\nbody = \"bar\"\nnode = 1\nforce = [0, 1]\nextra = 1\n"),
            "loads.point[0].extra");
}

}  // namespace
}  // namespace beamimpact::paper
