// The Hertz contact law in the paper's integrator: a rigid rod falling end-first onto an
// immovable rigid surface through a Hertz spring R = k delta^(3/2) is a mass on that spring.
// Energy gives delta_max = (5 m v0^2 / (4 k))^(2/5) and R_max = k delta_max^(3/2); the contact
// lasts T = 2 (delta_max / v0) int_0^1 (1 - x^(5/2))^(-1/2) dx = (4/5) B(2/5, 1/2) delta_max / v0
// = 2.9432 delta_max / v0 (Johnson 1985, section 11.4; Goldsmith 1960), and the rod leaves at
// v0 (an elastic law). Measured (dt 4, 2, 1 us): peak 4550.13, 4551.09, 4551.33 N against
// 4551.41 N (second order), duration 812, 810, 809 us against 808.34 us.
#include <solver/paper/solve.hpp>

#include <cmath>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::paper {
namespace {

constexpr double kK = 1e9, kM = 1.0, kV0 = 1.0;  // N/m^1.5, kg (rho A L), m/s

std::string scene_path() {
  return (testing::source_dir() / "verification/scenes/extra/hertz_drop.toml").string();
}

Scene drop(double dt, const std::vector<std::string>& more = {}) {
  std::vector<std::string> o = {"time.dt=" + std::to_string(dt)};
  o.insert(o.end(), more.begin(), more.end());
  return load_scene(scene_path(), o);
}

double delta_max() { return std::pow(5.0 * kM * kV0 * kV0 / (4.0 * kK), 0.4); }
double duration() {
  const double beta = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);  // B(2/5, 1/2)
  return 0.8 * beta * delta_max() / kV0;
}

TEST(HertzContact, RigidMassOnAHertzSpringMatchesTheClosedForm) {
  EXPECT_NEAR(duration() / (delta_max() / kV0), 2.9432, 1e-4);  // the constant as tabulated
  const double T = duration(), Rmax = kK * std::pow(delta_max(), 1.5);
  double last_peak_error = 0.0;
  for (double dt : {4e-6, 2e-6, 1e-6}) {
    const SimulationResult r = solve(drop(dt));
    ASSERT_EQ(r.contacts[0].intervals.size(), 1u) << "one contact, no chatter";
    const auto iv = r.contacts[0].intervals[0];
    // Interval ends are step times: the duration is within 2 dt of T.
    EXPECT_NEAR(iv[1] - iv[0], T, 2 * dt) << "dt " << dt;
    // Central differences: the peak force is second order in dt (tolerance 0.05 (dt / 1 us)^2
    // relative; the observed error falls about 4x per halving).
    const double peak_error = std::abs(r.contacts[0].peak_R - Rmax) / Rmax;
    EXPECT_LT(peak_error, 0.05 * (dt / 1e-6) * (dt / 1e-6)) << "dt " << dt;
    if (last_peak_error > 0.0) {
      EXPECT_GT(last_peak_error / peak_error, 3.0) << "dt " << dt;
    }
    last_peak_error = peak_error;
    // Impulse: the rod leaves at v0 (elastic), 2 m v0; the release step's share is O(dt).
    EXPECT_NEAR(r.contacts[0].impulse_normal, 2 * kM * kV0, 1e-3 * 2 * kM * kV0) << "dt " << dt;
    // Energy: kinetic + strain (with the spring's) + dissipated = E0 on every row; what the
    // dissipated column holds is the error in the spring's work, O(dt^2): below 1e-4 E0 here.
    // Energy: kinetic + strain (with the spring's) + dissipated = E0. Outside the contact the
    // account closes to roundoff; inside, the rows' kinetic energy is at V^p while the contact
    // work telescopes for the half-step velocities: they differ by at most dt/2 R v0 (J).
    const double E0 = 0.5 * kM * kV0 * kV0;
    double inside = 0.0, outside = 0.0;
    for (const HistoryRow& row : r.history) {
      const double miss = std::abs(row.kinetic + row.strain + row.dissipated - E0);
      double& worst = row.t >= iv[0] - dt && row.t <= iv[1] + dt ? inside : outside;
      worst = std::max(worst, miss);
    }
    EXPECT_LT(outside, 1e-12 * E0) << "dt " << dt;
    EXPECT_LT(inside, 0.5 * dt * Rmax * kV0) << "dt " << dt;
    // The elastic law returns the energy up to the trapezoidal force's error in the spring's
    // work (observed 3e-7 E0 at 4 us): 1e-5 E0.
    EXPECT_NEAR(r.energy_final, E0, 1e-5 * E0) << "dt " << dt;
  }
}

