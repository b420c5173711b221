#include <references/exact/solve_ball_on_beam.hpp>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <references/exact/BallOnBeam.hpp>
#include <references/exact/ExactCost.hpp>
#include <references/exact/finish_summary.hpp>
#include <solver/scene/run_cost.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::exact {
namespace {

/// rk8pd state-steps per second of one core (RodOnBeamCost.cc's measured rate; the ball takes
/// about one step per stop, measured with 64-512 modes on verification/scenes/extra/ball_on_beam.toml).
constexpr double kStateStepsPerSecond = 4e6;

/// @brief Refuses, before any mode is integrated, a solution (or a mode study's worst case)
/// beyond an ordinary run unless time.allow_long_run is set: the integrator stops every
/// ball_stop_spacing, about one rk8pd step of 2N + 3 states each.
void check_ball_cost(const Scene& scene, const BallOnBeamSetup& s, const BeamModeOptions& o) {
  const double span = std::max(0.0, s.t_end - s.gap / s.v0);
  double state_steps = 0.0;
  long top = o.modes;
  const auto add = [&](long n) {
    state_steps += span / ball_stop_spacing(s, static_cast<int>(n)) * (2.0 * static_cast<double>(n) + 3.0);
  };
  if (o.modes > 0) add(std::min<long>(o.modes, 1L << 30));
  for (long n = std::max(1L, o.modes_min); o.modes == 0; n *= 2) {
    add(n);
    top = n;
    if (2 * n > o.modes_max || n >= (1L << 30)) break;
  }
  ExactCost c;
  c.seconds = state_steps / kStateStepsPerSecond;
  c.bytes = (std::floor(s.t_end / s.dt_out) + 1.0) * kBytesPerRow;
  c.text = fmt::format("{} modes: {:.3g} state-steps, about {:.3g} min of one core{}", top, state_steps,
                       c.seconds / 60.0, o.modes > 0 ? "" : " (the mode study's worst case)");
  refuse_extraordinary(scene, o.modes > 0 ? "exact.modes" : "exact.modes_max", "the ball-on-beam solution", c,
                       "set fewer modes (exact.modes or exact.modes_max) or a shorter time.end");
}

/// @brief The solution's rows as the run's history (the striker's and the struck point's motion
/// along the impact direction d, energies with the spring's in `strain`).
std::vector<HistoryRow> history_rows(const BallOnBeamSolution& sol, const ExactProblem& p) {
  std::vector<HistoryRow> rows;
  const Vec2 d = p.dir;
  for (const BallOnBeamRow& q : sol.rows) {
    HistoryRow row;
    row.t = q.t;
    row.contacts.push_back(along_sample(d, q.R, q.gap, q.z, q.dz, q.w, q.dw));
    row.kinetic = 0.5 * p.mass * q.dz * q.dz + q.beam_kinetic;
    row.strain = q.beam_strain + q.spring;
    row.momentum = along(d, p.mass * q.dz + q.beam_momentum);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

BallOnBeamSetup ball_on_beam_setup(const ExactProblem& p) {
  BallOnBeamSetup s;
  s.mass = p.mass;
  s.stiffness = p.hertz_stiffness;
  s.beam = p.beam;
  s.x_c = p.x_c;
  s.v0 = p.v0;
  s.gap = p.gap;
  return s;
}

SimulationResult solve_ball_on_beam_scene(const Scene& scene, const ExactProblem& p, const BeamModeOptions& o,
                                          ResultRecorder& rec) {
  SimulationResult& r = rec.result();
  BallOnBeamSetup s = ball_on_beam_setup(p);
  s.t_end = scene.time.end;
  s.dt_out = r.dt;
  s.rtol = o.rtol;
  if (!(s.v0 > 0.0))
    throw InputError(scene.file, fmt::format("bodies[{}].velocity", p.striker),
                     "the exact method cannot solve this scene: the striker does not move towards the beam");
  check_ball_cost(scene, s, o);
  BallModeStudy study;
  if (o.modes > 0) {
    s.modes = static_cast<int>(o.modes);
    study.solution = solve_ball_on_beam(s);
    study.table.push_back({s.modes, study.solution.impulse, study.solution.peak_R, study.solution.intervals});
  } else {
    study = converge_ball_modes(s, static_cast<int>(o.modes_min), static_cast<int>(o.modes_max), o.tol);
  }
  const BallOnBeamSolution& sol = study.solution;
  std::vector<HistoryRow> rows = history_rows(sol, p);
  rec.set_final_velocity(scene.bodies[p.striker].name, along(p.dir, sol.final_velocity));
  rec.set_final_velocity(
      scene.bodies[p.target].name,
      along(p.dir, sol.rows.back().beam_momentum / (p.beam.rho * p.beam.area * p.beam.length)));
  r.effects = {"axial", "bending"};
  r.steps = sol.steps;
  nlohmann::json table = nlohmann::json::array();
  for (const auto& e : study.table)
    table.push_back(
        {{"modes", e.modes}, {"impulse", e.impulse}, {"peak_R", e.peak_R}, {"intervals", e.intervals}});
  nlohmann::json extra = {{"modes", sol.modes},
                          {"modes_converged", o.modes > 0 ? nlohmann::json("fixed by exact.modes")
                                                          : nlohmann::json(study.converged)},
                          {"mode_study", table},
                          {"change_last_doubling", study.change},
                          {"struck_point_x", p.x_c},
                          {"sub_impacts", sol.intervals.size()},
                          {"interval_peaks", sol.interval_peaks},
                          {"peak_time", sol.t_peak},
                          {"indentation_max", sol.delta_max},
                          {"deflection_max", sol.w_max},
                          {"deflection_max_time", sol.t_w_max}};
  r.extra["exact"] = {
      {"solution",
       "rigid striker onto a simply supported Euler-Bernoulli beam through a Hertz spring R = k delta^(3/2): "
       "modal sum, GSL rk8pd, Brent-located contact ends and peaks (BallOnBeam.hpp)"},
      {"hertz_stiffness", s.stiffness},
      {"striker_mass", s.mass},
      {"half_space_contact_time", half_space_contact_time(s.mass, s.stiffness, s.v0)},
      {"rk8pd_steps", sol.steps},
      {"rtol", o.rtol},
      {"stop_dt", sol.stop_dt},
      {"energy_balance_error", sol.energy_error},
      {"energy_columns",
       "kinetic: striker + beam modal sum; strain: beam modal sum + the spring's 2/5 k delta^(5/2)"},
      {"theory", "linear, small deformation; the [model] choices do not apply to the continuum"}};
  SimulationResult out = finish_summary(rec, std::move(rows), sol.intervals, sol.impulse, sol.peak_R, 0.0,
                                        p.contact_kind, extra);
  out.contacts[0].interval_impulses = sol.interval_impulses;
  return out;
}

}  // namespace beamimpact::exact
