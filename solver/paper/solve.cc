#include <solver/paper/solve.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include <solver/integrator/ExplicitContactIntegrator.hpp>
#include <solver/model/critical_dt.hpp>
#include <solver/model/deformed_geometry.hpp>
#include <solver/model/load_vector.hpp>
#include <solver/paper/gap_in_contact.hpp>
#include <solver/record/FieldWriter.hpp>
#include <solver/record/ResultRecorder.hpp>
#include <solver/scene/TableReader.hpp>
#include <solver/scene/run_cost.hpp>
#include <solver/schema/output_schema.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/Progress.hpp>
#include <solver/util/available_cores.hpp>

namespace beamimpact::paper {
namespace {

/// The step: given, or "auto" = fraction x critical; refused above critical unless allowed.
double choose_dt(const Scene& scene, const CriticalStep& cs, SimulationResult& r) {
  if (cs.bound == CriticalBound::kNone) {  // only rigid bodies: no stiffness, no stability limit
    if (!scene.time.dt)
      throw InputError(scene.file, "time.dt",
                       "\"auto\" takes a fraction of the critical step, and a scene of rigid bodies has none "
                       "(no stiffness); expected a step in seconds");
    return *scene.time.dt;
  }
  if (!scene.time.dt) {
    r.assumed["time.dt"] = fmt::format("auto: {} x critical step {:.6g} s", scene.time.fraction, cs.dt);
    return scene.time.fraction * cs.dt;
  }
  const double dt = *scene.time.dt;
  if (dt > cs.dt * (1.0 + 1e-12) && !scene.time.allow_above_critical)
    throw InputError(
        scene.file, "time.dt",
        fmt::format("expected at most the critical step {:.6g} s (2/omega_max, omega_max = "
                    "{:.6g} rad/s an upper estimate for M^-1 K), got {:.6g} s; use dt = \"auto\", a "
                    "smaller dt, or set time.allow_above_critical = true to run anyway",
                    cs.dt, cs.omega_max, dt));
  return dt;
}

/// summary.json's "critical_step": which upper estimate of omega_max set the step, and its margin
/// over the proven element bound.
nlohmann::json critical_step_json(const CriticalStep& cs, double dt) {
  namespace k = critical_step_key;
  if (cs.bound == CriticalBound::kNone)
    return {{k::kMethod, "none: no stiffness (rigid bodies only), no stability limit"},
            {k::kBound, to_string(cs.bound)}};
  return {{k::kMethod,
           "proven upper bound of omega_max: min of the element bound and the subdomain "
           "bound (runs of consecutive elements, each proven by the LDL^T inertia of "
           "sigma M - K); lower bound omega_lower: the Laguerre bracket of each body when every "
           "body is one run, else the top eigenvalue of the bounding run with the equations it "
           "shares with the rest of its body held at zero (Cauchy interlacing)"},
          {k::kBound, to_string(cs.bound)},
          {k::kOmegaMax, cs.omega_max},
          {k::kElementBoundDt, cs.element_bound_dt},
          {k::kOmegaLower, cs.omega_lower},
          {k::kMargin, cs.margin()},
          {k::kDtOverCritical, cs.dt > 0.0 ? dt / cs.dt : 0.0}};
}

/// The chatter merge rule: a gap in seconds when given (comparable across dt and methods), else
/// a number of open steps of this run.
void set_merge_rule(const Options& o, double dt, ResultRecorder& rec) {
  if (o.merge_gap > 0.0) {
    rec.set_merge_rule(o.merge_gap,
                       fmt::format("contact phases separated by less than {:.6g} s are merged; an "
                                   "interval runs from its first to its last step with R > 0",
                                   o.merge_gap));
    return;
  }
  rec.set_merge_rule(
      merge_gap_of(o.merge_steps, dt),
      fmt::format("contact phases separated by fewer than {} open steps ({:.6g} s) are merged; "
                  "an interval runs from its first to its last step with R > 0",
                  o.merge_steps, static_cast<double>(o.merge_steps) * dt));
}

/// One scene contact as the history and the statistics report it. A single pair: its force.
/// A search: R and tau summed over the contact's pairs (each along its own pair's normal and
/// tangent), the state of the pair carrying the largest R, the least gap over the pairs that
/// face the surface; `pair` is that largest-R pair (the primary while all are open).
struct ContactView {
  ContactForce f;
  int pair = 0;
};

ContactView view(const ExplicitContactIntegrator& in, const std::vector<int>& group) {
  const int primary = group.front();
  if (group.size() == 1) return {in.forces()[primary], primary};
  ContactView v{in.forces()[primary], primary};
  v.f.R = v.f.tau = 0.0;
  double Rmax = 0.0;
  for (int p : group) {
    const ContactForce& f = in.forces()[p];
    v.f.R += f.R;
    v.f.tau += f.tau;
    if (in.pairs()[p].on_surface()) v.f.gap_next = std::min(v.f.gap_next, f.gap_next);
    if (f.R > Rmax) {
      Rmax = f.R;
      v.pair = p;
      v.f.state = f.state;
    }
  }
  return v;
}

HistoryRow make_row(const ExplicitContactIntegrator& in) {
  const auto& groups = in.pair_groups();
  const Model& m = in.model();
  HistoryRow row;
  row.t = in.time();
  for (std::size_t c = 0; c < groups.size(); ++c) {
    const ContactView v = view(in, groups[c]);
    const ContactPair& pair = in.pairs()[v.pair];
    const ContactForce& f = v.f;
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
  const ExplicitContactIntegrator::RowSums sums = in.row_sums();  // one pass on the step's threads
  row.kinetic = sums.kinetic;
  row.strain = sums.strain + in.contact_energy();  // the Hertz springs' energy is strain too
  row.dissipated = in.dissipated();
  row.load_work = in.load_work();
  row.momentum = sums.momentum;
  return row;
}

/// The field output and its rows' buffers, kept from row to row (allocated anew, ~1 MB at 1e5 DOFs,
/// each row paid the first touch of fresh pages: on this machine transparent huge pages zeroed
/// 4 MB per row, a quarter of the row).
struct FieldRows {
  FieldRows(const Model& model, const Scene& scene, const std::filesystem::path& dir)
      : writer(model, dir, scene.output.field_format, scene.output.field_precision) {}
  FieldWriter writer;
  std::vector<Vec2> contact_force;                ///< per node (N)
  std::vector<std::array<double, 3>> end_forces;  ///< per element (InternalForce::end_forces)
};

/// The field output of one row: the contact forces on the nodes (each pair's, as its rows apply
/// them) and every element's end forces (the integrator's own operator).
void write_fields(const ExplicitContactIntegrator& in, double t, FieldRows& fields) {
  std::vector<Vec2>& fc = fields.contact_force;
  fc.assign(static_cast<std::size_t>(in.model().num_nodes()), Vec2{0.0, 0.0});
  for (std::size_t p = 0; p < in.pairs().size(); ++p) {
    const ContactForce& f = in.forces()[p];
    if (f.R == 0.0 && f.tau == 0.0) continue;
    for (const auto& [node, F] : in.pairs()[p].nodal_forces(f.R, f.tau)) {
      fc[node][0] += F[0];
      fc[node][1] += F[1];
    }
  }
  in.internal_force().end_forces(in.U(), fields.end_forces, in.team());
  fields.writer.write(t, in.U(), in.V(), fc, fields.end_forces, in.team());
}

/// Above this part of the run's energy the work of a contact's force on its slide along the
/// turned target warns (summary.json "warnings"): 0.1 % (docs/energy.md).
constexpr double kWarnSlideWork = 1e-3;

/// Per scene contact, over the steps in which a sliding pair carries a force: the largest turn of
/// the target under the struck point, and the work of the force along the target's reference
/// normal on the slide.
struct TurnedSlide {
  double turn_max = 0.0;  ///< rad
  double work = 0.0;      ///< J, so far (signed: > 0 put into the bodies)
  double work_max = 0.0;  ///< J, the largest |work| so far
};

/// Adds the step's turn and work to `slide`. The striker is held on the turned chord, so it slides
/// relative to the target along the chord's tangent t' = cos(turn) t + sin(turn) n: at v_t along
/// the reference tangent t, the force R n does R n.t' v_t / cos(turn) = R tan(turn) v_t per
/// second. Nothing slides (v_t = 0): no work, whatever the turn.
void track_turn(const ExplicitContactIntegrator& in, const std::vector<int>& group,
                std::vector<DeformedSurface>& surfaces, TurnedSlide& slide) {
  for (int q : group) {
    const ContactPair& pair = in.pairs()[q];
    const double R = in.forces()[q].R;
    if (!pair.can_slide() || R <= 0.0) continue;
    const RealGap g = surfaces[q].gap(in.U());
    if (g.beyond_end) continue;
    const double turn = surfaces[q].turn(in.U(), g.element, g.xi);
    slide.turn_max = std::max(slide.turn_max, std::abs(turn));
    slide.work += R * std::tan(turn) * in.velocity_along(pair.tangent_row()) * in.dt();
    slide.work_max = std::max(slide.work_max, std::abs(slide.work));
  }
}

/// The warning of a contact whose force worked on its slide along the turned target beyond
/// kWarnSlideWork of the energy `energy` (J; empty otherwise).
std::string turn_warning(const Scene& scene, std::size_t c, const TurnedSlide& slide, double energy) {
  if (!(slide.work_max > kWarnSlideWork * energy)) return {};
  const Contact& k = scene.contacts[c];
  return fmt::format(
      "contact {} -> {}: the contact slid along its target turned by up to {:.3g} rad; the contact "
      "force keeps the target's reference normal (linear contact kinematics), so it works on the "
      "slide: up to {:.3g} J ({:.3g} % of the energy) created or lost (see dissipated and "
      "energy_final); keep that below {:g} % (a stiffer target, a lighter or slower striker, less "
      "slide) for the energy to hold",
      scene.bodies[k.striker].name, scene.bodies[k.target].name, slide.turn_max, slide.work_max,
      100.0 * slide.work_max / energy, 100.0 * kWarnSlideWork);
}

/// Records the complete step p: contact samples, real gaps and the gap under force every step, a
/// row (and the fields, when asked for) every output_every-th step and at the last one. Throws
/// when the energy is no longer finite or has grown 1e6-fold.
void record_step(const ExplicitContactIntegrator& integ, long p, long N, const Scene& scene,
                 double critical_dt, std::vector<DeformedSurface>& surfaces, ResultRecorder& rec,
                 FieldRows* fields, std::vector<TurnedSlide>& slides, GapInContact& in_contact) {
  const auto& groups = integ.pair_groups();
  for (std::size_t c = 0; c < groups.size(); ++c) {
    const ContactForce f = view(integ, groups[c]).f;
    rec.sample(c, integ.time(), f.R, f.tau, integ.dt(), f.state);
    for (int q : groups[c]) rec.track_real_gap(c, integ.time(), surfaces[q].gap(integ.U()).gap);
    track_turn(integ, groups[c], surfaces, slides[c]);
    in_contact.track(c, groups[c], integ.forces(), integ.U(), integ.time());
  }
  if (p % scene.time.output_every != 0 && p != N) return;
  HistoryRow row = make_row(integ);
  const double E = row.kinetic + row.strain;
  // Loads feed the energy: the bound is on the initial energy plus their work so far.
  const double E0 = rec.result().energy_initial + std::abs(row.load_work);
  if (!std::isfinite(E) || E > 1e6 * E0 + 1e-300)
    throw std::runtime_error(fmt::format(
        "the run diverged at t = {:.6g} s (energy {:.3g} J from {:.3g} J) with dt = {:.6g} s, critical "
        "step {:.6g} s",
        row.t, E, E0, integ.dt(), critical_dt));
  rec.track_momentum(row.momentum, row.t);
  if (fields) write_fields(integ, row.t, *fields);
  rec.add_row(std::move(row));
}

/// The threads asked for: by the run, else by the scene, else the default (then written into
/// assumed).
int threads_asked(int run_threads, const Options& o, int dofs, SimulationResult& r) {
  if (run_threads > 0) return run_threads;
  if (o.threads > 0) return o.threads;
  const int asked = default_threads(dofs);
  r.assumed["paper.threads"] =
      fmt::format("{}: the machine's {} available cores ({}), 1 below {} equations (this model: {})", asked,
                  available_cores().count, available_cores().source, kThreadsMinDofs, dofs);
  return asked;
}

/// The threads a run takes: those asked for, at most the cores available (a thread beyond them
/// only waits for a core; the history is the same bits at any count). Writes the choice into
/// summary.json's settings block, `threads`: asked, cores, used and why; a capped count also
/// warns (stderr from the command line, summary.json `warnings`).
class ThreadChoice {
 public:
  ThreadChoice(int asked, SimulationResult& r) : asked_(asked), cores_(available_cores()) {
    if (asked_ <= cores_.count) return;
    cap_ = fmt::format("{} threads asked for; cores available: {} ({}): capped to {}", asked_, cores_.count,
                       cores_.source, cores_.count);
    r.extra["warnings"].push_back(cap_);
  }
  /// @brief The count to start the step with.
  int start() const { return std::min(asked_, cores_.count); }
  /// @brief Records the count the integrator runs and why it is that one.
  void record(const ExplicitContactIntegrator& integ, SimulationResult& r) const {
    std::string why = cap_;
    if (!integ.threads_note().empty()) why += (why.empty() ? "" : "; ") + integ.threads_note();
    if (why.empty())
      why = r.assumed.count("paper.threads") ? "the default (assumed paper.threads)" : "as asked";
    r.extra["threads"] = integ.threads();
    if (!integ.threads_note().empty()) r.extra["threads_note"] = integ.threads_note();
    r.settings["threads"] = {
        {"asked", asked_}, {"cores", cores_.count}, {"used", integ.threads()}, {"why", why}};
  }

 private:
  int asked_;
  AvailableCores cores_;
  std::string cap_;
};

}  // namespace

Options Options::read(const Scene& scene, std::map<std::string, std::string>* assumed) {
  MethodOptions table(scene, "paper", assumed);
  TableReader& in = table.reader();
  Options o;
  o.merge_steps = in.integer_or("merge_steps", o.merge_steps, "a whole number of steps >= 0");
  if (o.merge_steps < 0) in.fail("merge_steps", "expected a whole number of steps >= 0");
  o.merge_gap = in.number_or("merge_gap", o.merge_gap, "a time >= 0 (s); 0 = use merge_steps");
  if (o.merge_gap < 0.0) in.fail("merge_gap", "expected a time >= 0 (s)");
  o.surface = in.choice_or("surface", "linear", {"linear", "hermite"}) == "linear"
                  ? SurfaceInterpolation::kLinear
                  : SurfaceInterpolation::kHermite;
  o.closure_slip = in.choice_or("closure_slip", "step", {"step", "from_closure"}) == "step"
                       ? ClosureSlip::kWholeStep
                       : ClosureSlip::kFromClosure;
  if (in.has("threads")) {  // else the default, written once the model's size is known
    const long t = in.integer("threads", fmt::format("a whole number of threads 1..{}", kMaxThreads));
    if (!valid_thread_count(t))
      in.fail("threads", fmt::format("expected a whole number of threads 1..{}, got {}", kMaxThreads, t));
    o.threads = static_cast<int>(t);
  }
  in.finish();
  return o;
}

SimulationResult solve(const Scene& scene_in, const std::filesystem::path& fields_dir, int threads) {
  ResultRecorder rec(scene_in, "paper", ContactSampling::kFixedSteps);
  SimulationResult& r = rec.result();
  const Effects effects = derive_effects(scene_in);
  const Scene scene = effective_scene(scene_in, effects);
  r.effects = effects.names();
  const Options options = Options::read(scene, &r.assumed);

  const Model model(scene, effects.bending);
  const CriticalStep cs = critical_step(model);
  r.critical_dt = cs.dt;
  r.dt = choose_dt(scene, cs, r);
  // The run was admitted at the wave estimate of the step (planned_dt); a frame's bending step can
  // be far below it, and the steps, the work and the field files grow with 1/dt: checked again
  // at the step the run takes, before anything is written. The check's estimate is the step count.
  const long N = static_cast<long>(check_run_cost(scene, r.dt).steps);
  r.steps = N;
  set_merge_rule(options, r.dt, rec);

  const ThreadChoice thread_choice(threads_asked(threads, options, model.size(), r), r);
  ExplicitContactIntegrator integ(model, scene, effects, r.dt, options.surface, thread_choice.start());
  integ.set_closure_slip(options.closure_slip);
  thread_choice.record(integ, r);  // the threads used, and why when fewer than asked
  rec.set_initial_energy(integ.initial_energy());
  if (effects.loads) rec.set_load_force(net_load_force(model, load_vector(model, scene)));
  std::vector<DeformedSurface> surfaces;  // the real gap of each pair, from the deformed geometry
  for (const ContactPair& pair : integ.pairs())
    surfaces.emplace_back(model, pair.target_body(), pair.striker_node());
  std::optional<FieldRows> fields;
  if (!fields_dir.empty()) fields.emplace(model, scene, fields_dir);
  Progress progress("paper", scene.time.end);
  progress.set_dofs_per_update(model.size());
  std::vector<TurnedSlide> slides(scene.contacts.size());
  GapInContact in_contact(model, scene, integ.pairs(), options.surface);
  for (long p = 0;; ++p) {
    record_step(integ, p, N, scene, cs.dt, surfaces, rec, fields ? &*fields : nullptr, slides, in_contact);
    if (p == N) break;
    integ.step();
    progress.update(integ.time());
  }
  if (fields) fields->writer.finish();

  for (int b = 0; b < model.num_bodies(); ++b)
    rec.set_final_velocity(scene.bodies[b].name, {integ.momentum(b, 0) / model.body_mass(b),
                                                  integ.momentum(b, 1) / model.body_mass(b)});
  r.extra["critical_step"] = critical_step_json(cs, r.dt);
  r.extra["dofs"] = model.size();
  r.dofs = model.size();
  r.extra["dofs_per_node"] = model.dofs_per_node();
  std::vector<ContactKind> kinds;
  for (const auto& group : integ.pair_groups()) kinds.push_back(integ.pairs()[group.front()].kind());
  SimulationResult result = rec.finish(kinds);
  for (std::size_t c = 0; c < scene.contacts.size(); ++c) {
    result.contacts[c].extra["target_turn_max"] = slides[c].turn_max;
    result.contacts[c].extra["turned_slide_work"] = slides[c].work_max;
    const double energy = std::max(result.energy_initial, result.energy_final);
    if (const std::string w = turn_warning(scene, c, slides[c], energy); !w.empty())
      result.extra["warnings"].push_back(w);
  }
  in_contact.report(scene, result);
  for (std::size_t c = 0; c < scene.contacts.size(); ++c) {
    result.contacts[c].friction = scene.contacts[c].friction;  // as applied
    result.contacts[c].extra["contact_search"] =
        scene.contacts[c].search
            ? fmt::format(
                  "all nodes: {} node pairs (every striker node off the target's axis, the "
                  "target's end nodes against the striker); node {} reported while open",
                  integ.pair_groups()[c].size(), scene.contacts[c].node)
            : fmt::format("declared node {} only (the paper's method)", scene.contacts[c].node);
  }
  return result;
}

}  // namespace beamimpact::paper
