#include <verification/matrix/evaluate.hpp>

#include <cmath>

#include <fmt/format.h>

#include <verification/compare/compare_runs.hpp>
#include <verification/compare/run_checks.hpp>

namespace beamimpact::verification {

const char* to_string(GateStatus s) {
  switch (s) {
    case GateStatus::kPass: return "pass";
    case GateStatus::kFail: return "fail";
    default: return "skipped";
  }
}
namespace {

/// Gates of an item that could not be evaluated: skipped (not required) or failed.
void not_evaluated(ItemResult& r, const std::vector<Gate>& gates, const std::string& why, bool skipped) {
  const bool fail = !skipped || r.required;
  for (const auto& g : gates) {
    r.gates.push_back(
        {g, std::nullopt, fail ? GateStatus::kFail : GateStatus::kSkipped,
         skipped ? (r.required ? "skipped, and the case is required: " + why : "skipped: " + why) : why});
  }
}

/// The runs needed, in order; returns false (and fills the gates) when one is not ok.
bool runs_ok(ItemResult& r, const std::vector<const jobs::JobSpec*>& specs, const std::vector<Gate>& gates,
             const std::map<std::string, jobs::JobOutcome>& runs) {
  for (const jobs::JobSpec* s : specs) {
    const auto it = runs.find(s->key());
    if (it == runs.end()) {
      not_evaluated(r, gates, "run " + s->label() + " was not run", false);
      return false;
    }
    if (it->second.status != jobs::JobOutcome::Status::kOk) {
      const auto st = it->second.status;
      const bool skipped =
          st == jobs::JobOutcome::Status::kSkipped || st == jobs::JobOutcome::Status::kNotApplicable;
      const char* how = st == jobs::JobOutcome::Status::kNotApplicable ? " not applicable: "
                        : skipped                                      ? ": "
                                                                       : " failed: ";
      not_evaluated(r, gates, s->label() + how + it->second.message, skipped);
      return false;
    }
  }
  return true;
}

}  // namespace

std::optional<std::pair<double, double>> richardson_limit(double q1, double q2, double q3, double r) {
  const double d12 = q1 - q2, d23 = q2 - q3;
  if (d12 == 0.0 || !(d23 / d12 > 0.0 && d23 / d12 < 1.0)) return std::nullopt;
  const double p = std::log(d12 / d23) / std::log(r);
  return std::pair{q3 - d23 / (std::pow(r, p) - 1.0), p};
}

std::string GateResult::limit() const {
  std::string s;
  if (gate.richardson) s = fmt::format("|Q_R - ref| <= {:g} E_R", *gate.richardson);
  if (gate.min_order) s += fmt::format("{}order >= {:g}", s.empty() ? "" : ", ", *gate.min_order);
  if (gate.tol) s += fmt::format("{}<= {:g}", s.empty() ? "" : ", error ", *gate.tol);
  return s;
}

std::optional<double> GateResult::margin() const {
  if (!value || (gate.tol.has_value() + gate.min_order.has_value() + gate.richardson.has_value()) != 1)
    return std::nullopt;
  if (gate.tol) return *gate.tol > 0.0 ? std::optional(*value / *gate.tol) : std::nullopt;
  if (gate.min_order) return *value > 0.0 ? std::optional(*gate.min_order / *value) : std::nullopt;
  return *gate.richardson > 0.0 ? std::optional(*value / *gate.richardson) : std::nullopt;
}

GateCounts count_gates(const std::vector<ItemResult>& items) {
  GateCounts t;
  for (const auto& i : items)
    for (const auto& g : i.gates) {
      ++t.gates;
      if (g.status == GateStatus::kPass)
        ++t.pass;
      else if (g.status == GateStatus::kFail)
        ++t.fail;
      else
        ++t.skipped;
    }
  return t;
}

bool verification_passed(const std::vector<ItemResult>& items, bool complete) {
  return complete && count_gates(items).fail == 0;
}

bool ItemResult::passed() const {
  for (const auto& g : gates)
    if (g.status == GateStatus::kFail) return false;
  return true;
}

GateResult check_gate(const Gate& gate, const Comparison& cmp) {
  GateResult r{gate, std::nullopt, GateStatus::kFail, {}};
  const Norm* n = cmp.find(gate.metric);
  if (!n) {
    r.message = "norm '" + gate.metric + "' not produced (contact missing in one of the runs?)";
    return r;
  }
  if (!n->value) {
    r.message = "norm unavailable: " + n->unavailable;
    return r;
  }
  r.value = n->value;
  if (*n->value <= *gate.tol) {
    r.status = GateStatus::kPass;
  } else {
    r.message = fmt::format("{} = {:.4g} exceeds {:g}", gate.metric, *n->value, *gate.tol);
  }
  return r;
}

std::optional<double> observed_order(std::optional<double> e_coarse, std::optional<double> e_fine, double r) {
  if (!e_coarse || !e_fine || !(*e_coarse > 0.0) || !(*e_fine > 0.0) || !(r > 1.0)) return std::nullopt;
  return std::log(*e_coarse / *e_fine) / std::log(r);
}

namespace {

/// An item about one run under test: its identity and the run's times.
ItemResult item_for(const char* kind, const jobs::JobSpec& run, const std::string& name,
                    const std::string& tier, bool required, const std::string& note,
                    const std::map<std::string, jobs::JobOutcome>& runs) {
  ItemResult r;
  r.kind = kind;
  r.scene = run.scene_name();
  r.name = name;
  r.settings = run.settings_label();
  r.tier = tier;
  r.required = required;
  r.note = note;
  if (auto it = runs.find(run.key()); it != runs.end()) {
    r.wall_seconds = it->second.process_seconds;
    r.solver_seconds = it->second.solver_seconds;
  }
  return r;
}

/// Applies the gates to the comparison that `compute` makes; a failure to compute fails them all.
template <class F>
void apply_gates(ItemResult& r, const std::vector<Gate>& gates, F compute, const std::string& what) {
  try {
    const Comparison cmp = compute();
    for (const auto& g : gates) r.gates.push_back(check_gate(g, cmp));
    r.comparisons.push_back(cmp);
  } catch (const std::exception& e) {
    not_evaluated(r, gates, what + " failed: " + e.what(), false);
  }
}

}  // namespace

ItemResult evaluate_case(const Case& c, const std::map<std::string, jobs::JobOutcome>& runs) {
  ItemResult r = item_for("case", c.run, c.name(), c.tier, c.required, c.note, runs);
  r.reference = c.reference.scene == c.run.scene ? c.reference.settings_label() : c.reference.label();
  // Name every case by its step, also when the scene chose it (dt = "auto" or the scene's dt).
  if (auto it = runs.find(c.run.key()); it != runs.end() && !c.run.dt && it->second.dt > 0.0) {
    r.settings += fmt::format(" dt={:.6g}", it->second.dt);
    r.name = r.scene + " " + r.settings + " vs " + r.reference;
  }
  if (!runs_ok(r, {&c.run, &c.reference}, c.gates, runs)) return r;
  apply_gates(
      r, c.gates,
      [&] {
        return compare_runs(jobs::stored_run(runs.at(c.run.key()))->view(),
                            jobs::stored_run(runs.at(c.reference.key()))->view());
      },
      "comparison");
  return r;
}

ItemResult evaluate_check(const RunCheck& c, const std::map<std::string, jobs::JobOutcome>& runs) {
  ItemResult r = item_for("check", c.run, c.name(), c.tier, c.required, c.note, runs);
  if (!runs_ok(r, {&c.run}, c.gates, runs)) return r;  // a crash, a NaN or a refusal fails every gate
  apply_gates(
      r, c.gates, [&] { return check_run(jobs::stored_run(runs.at(c.run.key()))->view()); }, "health check");
  return r;
}

namespace {

/// A ladder's item: its identity and the wall times of its rungs.
ItemResult ladder_item(const Convergence& v, const std::map<std::string, jobs::JobOutcome>& runs) {
  ItemResult r;
  r.kind = "convergence";
  r.scene = v.runs.front().scene_name();
  r.name = v.name();
  r.settings = v.runs.front().settings_label();
  r.tier = v.tier;
  r.required = v.required;
  r.note = v.note;
  if (v.reference) r.reference = v.reference->settings_label();
  for (const auto& s : v.runs)
    if (auto it = runs.find(s.key()); it != runs.end()) {
      r.wall_seconds += it->second.process_seconds;
      r.solver_seconds += it->second.solver_seconds;
    }
  return r;
}

/// The ladder's comparisons: every rung against the reference, or consecutive pairs.
void compare_rungs(const Convergence& v, const std::map<std::string, jobs::JobOutcome>& runs, ItemResult& r) {
  std::vector<std::shared_ptr<const StoredRun>> rungs;  // each rung once, also when read here
  for (const auto& s : v.runs) rungs.push_back(jobs::stored_run(runs.at(s.key())));
  if (v.reference) {  // every rung against the reference
    const auto ref = jobs::stored_run(runs.at(v.reference->key()));
    for (const auto& rung : rungs) r.comparisons.push_back(compare_runs(rung->view(), ref->view()));
  } else {  // consecutive pairs
    for (std::size_t i = 0; i + 1 < rungs.size(); ++i)
      r.comparisons.push_back(compare_runs(rungs[i]->view(), rungs[i + 1]->view()));
  }
}

/// Orders of every norm (the table in the report) and, with a reference, the Richardson limits.
void add_orders(const Convergence& v, ItemResult& r) {
  for (const auto& n : r.comparisons.front().norms) {
    auto& [errors, orders] = r.orders[n.name];
    for (const auto& cmp : r.comparisons) {
      const Norm* m = cmp.find(n.name);
      errors.push_back(m ? m->value : std::nullopt);
    }
    for (std::size_t i = 0; i + 1 < errors.size(); ++i)
      orders.push_back(observed_order(errors[i], errors[i + 1], v.steps[i] / v.steps[i + 1]));
    // Richardson from the last three rungs' own values (scalar norms carry them as a, b).
    const std::size_t k = r.comparisons.size();
    if (!v.reference || k < 3) continue;
    const Norm *n1 = r.comparisons[k - 3].find(n.name), *n2 = r.comparisons[k - 2].find(n.name),
               *n3 = r.comparisons[k - 1].find(n.name);
    if (!n1 || !n2 || !n3 || !n1->a || !n2->a || !n3->a || !n3->b || *n3->b == 0.0) continue;
    const double ratio = v.steps[k - 2] / v.steps[k - 1];
    if (const auto lim = richardson_limit(*n1->a, *n2->a, *n3->a, ratio))
      r.richardson[n.name] = {lim->second, lim->first, *n3->b,
                              std::abs(lim->first - *n3->b) / std::abs(*n3->b),
                              std::abs(lim->first - *n3->a) / std::abs(*n3->b)};
  }
}

/// The Richardson part of a ladder gate: fails gr unless the limit is within the gate's factor of
/// its error estimate from the reference; the value is that distance in estimates.
void richardson_gate(const Gate& g, const ItemResult& r, GateResult& gr) {
  const auto rich = r.richardson.find(g.metric);
  if (rich == r.richardson.end()) {
    gr.status = GateStatus::kFail;
    gr.message = "no Richardson limit: the last three rungs' differences do not shrink monotonically";
  } else if (rich->second.error > *g.richardson * rich->second.estimate) {
    gr.status = GateStatus::kFail;
    gr.message = fmt::format(
        "Richardson limit {:.6g} (order {:.3g}) is {:.3g} from the reference {:.6g}, beyond {:g} x its "
        "error estimate {:.3g}",
        rich->second.limit, rich->second.order, rich->second.error, rich->second.reference, *g.richardson,
        rich->second.estimate);
  }
  // The value: the distance to the reference in units of the error estimate.
  if (rich != r.richardson.end() && rich->second.estimate > 0.0)
    gr.value = rich->second.error / rich->second.estimate;
}

/// One gate of a ladder on its finest pair: Richardson, then order, then tolerance.
GateResult ladder_gate(const Gate& g, const ItemResult& r) {
  GateResult gr{g, std::nullopt, GateStatus::kPass, {}};
  const auto it = r.orders.find(g.metric);
  if (it == r.orders.end()) {
    gr.status = GateStatus::kFail;
    gr.message = "norm '" + g.metric + "' not produced";
    return gr;
  }
  const auto& [errors, orders] = it->second;
  const auto finest = errors.back();
  if (g.richardson) richardson_gate(g, r, gr);
  if (g.min_order && gr.status == GateStatus::kPass) {
    gr.value = orders.empty() ? std::nullopt : orders.back();
    if (!gr.value) {
      const bool zero = finest && *finest == 0.0;
      gr.status = zero ? GateStatus::kPass : GateStatus::kFail;
      gr.message = zero ? "errors are zero (converged to round-off): no order to observe"
                        : "order not observable (an error is zero or unavailable)";
    } else if (*gr.value < *g.min_order) {
      gr.status = GateStatus::kFail;
      gr.message = fmt::format("observed order {:.3g} below {:g}", *gr.value, *g.min_order);
    }
  }
  if (g.tol && gr.status == GateStatus::kPass) {
    if (!finest || *finest > *g.tol) {
      gr.status = GateStatus::kFail;
      gr.message = finest ? fmt::format("finest-pair error {:.4g} exceeds {:g}", *finest, *g.tol)
                          : "finest-pair error unavailable";
    }
    if (!g.min_order && !g.richardson) gr.value = finest;
  }
  return gr;
}

}  // namespace

ItemResult evaluate_ladder(const Convergence& v, const std::map<std::string, jobs::JobOutcome>& runs) {
  ItemResult r = ladder_item(v, runs);
  std::vector<const jobs::JobSpec*> specs;
  if (v.reference) specs.push_back(&*v.reference);
  for (const auto& s : v.runs) specs.push_back(&s);
  if (!runs_ok(r, specs, v.gates, runs)) return r;
  try {
    compare_rungs(v, runs, r);
  } catch (const std::exception& e) {
    not_evaluated(r, v.gates, std::string("comparison failed: ") + e.what(), false);
    return r;
  }
  add_orders(v, r);  // the orders of every norm, then the gates on the finest pair
  for (const auto& g : v.gates) r.gates.push_back(ladder_gate(g, r));
  return r;
}

nlohmann::json to_json(const ItemResult& r) {
  nlohmann::json j{{"kind", r.kind},
                   {"scene", r.scene},
                   {"name", r.name},
                   {"settings", r.settings},
                   {"reference", r.reference},
                   {"tier", r.tier},
                   {"required", r.required},
                   {"wall_seconds", r.wall_seconds},
                   {"solver_seconds", r.solver_seconds},
                   {"passed", r.passed()},
                   {"note", r.note}};
  auto& gates = j["gates"] = nlohmann::json::array();
  for (const auto& g : r.gates) {
    nlohmann::json e{{"metric", g.gate.metric},       {"limit", g.limit()},   {"why", g.gate.why},
                     {"status", to_string(g.status)}, {"passed", g.passed()}, {"message", g.message}};
    e["value"] = g.value ? nlohmann::json(*g.value) : nlohmann::json(nullptr);
    const auto margin = g.margin();
    e["margin"] = margin ? nlohmann::json(*margin) : nlohmann::json(nullptr);
    if (g.gate.tol) e["tol"] = *g.gate.tol;
    if (g.gate.min_order) e["min_order"] = *g.gate.min_order;
    if (g.gate.richardson) e["richardson"] = *g.gate.richardson;
    gates.push_back(e);
  }
  auto& cmps = j["comparisons"] = nlohmann::json::array();
  for (const auto& c : r.comparisons) cmps.push_back(c.to_json());
  if (!r.orders.empty()) {
    auto& o = j["orders"];
    for (const auto& [name, eo] : r.orders) {
      auto opt = [](const std::vector<std::optional<double>>& v) {
        nlohmann::json a = nlohmann::json::array();
        for (const auto& x : v) a.push_back(x ? nlohmann::json(*x) : nlohmann::json(nullptr));
        return a;
      };
      o[name] = {{"errors", opt(eo.first)}, {"orders", opt(eo.second)}};
    }
  }
  for (const auto& [name, x] : r.richardson)
    j["richardson"][name] = {{"order", x.order},
                             {"limit", x.limit},
                             {"reference", x.reference},
                             {"error", x.error},
                             {"estimate", x.estimate}};
  return j;
}

}  // namespace beamimpact::verification
