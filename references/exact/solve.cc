#include <references/exact/solve.hpp>

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include <references/exact/CoaxialRods.hpp>
#include <references/exact/CoaxialRodsCost.hpp>
#include <references/exact/RigidRodImpact.hpp>
#include <references/exact/RodOnBeam.hpp>
#include <references/exact/RodOnBeamCost.hpp>
#include <references/exact/RodOnWall.hpp>
#include <references/exact/beam_mode_options.hpp>
#include <references/exact/finish_summary.hpp>
#include <references/exact/output_times.hpp>
#include <references/exact/recognise_scene.hpp>
#include <references/exact/solve_ball_on_beam.hpp>
#include <solver/record/ResultRecorder.hpp>
#include <solver/scene/TableReader.hpp>
#include <solver/scene/run_cost.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::exact {
namespace {

SimulationResult solve_rods(const Scene& scene, const ExactProblem& p, ResultRecorder& rec) {
  SimulationResult& r = rec.result();
  std::vector<HistoryRow> rows;
  const Rod& A = p.striker_rod;
  const Rod& B = p.target_rod;
  // Before any piece is solved: a solution far beyond an ordinary run is refused (its pieces grow
  // with time.end, as its square when the round trips are incommensurate).
  refuse_extraordinary(scene, "time.end", "the coaxial-rod solution",
                       estimate_coaxial_rods_cost(A, B, p.v0, p.gap, scene.time.end, r.dt).total(),
                       "set a shorter time.end, a larger exact.dt_out");
  const CoaxialRods sol(A, B, p.v0, p.gap, scene.time.end, p.target_far_end);
  const double vt = p.target_speed;  // the solution lives in the target's initial rest frame
  const Vec2 d = p.dir;
  for (double t : output_times(r.dt, scene.time.end)) {
    const RodsEndState e = sol.state(t);
    const RodField fa = sol.striker_field(t), fb = sol.target_field(t);
    HistoryRow row;
    row.t = t;
    row.contacts.push_back(along_sample(d, e.P, e.gap, e.ua + vt * t, e.va + vt, e.ub + vt * t, e.vb + vt));
    // Back to the ground frame: KE = KE' + vt p' + m vt^2 / 2 for each rod.
    row.kinetic =
        fa.kinetic + fb.kinetic + vt * (fa.momentum + fb.momentum) + 0.5 * (A.mass() + B.mass()) * vt * vt;
    row.strain = fa.strain + fb.strain;
    row.momentum = along(d, fa.momentum + fb.momentum + (A.mass() + B.mass()) * vt);
    rows.push_back(row);
  }
  const double te = scene.time.end;
  r.effects = {"axial"};
  r.steps = static_cast<long>(sol.segments().size());
  const double first = sol.first_touch() < te ? sol.state(sol.first_touch()).P : 0.0;
  nlohmann::json extra = {{"first_touch", sol.first_touch() < te ? sol.first_touch() : -1.0},
                          {"pieces", sol.segments().size()}};
  rec.set_final_velocity(scene.bodies[p.striker].name,
                         along(d, sol.striker_field(te).momentum / A.mass() + vt));
  rec.set_final_velocity(scene.bodies[p.target].name,
                         along(d, sol.target_field(te).momentum / B.mass() + vt));
  const bool fixed = p.target_far_end == FarEnd::kFixed;
  r.extra["exact"] = {
      {"solution", fixed ? "coaxial rods, the target clamped at its far end, d'Alembert with "
                           "reflection memory (references.md 1, CoaxialRods.hpp)"
                         : "coaxial free rods, d'Alembert with reflection memory (references.md 1)"},
      {"pieces", sol.segments().size()},
      {"note",
       "P is piecewise constant between breakpoints (contact start, re-contacts and their "
       "shifts by multiples of T_A, T_B); every output is exact to roundoff; energies are "
       "integrated exactly over the piecewise-constant wave fields"},
      {"round_trip_striker", A.round_trip()},
      {"round_trip_target", B.round_trip()},
      {"impedance_striker", A.impedance()},
      {"impedance_target", B.impedance()}};
  SimulationResult out = finish_summary(rec, std::move(rows), sol.force_intervals(), sol.impulse(te),
                                        sol.peak_force(), first, p.contact_kind, extra);
  out.contacts[0].interval_impulses.clear();
  for (const auto& i : sol.force_intervals())
    out.contacts[0].interval_impulses.push_back(sol.impulse(i[1]) - sol.impulse(i[0]));
  return out;
}

/// The rod on a rigid wall (RodOnWall.hpp): rows, energies and the load work from the exact
/// piecewise-linear wave field; intervals, impulse and peak force from its exact events.
SimulationResult solve_wall(const Scene& scene, const ExactProblem& p, ResultRecorder& rec) {
  SimulationResult& r = rec.result();
  const RodOnWall sol({p.striker_rod, p.v0, p.g, p.gap, scene.time.end});
  const Vec2 d = p.dir;
  std::vector<HistoryRow> rows;
  for (double t : output_times(r.dt, scene.time.end)) {
    const RodOnWallState e = sol.state(t);
    const RodField f = sol.field(t);
    HistoryRow row;
    row.t = t;
    ContactSample c;  // the wall does not move: no struck-point motion
    c.R = e.R;
    c.gap = e.gap;
    c.ua = along(d, e.u);
    c.va = along(d, e.v);
    c.state = e.R > 0.0 ? ContactState::kClosed : ContactState::kOpen;
    row.contacts.push_back(c);
    row.kinetic = f.kinetic;
    row.strain = f.strain;
    row.load_work = sol.load_work(t);
    row.momentum = along(d, f.momentum);
    rows.push_back(row);
  }
  const double te = scene.time.end, m = p.striker_rod.mass();
  rec.set_final_velocity(scene.bodies[p.striker].name, along(d, sol.field(te).momentum / m));
  rec.set_final_velocity(scene.bodies[p.target].name, {0.0, 0.0});
  r.effects = {"axial"};
  if (p.g != 0.0) r.effects.push_back("loads");
  r.steps = static_cast<long>(sol.pieces());
  const auto& iv = sol.intervals();
  nlohmann::json extra = {{"first_touch", iv.empty() ? -1.0 : iv.front()[0]}, {"pieces", sol.pieces()}};
  r.extra["exact"] = {{"solution",
                       "free elastic rod end-on onto an immovable rigid wall, gravity along the rod: "
                       "d'Alembert in the rod's free-fall frame (RodOnWall.hpp)"},
                      {"note",
                       "the wave p is piecewise linear: event times, force, impulse, energies (Simpson on "
                       "each linear piece) and the load work are exact to roundoff"},
                      {"round_trip", p.striker_rod.round_trip()},
                      {"impedance", p.striker_rod.impedance()},
                      {"gravity_along_axis", p.g},
                      {"approach_speed", p.v0}};
  const double first = iv.empty() ? 0.0 : sol.state(iv.front()[0]).R;
  SimulationResult out = finish_summary(rec, std::move(rows), iv, sol.impulse(te), sol.peak_force(), first,
                                        p.contact_kind, extra);
  out.contacts[0].interval_impulses.clear();
  for (const auto& i : iv) out.contacts[0].interval_impulses.push_back(sol.impulse(i[1]) - sol.impulse(i[0]));
  return out;
}

/// The rigid rod: free flight to the contact instant t0 = gap / V, the closed-form impulses
/// (restitution 0), then free flight with the new velocity and spin (rotation exact, no gravity).
SimulationResult solve_rigid(const Scene& scene, const ExactProblem& p, ResultRecorder& rec) {
  SimulationResult& r = rec.result();
  const Body& A = scene.bodies[p.striker];
  const double m = A.rho * A.area * A.length(), l = A.length(), I = m * l * l / 12.0;
  const RigidRodImpact imp = rigid_rod_impact(m, l, p.theta, p.v0, p.mu);
  const int node = scene.contacts[0].node;
  const Vec2 G0{0.5 * (A.start[0] + A.end[0]), 0.5 * (A.start[1] + A.end[1])};
  const Vec2 A0 = A.node_position(node);
  const Vec2 r0{A0[0] - G0[0], A0[1] - G0[1]};
  const Vec2 n = p.normal;
  // Tangential impulse toward the centre's side of the contact end, along the surface.
  const Vec2 t{n[1], -n[0]};
  const double toward_centre = -(r0[0] * t[0] + r0[1] * t[1]) >= 0.0 ? 1.0 : -1.0;
  const Vec2 P{imp.p_n * n[0] + toward_centre * imp.p_t * t[0],
               imp.p_n * n[1] + toward_centre * imp.p_t * t[1]};
  const double t0 = p.gap / p.v0;
  const Vec2 v0 = A.velocity;
  const Vec2 v1{v0[0] + P[0] / m, v0[1] + P[1] / m};
  const double w1 = (r0[0] * P[1] - r0[1] * P[0]) / I;  // counter-clockwise spin after the impact
  std::vector<HistoryRow> rows;
  for (double time : output_times(r.dt, scene.time.end)) {
    const bool after = time > t0;
    const double tau = after ? time - t0 : 0.0, phi = w1 * tau;
    const Vec2 v = after ? v1 : v0;
    const double w = after ? w1 : 0.0;
    const Vec2 G{G0[0] + v0[0] * std::min(time, t0) + v1[0] * tau,
                 G0[1] + v0[1] * std::min(time, t0) + v1[1] * tau};
    const Vec2 rt{std::cos(phi) * r0[0] - std::sin(phi) * r0[1],
                  std::sin(phi) * r0[0] + std::cos(phi) * r0[1]};
    HistoryRow row;
    row.t = time;
    ContactSample c;
    c.ua = {G[0] + rt[0] - A0[0], G[1] + rt[1] - A0[1]};
    c.va = {v[0] - w * rt[1], v[1] + w * rt[0]};
    c.gap = p.gap + c.ua[0] * n[0] + c.ua[1] * n[1];
    c.state = ContactState::kOpen;  // the impact is instantaneous: no finite force at any row
    row.contacts.push_back(c);
    row.kinetic = 0.5 * m * (v[0] * v[0] + v[1] * v[1]) + 0.5 * I * w * w;
    row.momentum = {m * v[0], m * v[1]};
    rows.push_back(row);
  }
  rec.set_final_velocity(A.name, scene.time.end > t0 ? v1 : v0);
  rec.set_final_velocity(scene.bodies[p.target].name, {0.0, 0.0});
  r.effects = {"rigid"};
  if (p.mu > 0.0) r.effects.push_back("friction");
  r.steps = 1;
  nlohmann::json extra = {{"stick_threshold", imp.mu_star},
                          {"regime", imp.stick ? "stick" : "slip"},
                          {"theta", p.theta},
                          {"approach_speed", p.v0},
                          {"impact_time", t0},
                          {"spin_after", w1}};
  r.extra["exact"] = {
      {"solution",
       "rigid rod onto an immovable rigid surface, Coulomb friction, restitution 0: closed-form "
       "impulses (references.md 3); free flight before and after (exact rotation, no gravity)"},
      {"note",
       "the impact is an instantaneous impulse: the rows carry no force; intervals are "
       "[t0, t0], the impulses are the closed form's"}};
  const bool hit = t0 <= scene.time.end;
  SimulationResult out = finish_summary(
      rec, std::move(rows),
      hit ? std::vector<std::array<double, 2>>{{t0, t0}} : std::vector<std::array<double, 2>>{},
      hit ? imp.p_n : 0.0, 0.0, 0.0, p.contact_kind, extra);
  // The paper's tangent is the normal turned -90 deg: the summary's sign convention.
  out.contacts[0].impulse_tangential = hit ? toward_centre * imp.p_t : 0.0;
  out.contacts[0].friction = p.mu;
  return out;
}

/// The most beam modes: the solution's state, 2 N + 3 numbers, is indexed by int.
constexpr long kMostModes = (std::numeric_limits<int>::max() - 3L) / 2;

/// Before any mode is integrated: a solution (or the worst case of a mode study, every doubling
/// up to modes_max) far beyond an ordinary run is refused with its estimate, unless
/// time.allow_long_run is set.
void check_beam_cost(const Scene& scene, const RodOnBeamSetup& s, const BeamModeOptions& o) {
  std::vector<int> counts;
  if (o.modes > 0) counts.push_back(static_cast<int>(std::min<long>(o.modes, 1L << 30)));
  for (long n = std::max(1L, o.modes_min); o.modes == 0; n *= 2) {
    counts.push_back(static_cast<int>(n));
    if (2 * n > o.modes_max || n >= (1L << 30)) break;  // 2^30 modes: refused anyway
  }
  ExactCost c = estimate_rod_on_beam_cost(s, counts).total();
  if (o.modes == 0) c.text += " (the mode study's worst case)";
  refuse_extraordinary(scene, o.modes > 0 ? "exact.modes" : "exact.modes_max", "the rod-on-beam solution", c,
                       "set fewer modes (exact.modes or exact.modes_max), a larger exact.dt_out");
}

/// summary.json exact.solution of the rod on a beam, Euler-Bernoulli or Timoshenko.
const char* rod_on_beam_note(const BeamShear& shear) {
  return shear.timoshenko()
             ? "rod end-on onto a simply supported Timoshenko beam: exact rod waves with reflection memory + "
               "modal sum of both frequency branches, GSL rk8pd, Brent-located events (RodOnBeam.hpp, "
               "TimoshenkoBeam.hpp)"
             : "rod end-on onto a simply supported Euler-Bernoulli beam: exact rod waves with "
               "reflection memory + modal sum, GSL rk8pd, Brent-located events (references.md 2)";
}

/// summary.json contacts[0].extra.timoshenko: the shear data of a Timoshenko target and what
/// `modes` counts.
nlohmann::json timoshenko_note(const BeamShear& shear) {
  return {{"shear_coefficient", shear.kappa},
          {"shear_modulus", shear.G},
          {"modes", "the lowest by frequency, both branches of the frequency equation counted"}};
}

SimulationResult solve_beam(const Scene& scene, const ExactProblem& p, const BeamModeOptions& o,
                            ResultRecorder& rec) {
  SimulationResult& r = rec.result();
  std::vector<HistoryRow> rows;
  RodOnBeamSetup s;
  s.rod = p.striker_rod;
  s.beam = p.beam;
  s.shear = p.shear;
  s.x_c = p.x_c;
  s.v0 = p.v0;
  s.gap = p.gap;
  s.t_end = scene.time.end;
  s.dt_out = r.dt;
  s.rtol = o.rtol;
  check_beam_cost(scene, s, o);
  ModeStudy study;
  if (o.modes > 0) {
    s.modes = static_cast<int>(o.modes);
    study.solution = RodOnBeam(s).solution();
    study.table.push_back({s.modes, study.solution.impulse, study.solution.intervals, study.solution.w_max});
  } else {
    study = converge_modes(s, static_cast<int>(o.modes_min), static_cast<int>(o.modes_max), o.tol);
  }
  const RodOnBeamSolution& sol = study.solution;
  const Vec2 d = p.dir;
  const double mA = p.striker_rod.mass();
  for (const RodOnBeamRow& q : sol.rows) {
    HistoryRow row;
    row.t = q.t;
    row.contacts.push_back(along_sample(d, q.P, q.gap, q.u, q.du, q.w, q.dw));
    row.kinetic = q.beam_kinetic + q.rod.kinetic;
    row.strain = q.beam_strain + q.rod.strain;
    row.momentum = along(d, mA * p.v0 - q.impulse + q.beam_momentum);
    rows.push_back(row);
  }
  const RodOnBeamRow& last = sol.rows.back();
  rec.set_final_velocity(scene.bodies[p.striker].name, along(d, p.v0 - last.impulse / mA));
  rec.set_final_velocity(scene.bodies[p.target].name,
                         along(d, last.beam_momentum / (p.beam.rho * p.beam.area * p.beam.length)));
  r.effects = {"axial", "bending"};
  r.steps = sol.steps;
  nlohmann::json table = nlohmann::json::array();
  for (const auto& e : study.table)
    table.push_back(
        {{"modes", e.modes}, {"impulse", e.impulse}, {"intervals", e.intervals}, {"w_max", e.w_max}});
  nlohmann::json extra = {{"modes", sol.modes},
                          {"modes_converged", o.modes > 0 ? nlohmann::json("fixed by exact.modes")
                                                          : nlohmann::json(study.converged)},
                          {"mode_study", table},
                          {"impulse_change_last_doubling", study.impulse_change},
                          {"time_change_last_doubling", study.time_change},
                          {"struck_point_x", p.x_c},
                          {"deflection_max", sol.w_max},
                          {"deflection_max_time", sol.t_w_max},
                          {"deflection_min", sol.w_min},
                          {"events", sol.events},
                          {"pieces", sol.pieces}};
  if (p.shear.timoshenko()) extra["timoshenko"] = timoshenko_note(p.shear);
  r.extra["exact"] = {{"solution", rod_on_beam_note(p.shear)},
                      {"rk8pd_steps", sol.steps},
                      {"rtol", o.rtol},
                      {"memory_sample_dt", sol.sample_dt},
                      {"energy_balance_error", sol.energy_error},
                      {"energy_columns",
                       "beam: modal sums; rod: kinetic and strain integrated over its wave field "
                       "(from the stored reflection memory); the beam's axial motion is not excited"},
                      {"theory",
                       "linear, small deformation; the [model] mass/rotary_inertia/kinematics choices "
                       "do not apply to the continuum"}};
  return finish_summary(rec, std::move(rows), sol.intervals, sol.impulse, sol.peak_P, sol.first_P,
                        p.contact_kind, extra);
}

}  // namespace

