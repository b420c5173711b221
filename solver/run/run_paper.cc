#include "run/run_paper.hpp"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "integrator/ExplicitContactIntegrator.hpp"
#include "io/ContactStats.hpp"
#include "io/Progress.hpp"
#include "model/critical_dt.hpp"
#include "scene/SceneError.hpp"
#include "scene/TableReader.hpp"

namespace beamimpact {
namespace {

/// The step: given, or "auto" = fraction x critical; refused above critical unless allowed.
double choose_dt(const Scene& scene, const CriticalStep& cs, RunResult& r) {
  if (!scene.time.dt) {
    r.assumed["time.dt"] = fmt::format("auto: {} x critical step {:.6g} s", scene.time.fraction, cs.dt);
    return scene.time.fraction * cs.dt;
  }
  const double dt = *scene.time.dt;
  if (dt > cs.dt * (1.0 + 1e-12) && !scene.time.allow_above_critical)
    throw SceneError(scene.file, "time.dt",
                     fmt::format("expected at most the critical step {:.6g} s (2/omega_max of the full "
                                 "M^-1 K, omega_max = {:.6g} rad/s), got {:.6g} s; use dt = \"auto\", a "
                                 "smaller dt, or set time.allow_above_critical = true to run anyway",
                                 cs.dt, cs.omega_max, dt));
  return dt;
}

HistoryRow make_row(const ExplicitContactIntegrator& in) {
  const Model& m = in.model();
  HistoryRow row;
  row.t = in.time();
  for (std::size_t c = 0; c < in.pairs().size(); ++c) {
    const ContactPair& pair = in.pairs()[c];
    const ContactForce& f = in.forces()[c];
    ContactSample s;
    s.R = f.R;
    s.tau = f.tau;
    s.gap = f.gap_next;
    s.state = f.state;
    s.ua = m.node_vector(in.U(), pair.striker_node());
    s.va = m.node_vector(in.V(), pair.striker_node());
    s.ub = pair.target_vector(in.U());
    s.vb = pair.target_vector(in.V());
    row.contacts.push_back(s);
  }
  row.kinetic = in.kinetic_energy();
  row.strain = in.strain_energy();
  row.dissipated = in.dissipated();
  for (int b = 0; b < m.num_bodies(); ++b)
    for (int c = 0; c < 2; ++c) row.momentum[c] += in.momentum(b, c);
  return row;
}

}  // namespace

RunResult run_paper(const Scene& scene_in) {
  const auto wall0 = std::chrono::steady_clock::now();
  const Effects effects = derive_effects(scene_in);
  const Scene scene = effective_scene(scene_in, effects);
  RunResult r;
  r.method = "paper";
  r.effects = effects.names();
  MethodOptions options(scene, "paper", &r.assumed);
  const long merge_steps = options.reader().integer_or("merge_steps", 3, "a whole number of steps >= 0");
  if (merge_steps < 0) options.reader().fail("merge_steps", "expected a whole number of steps >= 0");
  const double merge_gap = options.reader().number_or("merge_gap", 0.0, "a time >= 0 (s); 0 = use merge_steps");
  if (merge_gap < 0.0) options.reader().fail("merge_gap", "expected a time >= 0 (s)");
  const SurfaceInterpolation surface = options.reader().choice_or("surface", "linear", {"linear", "hermite"}) == "linear"
                                           ? SurfaceInterpolation::kLinear : SurfaceInterpolation::kHermite;
  options.reader().finish();

  const Model model(scene, effects.bending);
  const CriticalStep cs = critical_step(model);
  r.critical_dt = cs.dt;
  const double dt = choose_dt(scene, cs, r);
  r.dt = dt;
  const long N = static_cast<long>(std::ceil(scene.time.end / dt - 1e-9));
  r.steps = N;

  ExplicitContactIntegrator integ(model, scene, effects, dt, surface);
  // Chatter merge: a gap in seconds when given (comparable across dt and methods), else a number
  // of open steps of this run.
  const double steps_gap = (static_cast<double>(merge_steps) + 0.5) * dt;
  const double gap = merge_gap > 0.0 ? merge_gap : steps_gap;
  const std::string rule =
      merge_gap > 0.0
          ? fmt::format("contact phases separated by less than {:.6g} s are merged; an interval runs from its "
                        "first to its last step with R > 0", merge_gap)
          : fmt::format("contact phases separated by fewer than {} open steps ({:.6g} s) are merged; an interval "
                        "runs from its first to its last step with R > 0", merge_steps,
                        static_cast<double>(merge_steps) * dt);
  std::vector<ContactStats> stats(scene.contacts.size(), ContactStats(gap, rule));

  Progress progress("paper", scene.time.end);
  Vec2 p0{};
  for (long p = 0; p <= N; ++p) {
    integ.solve_contacts();
    for (std::size_t c = 0; c < stats.size(); ++c) {
      const ContactForce& f = integ.forces()[c];
      stats[c].add(integ.time(), f.R, f.tau, dt, f.state);
    }
    if (p % scene.time.output_every == 0 || p == N) {
      HistoryRow row = make_row(integ);
      const double E = row.kinetic + row.strain;
      if (p == 0) {
        r.energy_initial = E;
        p0 = row.momentum;
      }
      if (!std::isfinite(E) || E > 1e6 * r.energy_initial + 1e-300)
        throw std::runtime_error(fmt::format(
            "the run diverged at t = {:.6g} s (energy {:.3g} J from {:.3g} J) with dt = {:.6g} s, critical "
            "step {:.6g} s", row.t, E, r.energy_initial, dt, cs.dt));
      r.momentum_drift_max = std::max(r.momentum_drift_max, std::hypot(row.momentum[0] - p0[0], row.momentum[1] - p0[1]));
      r.energy_final = E;
      r.history.push_back(std::move(row));
    }
    if (p < N) integ.advance();
    progress.update(integ.time());
  }

  for (std::size_t c = 0; c < scene.contacts.size(); ++c) {
    ContactSummary s;
    s.striker = scene.bodies[scene.contacts[c].striker].name;
    s.target = scene.bodies[scene.contacts[c].target].name;
    s.kind = to_string(integ.pairs()[c].kind());
    stats[c].fill(s);
    r.contacts.push_back(s);
  }
  for (int b = 0; b < model.num_bodies(); ++b)
    r.final_velocity[scene.bodies[b].name] = {integ.momentum(b, 0) / model.body_mass(b),
                                              integ.momentum(b, 1) / model.body_mass(b)};
  r.extra["critical_step"] = {{"method", "Lanczos on the sparse M^-1 K (M-inner product)"},
                              {"omega_max", cs.omega_max}, {"lanczos_iterations", cs.iterations},
                              {"element_bound_dt", cs.element_bound_dt},
                              {"dt_over_critical", dt / cs.dt}};
  r.extra["dofs"] = model.size();
  r.extra["dofs_per_node"] = model.dofs_per_node();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return r;
}

}  // namespace beamimpact
