#include "ida/run_ida.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>

#include "ida/ContactKinematics.hpp"
#include "ida/PenaltyIda.hpp"
#include "ida/ida_options.hpp"
#include "io/ContactStats.hpp"
#include "io/Progress.hpp"
#include "model/MassSolver.hpp"
#include "model/Model.hpp"
#include "model/critical_dt.hpp"

namespace beamimpact {
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

}  // namespace

RunResult run_ida(const Scene& scene) {
  const auto wall0 = std::chrono::steady_clock::now();
  RunResult res;
  res.method = "ida";

  const bool bending = scene.effects.bending.value_or(!scene_is_collinear(scene));
  const Model model(scene, bending);
  const int n = model.size();

  // Output grid: the scene's dt ("auto": fraction x the critical step of M^-1 K).
  double dt = scene.time.dt.value_or(0.0);
  if (!scene.time.dt) {
    res.critical_dt = critical_step(model).dt;  // the same grid as the paper's run
    dt = scene.time.fraction * res.critical_dt;
  }
  double v_scale = 0.0;
  for (const Body& b : scene.bodies) v_scale = std::max(v_scale, std::hypot(b.velocity[0], b.velocity[1]));
  const IdaOptions opt = read_ida_options(scene, dt, v_scale, &res.assumed);
  res.dt = dt;

  // Effects a scene asks for (and only those).
  bool friction = false;
  for (const Contact& c : scene.contacts) friction |= c.friction > 0.0;
  friction = scene.effects.friction.value_or(friction);
  const bool damping = scene.effects.damping.value_or(model.damped());
  res.effects = {"axial"};
  if (bending) res.effects.push_back("bending");
  if (friction) res.effects.push_back("friction");
  if (damping) res.effects.push_back("damping");
  if (scene.model.kinematics == Kinematics::kCorotational)
    res.assumed["ida.kinematics"] =
        "linear: the scene asks for corotational, the IDA reference keeps global axes, the "
        "target's reference normal and a sliding interpolated struck point; large-rotation "
        "agreement with the paper's corotational run is not expected";
  else
    res.assumed["ida.kinematics"] = "linear (reference normal, sliding interpolated struck point)";

  SparseMatrix C;
  if (damping) C = model.rayleigh_mass() * model.M() + model.rayleigh_stiffness() * model.K();

  // Contacts and their penalty laws.
  std::vector<std::unique_ptr<ModelContact>> geo;
  std::vector<const ContactKinematics*> kin;
  std::vector<PenaltyLaw> laws;
  const Eigen::VectorXd U0 = Eigen::VectorXd::Zero(n);
  nlohmann::json contact_extra = nlohmann::json::array();
  for (int i = 0; i < static_cast<int>(scene.contacts.size()); ++i) {
    geo.push_back(std::make_unique<ModelContact>(model, scene, i));
    kin.push_back(geo.back().get());
    const std::string key = "ida.contacts[" + std::to_string(i) + "].";
    PenaltyLaw law;
    law.kn = opt.kn.value_or(opt.kn_factor * geo.back()->element_stiffness());
    const double m_red = reduced_mass(model, geo.back()->evaluate(U0));
    double zeta = 0.0;
    if (opt.cn) {
      law.cn = *opt.cn;
      zeta = law.cn / (2.0 * std::sqrt(law.kn * m_red));
    } else {
      zeta = opt.damping_ratio ? *opt.damping_ratio : damping_ratio_for_restitution(opt.restitution);
      law.cn = 2.0 * zeta * std::sqrt(law.kn * m_red);
    }
    law.mu = friction ? scene.contacts[i].friction : 0.0;
    law.v_reg = opt.friction_velocity;
    if (!opt.kn) res.assumed[key + "kn"] = str(law.kn) + " N/m (kn_factor x EA/le)";
    res.assumed[key + "cn"] = str(law.cn) + " N s/m (damping ratio " + str(zeta) +
                              ", two-mass restitution " + str(restitution_for_damping_ratio(zeta)) +
                              ", m_red " + str(m_red) + " kg)";
    contact_extra.push_back({{"kind", geo.back()->kind()}, {"kn", law.kn}, {"cn", law.cn},
                             {"damping_ratio", zeta},
                             {"restitution", restitution_for_damping_ratio(zeta)},
                             {"reduced_mass", m_red}, {"friction_velocity", law.v_reg},
                             {"contact_period", M_PI * std::sqrt(m_red / law.kn)}});
    laws.push_back(law);
  }

  IdaSettings settings;
  settings.rtol = opt.rtol;
  settings.atol = opt.atol;
  settings.max_step = opt.max_step;
  const bool dense = opt.linear_solver == "dense" ||
                     (opt.linear_solver == "auto" && 2 * n <= opt.dense_max);
  settings.linear_solver = dense ? IdaLinearSolver::kDense : IdaLinearSolver::kKlu;
  if (opt.linear_solver == "auto")
    res.assumed["ida.linear_solver"] = std::string(dense ? "dense" : "klu") + " (auto: dense up to " +
                                       std::to_string(opt.dense_max) + " unknowns)";

  PenaltyIda ida(model.M(), model.K(), C, kin, laws, settings);
  const Eigen::VectorXd V0 = model.initial_velocity();
  ida.start(0.0, U0, V0);

  const int nb = model.num_bodies(), nc = static_cast<int>(scene.contacts.size());
  auto momentum = [&](const Eigen::Ref<const Eigen::VectorXd>& V) {
    Vec2 p{0.0, 0.0};
    for (int b = 0; b < nb; ++b)
      for (int c = 0; c < 2; ++c) p[c] += model.momentum_covector(b, c).dot(V);
    return p;
  };
  const Vec2 p0 = momentum(V0);
  auto drift = [&]() {
    const Vec2 p = momentum(ida.V());
    res.momentum_drift_max = std::max(res.momentum_drift_max, std::hypot(p[0] - p0[0], p[1] - p0[1]));
  };
  auto state_of = [&](int i, const ContactReading& r) {
    if (!r.closed) return ContactState::kOpen;
    if (laws[i].mu > 0.0 && std::abs(r.slip_rate) > laws[i].v_reg) return ContactState::kSlip;
    return ContactState::kStick;
  };
  auto energy = [&](HistoryRow& row) {
    const auto U = ida.U();
    const auto V = ida.V();
    row.kinetic = 0.5 * V.dot(model.M() * V);
    row.strain = 0.5 * U.dot(model.K() * U);  // + the penalty springs (below)
    for (int i = 0; i < nc; ++i) row.strain += ida.contact(i).penalty_energy;
  };
  auto make_row = [&]() {
    HistoryRow row;
    row.t = ida.t();
    const auto U = ida.U();
    const auto V = ida.V();
    for (int i = 0; i < nc; ++i) {
      const ContactReading r = ida.contact(i);
      ContactSample s;
      s.R = r.R;
      s.tau = r.tau;
      s.gap = r.gap;
      const int a = geo[i]->striker_node();
      s.ua = model.node_vector(U, a);
      s.va = model.node_vector(V, a);
      const auto nodes = geo[i]->segment_nodes(r.frame);
      s.ub = lerp(model.node_vector(U, nodes[0]), model.node_vector(U, nodes[1]), r.frame.xi2);
      s.vb = lerp(model.node_vector(V, nodes[0]), model.node_vector(V, nodes[1]), r.frame.xi2);
      s.state = state_of(i, r);
      row.contacts.push_back(s);
    }
    energy(row);
    row.dissipated = ida.dissipated();
    row.momentum = momentum(V);
    return row;
  };

  std::vector<ContactStats> stats;
  std::ostringstream rule;
  rule << "contact phases (located by IDA root finding) separated by less than " << opt.merge_gap
       << " s are merged";
  for (int i = 0; i < nc; ++i) stats.emplace_back(opt.merge_gap, rule.str());
  Progress progress("ida", scene.time.end);  // stderr, only on long runs
  auto on_step = [&](double t_prev) {
    progress.update(ida.t());
    for (int i = 0; i < nc; ++i) {
      const ContactReading r = ida.contact(i);
      stats[i].add(ida.t(), r.R, r.tau, ida.t() - t_prev, state_of(i, r));
    }
    drift();
  };

  res.history.push_back(make_row());
  res.energy_initial = res.history.back().kinetic + res.history.back().strain;
  // Rows on the paper's grid: p dt for every output_every-th p and the last step N =
  // ceil(end/dt), so that histories of the two methods line up row by row.
  const double h = opt.output_step.value_or(dt);
  const long every = opt.output_step ? 1 : scene.time.output_every;
  const long N = static_cast<long>(std::ceil(scene.time.end / h - 1e-9));
  res.assumed["ida.output_step"] = str(h * static_cast<double>(every)) + " s" +
                                   (opt.output_step ? "" : " (the scene's dt x output_every)");
  for (long p = 1; p <= N; ++p) {
    if (p % every != 0 && p != N) continue;
    ida.advance_to(static_cast<double>(p) * h, on_step);
    res.history.push_back(make_row());
  }

  // Summaries: intervals from the located events (exact switch times), impulses from the
  // quadratures; peaks and stick/slip counts from the internal steps via ContactStats.
  for (int i = 0; i < nc; ++i) {
    ContactSummary s;
    s.striker = scene.bodies[scene.contacts[i].striker].name;
    s.target = scene.bodies[scene.contacts[i].target].name;
    s.kind = geo[i]->kind();
    stats[i].fill(s);
    const double rect_n = s.impulse_normal;
    s.intervals.clear();
    nlohmann::json ev = nlohmann::json::array();
    double open_at = -1.0;
    for (const ContactEvent& e : ida.events()) {
      if (e.contact != i) continue;
      ev.push_back({e.t, e.onset ? "onset" : "release"});
      if (e.onset) {
        if (!s.intervals.empty() && e.t - s.intervals.back()[1] < opt.merge_gap) {
          open_at = s.intervals.back()[0];
          s.intervals.pop_back();
        } else {
          open_at = e.t;
        }
      } else if (open_at >= 0.0) {
        s.intervals.push_back({open_at, e.t});
        open_at = -1.0;
      }
    }
    if (open_at >= 0.0) s.intervals.push_back({open_at, ida.t()});  // still closed at the end
    s.impulse_normal = ida.impulse_normal(i);
    s.impulse_tangential = ida.impulse_tangential(i);
    s.extra = contact_extra[i];
    s.extra["events"] = ev;
    s.extra["impulse_normal_step_sum"] = rect_n;
    res.contacts.push_back(s);
  }

  const auto V = ida.V();
  for (int b = 0; b < nb; ++b) {
    const double m = model.body_mass(b);
    res.final_velocity[scene.bodies[b].name] = {model.momentum_covector(b, 0).dot(V) / m,
                                                model.momentum_covector(b, 1).dot(V) / m};
  }
  res.energy_final = res.history.back().kinetic + res.history.back().strain;
  const IdaCounters c = ida.counters();
  res.steps = c.steps;
  res.extra["ida"] = {{"rtol", opt.rtol}, {"atol", opt.atol},
                      {"linear_solver", dense ? "dense" : "klu"}, {"unknowns", 2 * n},
                      {"steps", c.steps}, {"residual_evals", c.residual_evals},
                      {"jacobian_evals", c.jacobian_evals}, {"nonlinear_iters", c.nonlinear_iters},
                      {"error_test_fails", c.error_test_fails},
                      {"nonlinear_conv_fails", c.nonlinear_conv_fails},
                      {"root_evals", c.root_evals}, {"events", c.events},
                      {"klu_pattern_changes", c.klu_pattern_changes}, {"warnings", c.warnings},
                      {"output_step", h * static_cast<double>(every)}, {"dissipated", ida.dissipated()},
                      {"contacts", contact_extra}};
  res.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace beamimpact