SimulationResult solve(const Scene& scene) {
  ResultRecorder rec(scene, "exact", ContactSampling::kExactEvents);
  SimulationResult& r = rec.result();
  const ExactProblem p = recognise_scene(scene);
  MethodOptions opts(scene, "exact", &r.assumed);
  TableReader& in = opts.reader();
  if (in.has("dt_out")) {
    r.dt = in.number("dt_out", "a positive output interval (s)");
    if (!(r.dt > 0.0)) in.fail("dt_out", "expected a positive output interval (s)");
  } else if (scene.time.dt) {
    r.dt = *scene.time.dt * scene.time.output_every;
  } else {
    r.dt = scene.time.end / 2000.0;
    r.assumed["exact.dt_out"] = fmt::format("{} s (time.end / 2000, as time.dt is auto)", r.dt);
  }
  check_run_cost(scene, r.dt);  // one row per output time: refuses 1e300 rows (was a hang)
  BeamModeOptions o;
  if (p.kind == ExactKind::kRodOnBeam || p.kind == ExactKind::kBallOnBeam) {
    if (in.has("modes")) {
      o.modes = in.integer("modes", "a positive number of beam modes");
      if (o.modes < 1 || o.modes > kMostModes)
        in.fail("modes", fmt::format("expected a positive number of beam modes, at most {}", kMostModes));
    } else {
      o.modes_min = in.integer_or("modes_min", o.modes_min, "the first mode count of the convergence study");
      o.modes_max =
          in.integer_or("modes_max", o.modes_max, "the largest mode count of the convergence study");
      o.tol =
          in.number_or("mode_tolerance", o.tol, "relative change of impulse and contact times per doubling");
      if (o.modes_min < 1 || o.modes_max < o.modes_min)
        in.fail("modes_max", "expected 1 <= modes_min <= modes_max");
      if (o.modes_max > kMostModes)
        in.fail("modes_max", fmt::format("expected at most {} modes", kMostModes));
      if (!(o.tol > 0.0)) in.fail("mode_tolerance", "expected a positive tolerance");
    }
    o.rtol = in.number_or("rtol", o.rtol, "rk8pd relative tolerance");
    if (!(o.rtol > 0.0 && o.rtol < 1e-2)) in.fail("rtol", "expected a tolerance in (0, 0.01)");
  }
  in.finish();
  if (p.kind == ExactKind::kRigidRod) return solve_rigid(scene, p, rec);
  if (p.kind == ExactKind::kRodOnWall) return solve_wall(scene, p, rec);
  if (p.kind == ExactKind::kBallOnBeam) return solve_ball_on_beam_scene(scene, p, o, rec);
  return p.kind == ExactKind::kCoaxialRods ? solve_rods(scene, p, rec) : solve_beam(scene, p, o, rec);
}

}  // namespace beamimpact::exact