/// The energy account of a run, / E0: the largest |K + S + D - W - E0| (W the loads' work) over
/// the rows outside the contact intervals (widened by a step) and inside them, and the largest
/// fall of D below its running maximum.
struct Account {
  double outside = 0.0, inside = 0.0, fall = 0.0;
};
Account energy_account(const SimulationResult& r) {
  Account a;
  double d_max = -1e300;
  const double E0 = r.energy_initial;
  for (const HistoryRow& row : r.history) {
    const double miss = std::abs(row.kinetic + row.strain + row.dissipated - row.load_work - E0) / E0;
    bool in = false;
    for (const auto& iv : r.contacts[0].intervals)
      in = in || (row.t >= iv[0] - r.dt && row.t <= iv[1] + r.dt);
    double& worst = in ? a.inside : a.outside;
    worst = std::max(worst, miss);
    d_max = std::max(d_max, row.dissipated);
    a.fall = std::max(a.fall, (d_max - row.dissipated) / E0);
  }
  return a;
}

TEST(HertzContact, AStepLongerThanTheContactCreatesNoEnergy) {
  // dt = 1 ms against a contact of 808 us: the spring is not resolved at all, yet the secant
  // force's work is the spring's energy change (hertz_law.hpp), so the rod leaves at v0 (an
  // elastic law), D never moves and the account closes to roundoff outside the contact (1e-12
  // E0: sums of ~10 rows of O(E0) terms). Inside it the rows' V^p differs from the half-step
  // velocities the work telescopes for by dt/2 M^-1 R: at most dt/2 R_peak v0 (J). The
  // trapezoidal force this replaced sent the rod off at 1.168 m/s (0.682 J from 0.5 J).
  for (double dt : {1e-3, 3e-4, 1e-4}) {
    const SimulationResult r = solve(drop(dt, {"time.end=0.01"}));
    const double E0 = 0.5 * kM * kV0 * kV0;
    EXPECT_NEAR(r.energy_final, E0, 1e-12 * E0) << "dt " << dt;
    EXPECT_NEAR(r.final_velocity.at("A")[1], kV0, 1e-12) << "dt " << dt;
    const Account a = energy_account(r);
    EXPECT_LT(a.outside, 1e-12) << "dt " << dt;
    EXPECT_LT(a.inside, 0.5 * dt * r.contacts[0].peak_R * kV0 / E0) << "dt " << dt;
    EXPECT_LT(a.fall, 1e-12) << "dt " << dt;
  }
}

TEST(HertzContact, ABounceUnderGravityKeepsItsEnergy) {
  // The rod bounces on the spring under g = 10 m/s^2 for 20 s (0.2 s flights) at a step of 1e-4
  // s, an eighth of the contact: an elastic law under a conservative load, so K + S + D - W = E0
  // on every row between the contacts and D never falls (roundoff: 1e-9 E0 over 2e5 steps; the
  // loads' work W is of the order of E0). With the trapezoidal force a 20 s bounce ended with D at
  // -0.416 J of 0.5 J.
  const SimulationResult r =
      solve(drop(1e-4, {"time.end=20.0", "loads.gravity=[0.0, -10.0]", "time.output_every=10"}));
  const Account a = energy_account(r);
  EXPECT_LT(a.outside, 1e-9);
  EXPECT_LT(a.fall, 1e-9);
  EXPECT_GT(r.contacts[0].intervals.size(), 50u);  // it did bounce
}

TEST(HertzContact, KeysAreCheckedWithTheirLaw) {
  auto fails = [](const std::vector<std::string>& o, const std::string& key) {
    try {
      drop(1e-6, o);
    } catch (const InputError& e) {
      return std::string(e.what()).find(key) != std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(fails({"contacts[0].law=hard"}, "contacts[0].stiffness"));  // a Hertz key with the hard law
  EXPECT_TRUE(fails({"contacts[0].stiffness=-1.0"}, "contacts[0].stiffness"));
  EXPECT_TRUE(fails({"contacts[0].law=soft"}, "contacts[0].law"));
  EXPECT_TRUE(
      fails({"contacts[0].radius=0.01", "contacts[0].modulus=1e11"}, "contacts[0].law"));  // both ways
  // radius and modulus give k = 4/3 E* sqrt(R*).
  std::ifstream in(scene_path());
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("stiffness = 1.0e9"), 17, "radius = 0.01\nmodulus = 1.5e11");
  EXPECT_DOUBLE_EQ(load_scene_text(text, "t").contacts[0].hertz_stiffness, 4.0 / 3.0 * 1.5e11 * 0.1);
  text.replace(text.find("radius = 0.01"), 13, "");  // modulus alone
  EXPECT_THROW(load_scene_text(text, "t"), InputError);
}

}  // namespace
}  // namespace beamimpact::paper
