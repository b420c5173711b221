#include <references/ida/solve.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include <references/ida/ContactKinematics.hpp>
#include <references/ida/PenaltyIda.hpp>
#include <references/ida/ida_options.hpp>
#include <references/ida/step_mean_rows.hpp>
#include <solver/model/Effects.hpp>
#include <solver/model/MassSolver.hpp>
#include <solver/model/Model.hpp>
#include <solver/model/critical_dt.hpp>
#include <solver/model/deformed_geometry.hpp>
#include <solver/model/load_vector.hpp>
#include <solver/record/ContactIntervals.hpp>
#include <solver/record/ResultRecorder.hpp>
#include <solver/scene/run_cost.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/Progress.hpp>

namespace beamimpact::ida {
namespace {

std::string str(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

/// 1 / (G^T M^-1 G): the effective mass of the contact's relative normal motion (kg).
double reduced_mass(const Model& model, const ContactFrame& f) {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(model.size()), mg;
  for (const DofTerm& d : f.n_terms) g(d.eq) += d.coeff;
  MassSolver(model).apply(g, mg);
  return 1.0 / g.dot(mg);
}

Vec2 lerp(const Vec2& a, const Vec2& b, double w) {
  return {(1 - w) * a[0] + w * b[0], (1 - w) * a[1] + w * b[1]};
}

/// The effects of the scene, derived as for every method. The bodies that the scene makes
/// corotational run the IDA reference's own corotational elements (ElasticForce) with lumped
/// mass, the same in every frame; with consistent mass (a mass that turns with the element) the
/// IDA reference keeps global axes. Either is said in `assumed` and in r.kinematics.
Effects ida_effects(const Scene& scene, SimulationResult& r) {
  Effects e = derive_effects(scene);
  const std::string contact =
      "the contact keeps the target's reference normal and a sliding interpolated struck point";
  if (e.corotational && scene.model.mass == MassKind::kLumped) {
    r.kinematics = "corotational";
    r.assumed["ida.kinematics"] =
        "corotational: each element of a rotating body has its rigid rotation taken out and its local linear "
        "stiffness applied in the rotated frame (ElasticForce); lumped mass; " +
        contact;
    return e;
  }
  if (scene.model.kinematics == Kinematics::kCorotational)
    r.assumed["ida.kinematics"] =
        e.corotational
            ? "linear: the scene asks for corotational with consistent mass, which the IDA reference "
              "does not rotate; it keeps global axes, and " +
                  contact
            : "linear: no body can rotate (corotational changes nothing); " + contact;
  else
    r.assumed["ida.kinematics"] = "linear: " + contact;
  r.kinematics = "linear";
  e.corotational = false;
  e.rotating.assign(scene.bodies.size(), false);
  return e;
}

/// The contacts' geometry and penalty laws, with what was assumed written into `r`.
struct PenaltyContacts {
  std::vector<std::unique_ptr<ModelContact>> geometry;
  std::vector<PenaltyLaw> laws;
  std::vector<double> reduced_mass;                ///< kg, per contact: the two contact points' reduced mass
  nlohmann::json extra = nlohmann::json::array();  ///< per contact: kn, cn, restitution, ...
};

PenaltyContacts make_penalty_contacts(const Scene& scene, const Model& model, const IdaOptions& opt,
                                      bool friction, SimulationResult& r) {
  PenaltyContacts pc;
  const Eigen::VectorXd U0 = Eigen::VectorXd::Zero(model.size());
  for (int i = 0; i < static_cast<int>(scene.contacts.size()); ++i) {
    pc.geometry.push_back(std::make_unique<ModelContact>(model, scene, i));
    const ModelContact& geo = *pc.geometry.back();
    const std::string key = "ida.contacts[" + std::to_string(i) + "].";
    PenaltyLaw law;
    law.kn = opt.kn.value_or(opt.kn_factor * geo.element_stiffness());
    const double m_red = reduced_mass(model, geo.evaluate(U0));
    double zeta = 0.0;
    if (scene.contacts[i].law == ContactLaw::kHertz) {
      // The scene's own Hertz spring, elastic as in the paper method: no penalty, no dashpot.
      law.hertz = true;
      law.kn = scene.contacts[i].hertz_stiffness;
      law.cn = 0.0;
      r.assumed[key + "law"] = "hertz: the scene's spring kn |g|^(3/2), kn " + str(law.kn) + " N/m^1.5, cn 0";
    } else if (opt.cn) {
      law.cn = *opt.cn;
      zeta = law.cn / (2.0 * std::sqrt(law.kn * m_red));
    } else {
      zeta = opt.damping_ratio ? *opt.damping_ratio : damping_ratio_for_restitution(opt.restitution);
      law.cn = 2.0 * zeta * std::sqrt(law.kn * m_red);
    }
    law.mu = friction ? scene.contacts[i].friction : 0.0;
    law.v_reg = opt.friction_velocity;
    if (!opt.kn && !law.hertz) r.assumed[key + "kn"] = str(law.kn) + " N/m (kn_factor x EA/le)";
    if (!law.hertz)
      r.assumed[key + "cn"] = str(law.cn) + " N s/m (damping ratio " + str(zeta) + ", two-mass restitution " +
                              str(restitution_for_damping_ratio(zeta)) + ", m_red " + str(m_red) + " kg)";
    pc.extra.push_back({{"kind", to_string(geo.kind())},
                        {"kn", law.kn},
                        {"cn", law.cn},
                        {"damping_ratio", zeta},
                        {"restitution", restitution_for_damping_ratio(zeta)},
                        {"reduced_mass", m_red},
                        {"friction_velocity", law.v_reg}});
    if (law.hertz)
      pc.extra.back()["law"] = "hertz";  // kn in N/m^1.5; no fixed period
    else
      pc.extra.back()["contact_period"] = M_PI * std::sqrt(m_red / law.kn);
    pc.laws.push_back(law);
    pc.reduced_mass.push_back(m_red);
  }
  return pc;
}

/// IDA resolves a closed penalty contact's oscillation (period 2 pi sqrt(m_red / kn)) with some
/// 20 steps; a contact that stays closed for the whole run then costs 20 end / period steps. A
/// striker of vanishing mass under a stiff penalty would make that astronomically many (a run
/// that never ends): refused like any run far beyond the ordinary (run_cost.hpp) unless
/// time.allow_long_run is set.
void check_penalty_cost(const Scene& scene, const PenaltyContacts& pc, int unknowns) {
  if (scene.time.allow_long_run) return;
  for (std::size_t i = 0; i < pc.laws.size(); ++i) {
    // A Hertz spring softens as it opens (no fixed period): its cost follows the impact and is
    // bounded by the run's own dynamics, not by a penalty the reference chose.
    if (pc.laws[i].hertz) continue;
    const double m_red = pc.reduced_mass[i];
    const double period = 2.0 * M_PI * std::sqrt(m_red / pc.laws[i].kn);
    const double steps = 20.0 * scene.time.end / period;
    if (!(steps * unknowns <= kOrdinaryWork))
      throw InputError(
          scene.file, "time.allow_long_run",
          fmt::format("IDA's penalty on contacts[{}] oscillates with a period of {:.3g} s "
                      "(kn {:.3g} N/m, reduced mass {:.3g} kg): resolving it over time.end = "
                      "{:g} s takes about {:.3g} steps x {} unknowns, beyond an ordinary run "
                      "({:g}); set time.allow_long_run = true (or --allow-long), or a softer "
                      "ida.kn",
                      i, period, pc.laws[i].kn, m_red, scene.time.end, steps, unknowns, kOrdinaryWork));
  }
}

/// IDA's tolerances and linear solver: dense, or KLU ("auto": dense up to opt.dense_max unknowns).
IdaSettings make_settings(const IdaOptions& opt, int n, SimulationResult& r) {
  IdaSettings settings;
  settings.rtol = opt.rtol;
  settings.atol = opt.atol;
  settings.max_step = opt.max_step;
  const bool dense = opt.linear_solver == "dense" || (opt.linear_solver == "auto" && 2 * n <= opt.dense_max);
  settings.linear_solver = dense ? IdaLinearSolver::kDense : IdaLinearSolver::kKlu;
  if (opt.linear_solver == "auto")
    r.assumed["ida.linear_solver"] = std::string(dense ? "dense" : "klu") + " (auto: dense up to " +
                                     std::to_string(opt.dense_max) + " unknowns)";
  return settings;
}

/// Reads the running IDA solution as history rows and contact samples.
class Observer {
 public:
  Observer(const Model& model, const PenaltyIda& ida, const PenaltyContacts& contacts,
           const Eigen::VectorXd& load, const ElasticForce& elastic)
      : model_(model), ida_(ida), contacts_(contacts), load_(load), elastic_(elastic) {}

  Vec2 momentum(const Eigen::Ref<const Eigen::VectorXd>& V) const {
    Vec2 p{0.0, 0.0};
    for (int b = 0; b < model_.num_bodies(); ++b)
      for (int c = 0; c < 2; ++c) p[c] += model_.momentum_covector(b, c).dot(V);
    return p;
  }

  ContactState state(int i, const ContactReading& r) const {
    if (!r.closed) return ContactState::kOpen;
    if (contacts_.laws[i].mu > 0.0 && std::abs(r.slip_rate) > contacts_.laws[i].v_reg)
      return ContactState::kSlip;
    return ContactState::kStick;
  }

  HistoryRow row() const {
    HistoryRow row;
    row.t = ida_.t();
    const auto U = ida_.U();
    const auto V = ida_.V();
    for (int i = 0; i < static_cast<int>(contacts_.laws.size()); ++i) {
      const ContactReading r = ida_.contact(i);
      const ModelContact& geo = *contacts_.geometry[i];
      ContactSample s;
      s.R = r.R;
      s.tau = r.tau;
      s.gap = r.gap;
      s.ua = model_.node_vector(U, geo.striker_node());
      s.va = model_.node_vector(V, geo.striker_node());
      const auto nodes = geo.segment_nodes(r.frame);
      s.ub = lerp(model_.node_vector(U, nodes[0]), model_.node_vector(U, nodes[1]), r.frame.xi2);
      s.vb = lerp(model_.node_vector(V, nodes[0]), model_.node_vector(V, nodes[1]), r.frame.xi2);
      s.state = state(i, r);
      row.contacts.push_back(s);
    }
    row.kinetic = 0.5 * V.dot(model_.M() * V);
    row.strain = elastic_.energy(U);  // + the penalty springs
    for (int i = 0; i < static_cast<int>(contacts_.laws.size()); ++i)
      row.strain += ida_.contact(i).penalty_energy;
    row.dissipated = ida_.dissipated();
    if (load_.size()) row.load_work = load_.dot(U);
    row.momentum = momentum(V);
    return row;
  }

 private:
  const Model& model_;
  const PenaltyIda& ida_;
  const PenaltyContacts& contacts_;
  const Eigen::VectorXd& load_;
  const ElasticForce& elastic_;
};

/// Contact i's intervals from the located onset and release events (exact switch times), each
/// onset-to-release a phase of ContactIntervals; an interval still closed ends at t_end.
std::vector<std::array<double, 2>> event_intervals(const std::vector<ContactEvent>& events, int i,
                                                   double merge_gap, double t_end, nlohmann::json& listed) {
  ContactIntervals intervals(merge_gap);
  bool open = false;
  for (const ContactEvent& e : events) {
    if (e.contact != i) continue;
    listed.push_back({e.t, e.onset ? "onset" : "release"});
    if (e.onset) {
      intervals.begin(e.t);
      open = true;
    } else if (open) {
      intervals.extend(e.t);
      open = false;
    }
  }
  if (open) intervals.extend(t_end);
  return intervals.intervals();
}

/// One contact's running impulse (quadrature) after every accepted step: (t, J(t)).
using ImpulseTrace = std::vector<std::array<double, 2>>;

/// Per contact, over the accepted steps, the penalty force as IDA solves it. At a first touch the
/// dashpot jumps to cn times the closing speed (S1: 608 N against the exact 2 N), absorbs the
/// closing speed within m_red / cn and leaves the spring compressed by about m_red v / cn, which
/// relaxes through the dashpot with time constant cn / kn: the closure's transient, the penalty's
/// counterpart of the paper's closure step. Its onsets and the closure window kClosureWindow x
/// cn / kn after each feed the rows' peaks (StepMeanRows); the instantaneous force's own peak and
/// the jump are stated apart.
struct ForcePeaks {
  static constexpr double kClosureWindow = 5.0;  ///< time constants: e^-5 = 0.7 % of the overshoot left
  std::vector<double> total, dashpot_jump;
  std::vector<std::vector<double>> onsets;  ///< every onset of each contact (s)
  std::vector<char> was_closed;
  explicit ForcePeaks(int nc) : total(nc, 0.0), dashpot_jump(nc, 0.0), onsets(nc), was_closed(nc, 0) {}
  /// @brief Adds contact i's reading of an accepted step from t_prev (s) under law `law`.
  void add(int i, const ContactReading& r, const PenaltyLaw& law, double t_prev) {
    if (r.closed) {
      if (!was_closed[i]) {
        onsets[i].push_back(t_prev);
        dashpot_jump[i] = std::max(dashpot_jump[i], r.R - law.normal_force(r.gap, 0.0));
      }
      total[i] = std::max(total[i], r.R);
    }
    was_closed[i] = r.closed;
  }
  /// @brief The closure window of each contact (s): kClosureWindow x cn / kn, 0 without a dashpot.
  static std::vector<double> windows(const std::vector<PenaltyLaw>& laws) {
    std::vector<double> w;
    for (const PenaltyLaw& law : laws) w.push_back(law.kn > 0.0 ? kClosureWindow * law.cn / law.kn : 0.0);
    return w;
  }
};

/// The largest mean force over a window of the mesh's shortest period W = 2 pi / omega_max, from
/// the running impulse (J(s + W) - J(s)) / W, windows that meet a closure window left out. The
/// lumped mesh passes a wave front with a fixed overshoot at its cutoff frequency omega_max (S1:
/// 2.1844 N against the continuum's 2 N at 10 and at 40 elements, in the paper integrator's run
/// as in this one): the force the mesh resolves is its mean over that period. The ringing keeps
/// its shape in units of le / c, so the mean keeps the same small share of it at every mesh (S1:
/// 2.0304 N at 10 and at 40 elements, 1.5 %). Without a period (W <= 0), the peak itself.
double resolved_peak(const ImpulseTrace& trace, const std::vector<double>& onsets, double closure, double W,
                     double peak) {
  if (!(W > 0.0) || !std::isfinite(W) || trace.size() < 2) return peak;
  const auto J = [&](double t) {
    const auto it = std::lower_bound(trace.begin(), trace.end(), t,
                                     [](const std::array<double, 2>& p, double x) { return p[0] < x; });
    if (it == trace.begin()) return (*it)[1];
    const auto& [t1, j1] = *it;
    const auto& [t0, j0] = *(it - 1);
    return t1 > t0 ? j0 + (j1 - j0) * (t - t0) / (t1 - t0) : j1;
  };
  double best = 0.0;
  for (const auto& point : trace) {  // not a structured binding: a lambda below captures s
    const double s = point[0], js = point[1];
    const double e = s + W;
    if (e > trace.back()[0]) break;
    const bool meets_closure =
        std::any_of(onsets.begin(), onsets.end(), [&](double o) { return o < e && o + closure > s; });
    if (!meets_closure) best = std::max(best, (J(e) - js) / W);
  }
  return best;
}

/// The impulse of each interval: J at the middle of the open gap after it less J at the middle of
/// the gap before it (J is constant while open, so any step there gives its exact value).
std::vector<double> interval_impulses(const std::vector<std::array<double, 2>>& iv, const ImpulseTrace& trace,
                                      double t_end) {
  const auto J = [&](double t) {
    double j = 0.0;
    for (const auto& [ts, js] : trace)
      if (ts <= t) j = js;
    return j;
  };
  std::vector<double> out;
  for (std::size_t i = 0; i < iv.size(); ++i) {
    const double lo = i == 0 ? 0.0 : 0.5 * (iv[i - 1][1] + iv[i][0]);
    const double hi = i + 1 < iv.size() ? 0.5 * (iv[i][1] + iv[i + 1][0]) : t_end;
    out.push_back(J(hi) - J(lo));
  }
  return out;
}

/// What the run keeps of its contacts beside the recorder: the impulse traces, the instantaneous
/// force's peaks and the rows with their step means.
struct ContactTracks {
  std::vector<ImpulseTrace> traces;
  ForcePeaks peaks;
  StepMeanRows rows;
  ContactTracks(ResultRecorder& rec, const std::vector<PenaltyLaw>& laws)
      : traces(laws.size()), peaks(static_cast<int>(laws.size())), rows(rec, ForcePeaks::windows(laws)) {}
  /// @brief Each contact's running (normal, tangential) impulse at IDA's current time (N s).
  static std::vector<std::array<double, 2>> impulses(const PenaltyIda& ida, int nc) {
    std::vector<std::array<double, 2>> j;
    for (int i = 0; i < nc; ++i) j.push_back({ida.impulse_normal(i), ida.impulse_tangential(i)});
    return j;
  }
};

/// Integrates to the end, one row per output time on the paper's grid: p h for every
/// every-th p and the last step N = ceil(end / h), so that the two methods' rows line up; each
/// row's forces are their means over the step it begins (StepMeanRows). Returns the output step (s).
double integrate(const Scene& scene, const IdaOptions& opt, double dt, PenaltyIda& ida, const Observer& obs,
                 const Model& model, ResultRecorder& rec, ContactTracks& tracks,
                 const std::vector<PenaltyLaw>& laws) {
  const int nc = static_cast<int>(scene.contacts.size());
  std::vector<DeformedSurface> surfaces;  // the real gap of each contact, from the deformed geometry
  for (const Contact& c : scene.contacts)
    surfaces.emplace_back(model, c.target, model.node_id(c.striker, c.node));
  Progress progress("ida", scene.time.end);  // stderr, only on long runs
  auto on_step = [&](double t_prev) {
    progress.update(ida.t());
    for (int i = 0; i < nc; ++i) {
      const ContactReading r = ida.contact(i);
      rec.sample(i, ida.t(), r.R, r.tau, ida.t() - t_prev, obs.state(i, r));
      tracks.peaks.add(i, r, laws[i], t_prev);
      if (r.closed) tracks.rows.touch(i);
      rec.track_real_gap(i, ida.t(), surfaces[i].gap(ida.U()).gap);
      tracks.traces[i].push_back({ida.t(), ida.impulse_normal(i)});
    }
    rec.track_momentum(obs.momentum(ida.V()), ida.t());
  };
  tracks.rows.add(obs.row(), ContactTracks::impulses(ida, nc), tracks.peaks.onsets);
  const double h = opt.output_step.value_or(dt);
  const long every = opt.output_step ? 1 : scene.time.output_every;
  const long N = step_count(scene, h);
  rec.result().assumed["ida.output_step"] = str(h * static_cast<double>(every)) + " s" +
                                            (opt.output_step ? "" : " (the scene's dt x output_every)");
  for (long p = 1; p <= N; ++p) {
    if (p % every != 0 && p != N) continue;
    ida.advance_to(static_cast<double>(p) * h, on_step);
    tracks.rows.add(obs.row(), ContactTracks::impulses(ida, nc), tracks.peaks.onsets);
  }
  tracks.rows.finish(tracks.peaks.onsets);
  return h * static_cast<double>(every);
}

/// The output grid's step: the scene's dt ("auto": fraction x the critical step of M^-1 K, the
/// same grid as the paper's run, whose critical step is written into `r`).
double output_grid_step(const Scene& scene, const Model& model, SimulationResult& r) {
  if (scene.time.dt) return *scene.time.dt;
  r.critical_dt = critical_step(model).dt;
  return scene.time.fraction * r.critical_dt;
}

/// The summary's "ida" block: settings, IDA's counters and each contact's penalty law.
nlohmann::json ida_extra(const IdaOptions& opt, const IdaSettings& settings, int n, const IdaCounters& c,
                         double output_step, double dissipated, const nlohmann::json& contacts) {
  return {{"rtol", opt.rtol},
          {"atol", opt.atol},
          {"linear_solver", settings.linear_solver == IdaLinearSolver::kDense ? "dense" : "klu"},
          {"unknowns", 2 * n},
          {"steps", c.steps},
          {"residual_evals", c.residual_evals},
          {"jacobian_evals", c.jacobian_evals},
          {"nonlinear_iters", c.nonlinear_iters},
          {"error_test_fails", c.error_test_fails},
          {"nonlinear_conv_fails", c.nonlinear_conv_fails},
          {"root_evals", c.root_evals},
          {"events", c.events},
          {"klu_pattern_changes", c.klu_pattern_changes},
          {"warnings", c.warnings},
          {"output_step", output_step},
          {"dissipated", dissipated},
          {"contacts", contacts}};
}

/// Each contact's intervals from the located events and impulses from the quadratures; the peaks
/// from the rows, the force of the protocol (StepMeanRows), the instantaneous force's stated apart;
/// stick/slip counts stay the recorder's (from the accepted steps).
void summarize_contacts(const PenaltyIda& ida, const PenaltyContacts& contacts, const ContactTracks& tracks,
                        double merge_gap, double shortest_period, SimulationResult& result) {
  const std::vector<ImpulseTrace>& traces = tracks.traces;
  const ForcePeaks& peaks = tracks.peaks;
  const std::vector<double> windows = ForcePeaks::windows(contacts.laws);
  for (int i = 0; i < static_cast<int>(result.contacts.size()); ++i) {
    ContactSummary& s = result.contacts[i];
    const double step_sum = s.impulse_normal;
    nlohmann::json events = nlohmann::json::array();
    s.intervals = event_intervals(ida.events(), i, merge_gap, ida.t(), events);
    s.impulse_normal = ida.impulse_normal(i);
    s.interval_impulses = interval_impulses(s.intervals, traces[i], ida.t());
    s.impulse_tangential = ida.impulse_tangential(i);
    s.extra = contacts.extra[i];
    s.extra["events"] = events;
    s.extra["impulse_normal_step_sum"] = step_sum;
    // The rows' step means, as the history: every row, the rows whose step meets a closure window
    // left out, the first row in contact. The instantaneous penalty force's peak and the dashpot's
    // jump (ForcePeaks) are stated apart.
    const RowPeaks& rows = tracks.rows.peaks()[i];
    s.peak_R = rows.all;
    s.peak_R_excluding_closure = rows.outside_closure;
    s.first_step_R = rows.first_closure;
    s.extra["peak_R_with_closure"] = peaks.total[i];
    s.extra["closure_dashpot_jump"] = peaks.dashpot_jump[i];
    s.extra["closure_window"] = windows[i];
    s.extra["peak_R_resolved"] =
        resolved_peak(traces[i], peaks.onsets[i], windows[i], shortest_period, s.peak_R_excluding_closure);
    s.extra["resolved_window"] = shortest_period;
    s.friction = contacts.laws[i].mu;  // as applied
  }
}

}  // namespace

SimulationResult solve(const Scene& scene) {
  ResultRecorder rec(scene, "ida", ContactSampling::kAdaptiveSteps);
  SimulationResult& r = rec.result();
  const Effects effects = ida_effects(scene, r);
  const Model model(scene, effects.bending);
  const int n = model.size();

  const double dt = output_grid_step(scene, model, r);
  double v_scale = 0.0;
  for (const Body& b : scene.bodies) v_scale = std::max(v_scale, std::hypot(b.velocity[0], b.velocity[1]));
  const IdaOptions opt = read_ida_options(scene, dt, v_scale, &r.assumed);
  r.dt = dt;
  r.effects = effects.names();

  SparseMatrix C;
  if (effects.damping) C = model.rayleigh_mass() * model.M() + model.rayleigh_stiffness() * model.K();
  const PenaltyContacts contacts = make_penalty_contacts(scene, model, opt, effects.friction, r);
  check_penalty_cost(scene, contacts, n);
  std::vector<const ContactKinematics*> kinematics;
  for (const auto& g : contacts.geometry) kinematics.push_back(g.get());
  const IdaSettings settings = make_settings(opt, n, r);

  PenaltyIda ida(model.M(), model.K(), C, kinematics, contacts.laws, settings);
  const ElasticForce elastic(model, effects.rotating);
  if (elastic.corotational()) ida.set_elastic(&elastic);
  const Eigen::VectorXd load = effects.loads ? load_vector(model, scene) : Eigen::VectorXd();
  ida.set_load(load);
  const Eigen::VectorXd V0 = model.initial_velocity();
  ida.start(0.0, Eigen::VectorXd::Zero(n), V0);
  const Observer obs(model, ida, contacts, load, elastic);
  rec.set_load_force(net_load_force(model, load));
  rec.track_momentum(obs.momentum(V0), 0.0);
  std::ostringstream rule;
  rule << "contact phases (located by IDA root finding) separated by less than " << opt.merge_gap
       << " s are merged";
  rec.set_merge_rule(opt.merge_gap, rule.str());
  ContactTracks tracks(rec, contacts.laws);
  const double output_step = integrate(scene, opt, dt, ida, obs, model, rec, tracks, contacts.laws);

  const auto V = ida.V();
  for (int b = 0; b < model.num_bodies(); ++b) {
    const double m = model.body_mass(b);
    rec.set_final_velocity(scene.bodies[b].name, {model.momentum_covector(b, 0).dot(V) / m,
                                                  model.momentum_covector(b, 1).dot(V) / m});
  }
  const IdaCounters c = ida.counters();
  r.steps = c.steps;
  r.dofs = n;
  r.extra["ida"] = ida_extra(opt, settings, n, c, output_step, ida.dissipated(), contacts.extra);

  std::vector<ContactKind> kinds;
  for (const auto& g : contacts.geometry) kinds.push_back(g->kind());
  SimulationResult result = rec.finish(kinds);
  // The mesh's shortest period 2 pi / omega_max (omega_max: the critical step's proven bound).
  const double omega_max = critical_step(model).omega_max;
  summarize_contacts(ida, contacts, tracks, opt.merge_gap, omega_max > 0.0 ? 2.0 * M_PI / omega_max : 0.0,
                     result);
  return result;
}

}  // namespace beamimpact::ida
