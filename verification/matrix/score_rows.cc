// score_rows (scorecard.hpp): each finished run, or ladder, compared with its reference and judged
// under its card.
#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <verification/compare/compare_runs.hpp>
#include <verification/matrix/scorecard.hpp>

namespace beamimpact::verification {
namespace {

using Status = jobs::JobOutcome::Status;

/// The outcome of `spec`, or a failed one when it was not run.
jobs::JobOutcome outcome_of(const std::map<std::string, jobs::JobOutcome>& runs, const jobs::JobSpec& spec,
                            const char* why) {
  const auto it = runs.find(spec.key());
  if (it != runs.end()) return it->second;
  return jobs::JobOutcome{spec, {}, Status::kSkipped, why, 0.0, 0.0, 0, 0.0, nullptr};
}

/// Quantities whose norm's `a` is the run's own value of a smooth scalar (its limit extrapolates):
/// impulse, peak force, final energy (per contact with a suffix "_2", ...). Contact times are not:
/// a scheme closing at a step boundary moves them by whole steps, not smoothly in h; they are
/// judged on the finest rung.
bool extrapolable(const std::string& metric) {
  for (const char* m : {"impulse", "peak_R", "energy_final"})
    if (metric == m || (metric.rfind(std::string(m) + "_", 0) == 0 &&
                        std::all_of(metric.begin() + std::string(m).size() + 1, metric.end(), ::isdigit)))
      return true;
  return false;
}

/// The magnitude an error was computed from, for tolerance_slack: the compared values for an
/// absolute error (a time in s), 1 for a relative one.
double error_scale(const Norm& n) {
  if (n.a && n.b && n.unit != "1") return std::max(std::abs(*n.a), std::abs(*n.b));
  return n.unit == "1" ? 1.0 : 0.0;
}

/// The error's unit per unit of |a - b| (1 / |b| relative, 1 absolute, 1 / E0 for energy_final).
double per_difference(const Norm& n) {
  if (n.value && n.a && n.b && *n.a != *n.b) return *n.value / std::abs(*n.a - *n.b);
  return n.unit == "1" && n.b && *n.b != 0.0 ? 1.0 / std::abs(*n.b) : 1.0;
}

/// A quantity judged on a single comparison (one run, or a ladder's finest rung).
ScoreQuantity single(const Gate& g, const Comparison& cmp, const std::optional<Comparison>& spread,
                     const std::string& spread_note, const char* judged) {
  ScoreQuantity q{g.metric, std::nullopt, g.tol,        std::nullopt, QuantityStatus::kFail,
                  "",       judged,       std::nullopt, std::nullopt, std::nullopt};
  const Norm* s = spread ? spread->find(g.metric) : nullptr;
  q.uncertainty = s ? s->value : spread ? std::nullopt : std::optional<double>(0.0);
  const std::string tail = spread_note.empty() ? "" : "; " + spread_note;
  const GateResult r = check_gate(g, cmp);
  const Norm* n = cmp.find(g.metric);
  if (!r.value || !n) {
    q.note = r.message + tail;
    return q;
  }
  q.error = r.value;
  q.exact = n->b;
  // A reference whose check did not finish has an unknown spread: no verdict it could reverse.
  q.status = verdict(*r.value, *g.tol, q.uncertainty.value_or(INFINITY), error_scale(*n));
  const std::string spread_text =
      spread && q.uncertainty ? fmt::format("the reference's spread {:.3g}", *q.uncertainty) : "";
  if (q.status == QuantityStatus::kPass)
    q.note = g.why + tail;
  else if (q.status == QuantityStatus::kFail)
    q.note = fmt::format("{} = {:.4g} exceeds {:g}", g.metric, *r.value, *g.tol) +
             (spread_text.empty() ? "" : " by more than " + spread_text) + tail;
  else
    q.note = fmt::format("{} = {:.4g} against {:g}: {} could reverse the verdict", g.metric, *r.value, *g.tol,
                         spread_text.empty() ? "an unknown spread" : spread_text) +
             tail;
  return q;
}

/// A quantity judged against its settled value v +- U (the card's; docs/s4.md): the run's own value
/// a (the comparison's run side, read from its history) against v, |a - v| / |v| for a relative norm
/// and |a - v| for one in s, the uncertainty U / |v| or U in place of the reference's spread.
ScoreQuantity against_settled(const Gate& g, const Comparison& cmp, const SettledValue& v,
                              const char* judged) {
  ScoreQuantity q{g.metric, std::nullopt, g.tol,        std::nullopt, QuantityStatus::kFail,
                  "",       judged,       std::nullopt, v.value,      std::nullopt};
  const Norm* n = cmp.find(g.metric);
  if (!n || !n->a || n->difference) {
    q.note =
        fmt::format("{}: the run has no value of its own to hold to the settled {:.6g}", g.metric, v.value);
    return q;
  }
  const double per = n->unit == "1" ? 1.0 / std::abs(v.value) : 1.0;  // the error's unit per unit of a - v
  q.error = std::abs(*n->a - v.value) * per;
  q.uncertainty = v.uncertainty * per;
  q.status = verdict(*q.error, *g.tol, q.uncertainty, n->unit == "1" ? 1.0 : std::abs(v.value));
  const std::string against = fmt::format("{} = {:.6g} against the settled {:.6g} +- {:.3g} ({})", g.metric,
                                          *n->a, v.value, v.uncertainty, v.why);
  if (q.status == QuantityStatus::kPass)
    q.note = g.why + "; " + against;
  else if (q.status == QuantityStatus::kFail)
    q.note = fmt::format("error {:.4g} exceeds {:g} by more than the settled uncertainty {:.3g}: {}",
                         *q.error, *g.tol, *q.uncertainty, against);
  else
    q.note =
        fmt::format("error {:.4g} against {:g}: the settled uncertainty {:.3g} could reverse the verdict: {}",
                    *q.error, *g.tol, *q.uncertainty, against);
  return q;
}

/// A scalar judged by its ladder: the limit against the exact value, within 1.25 U + tol / 10.
ScoreQuantity on_ladder(const Gate& g, const std::vector<Comparison>& cmps) {
  std::vector<double> values;
  for (const Comparison& c : cmps) {
    const Norm* n = c.find(g.metric);
    if (!n || !n->a || !n->b || !n->value) return single(g, cmps.back(), std::nullopt, "", "finest rung");
    values.push_back(*n->a);
  }
  const Norm& fine = *cmps.back().find(g.metric);
  const double k = per_difference(fine);  // the error's unit per unit of the quantity
  // Rungs within tol / 10 of each other agree: refinement no longer changes what is judged.
  ScoreQuantity q{g.metric,
                  std::nullopt,
                  g.tol,
                  std::nullopt,
                  QuantityStatus::kNotConverged,
                  "",
                  "limit",
                  ladder_limit(values, 0.1 * *g.tol / k),
                  fine.b,
                  std::nullopt};
  const LadderResult& L = *q.ladder;
  if (!L.limit) {
    q.note = fmt::format("not converged: {} (rung values {:.6g})", L.why_not, fmt::join(values, ", "));
    return q;
  }
  q.error = std::abs(*L.limit - *fine.b) * k;
  q.uncertainty = *L.uncertainty * k;
  q.allowed = kRichardsonFactor * *q.uncertainty + 0.1 * *g.tol;
  const double slack = tolerance_slack(*q.allowed, *q.error, error_scale(fine));
  q.status = *q.error <= *q.allowed + slack ? QuantityStatus::kPass : QuantityStatus::kFail;
  const std::string order = L.order ? fmt::format("order {:.3g}", *L.order) : "rungs agree";
  if (q.status == QuantityStatus::kPass)
    q.note = fmt::format("limit {:.6g} ({}) within {:.3g} of exact {:.6g}; tolerance: {}", *L.limit, order,
                         *q.allowed, *fine.b, g.why);
  else
    q.note = fmt::format(
        "limit {:.6g} ({}, uncertainty {:.3g}) is {:.3g} from exact {:.6g}, beyond 1.25 x its uncertainty + "
        "tol / 10 = {:.3g}: the method converges to another answer (a bias, or a model of its own such as a "
        "penalty contact's), not to the exact one",
        *L.limit, order, *q.uncertainty, *q.error, *fine.b, *q.allowed);
  return q;
}

/// The reference compared with its check (its spread), or none: no check, or the check did not
/// finish or compare (said in `note`).
std::optional<Comparison> reference_spread(const ScoreItem& it, const jobs::JobOutcome& ref,
                                           const std::map<std::string, jobs::JobOutcome>& runs,
                                           std::string& note) {
  if (!it.reference_check) return std::nullopt;
  const jobs::JobOutcome check = outcome_of(runs, *it.reference_check, "not run");
  const std::string label = "reference check " + it.reference_check->settings_label();
  if (check.status != Status::kOk) {
    note = label + " " + to_string(check.status) + " (spread unknown): " + check.message;
    return Comparison{};
  }
  try {
    return compare_runs(jobs::stored_run(ref)->view(), jobs::stored_run(check)->view());
  } catch (const std::exception& e) {
    note = label + " did not compare (spread unknown): " + e.what();
    return Comparison{};
  }
}

/// The status of a quantity whose scored run did not finish: failed, skipped (the method or its
/// program is not here) or not applicable (the method refused the scene).
QuantityStatus not_finished(Status run) {
  switch (run) {
    case Status::kSkipped: return QuantityStatus::kSkipped;
    case Status::kNotApplicable: return QuantityStatus::kNotApplicable;
    default: return QuantityStatus::kFailed;
  }
}

/// Every quantity of a row not judged: the status and its reason.
void not_judged(ScoreRow& row, QuantityStatus status, const std::string& why) {
  for (const Gate& g : row.item->gates)
    row.quantities.push_back(ScoreQuantity{g.metric, std::nullopt, g.tol, std::nullopt, status, why, "",
                                           std::nullopt, std::nullopt, std::nullopt});
}

/// The row's quantities once every run it needs finished.
void judge(ScoreRow& row, const jobs::JobOutcome& ref, const std::map<std::string, jobs::JobOutcome>& runs) {
  const ScoreItem& it = *row.item;
  std::vector<Comparison> cmps;  // every rung (or the one run) against the reference: run first
  // The scored run's impulse, intervals and interval impulses come from its own history.csv, never
  // from what its summary.json claims (a summary that disagrees with its rows cannot pass:
  // `beamimpact run` refuses such an outside run with exit 3, api/output_rules.hpp).
  CompareOptions options;
  options.run_from_history = true;
  try {
    const auto reference = jobs::stored_run(ref);
    for (const jobs::JobOutcome& o : row.rungs)
      cmps.push_back(compare_runs(jobs::stored_run(o)->view(), reference->view(), options));
  } catch (const std::exception& e) {
    not_judged(row, QuantityStatus::kFailed, e.what());
    return;
  }
  std::string spread_note;
  const std::optional<Comparison> spread = reference_spread(it, ref, runs, spread_note);
  for (const Gate& g : it.gates) {
    const auto settled = std::find_if(it.settled.begin(), it.settled.end(),
                                      [&](const SettledValue& v) { return v.metric == g.metric; });
    if (settled != it.settled.end())
      row.quantities.push_back(
          against_settled(g, cmps.back(), *settled, cmps.size() >= 3 ? "finest rung" : "single run"));
    else if (cmps.size() >= 3 && extrapolable(g.metric))
      row.quantities.push_back(on_ladder(g, cmps));
    else
      row.quantities.push_back(
          single(g, cmps.back(), spread, spread_note, cmps.size() >= 3 ? "finest rung" : "single run"));
  }
}

}  // namespace

std::vector<ScoreRow> score_rows(const std::vector<ScoreItem>& items,
                                 const std::map<std::string, jobs::JobOutcome>& runs) {
  std::vector<ScoreRow> rows;
  for (const ScoreItem& it : items) {
    ScoreRow row{&it, outcome_of(runs, it.run, "not run"), {}, {}};
    if (it.ladder.rungs.empty()) row.rungs.push_back(row.outcome);
    for (const jobs::JobSpec& s : it.ladder.rungs) row.rungs.push_back(outcome_of(runs, s, "not run"));
    const auto bad = std::find_if(row.rungs.begin(), row.rungs.end(),
                                  [](const jobs::JobOutcome& o) { return o.status != Status::kOk; });
    if (row.outcome.status != Status::kOk) {
      not_judged(row, not_finished(row.outcome.status), row.outcome.message);
    } else if (bad != row.rungs.end()) {
      not_judged(
          row, QuantityStatus::kFailed,
          "ladder rung " + bad->spec.settings_label() + " " + to_string(bad->status) + ": " + bad->message);
    } else if (const jobs::JobOutcome ref = outcome_of(runs, it.reference, "not run");
               ref.status != Status::kOk) {
      not_judged(
          row, QuantityStatus::kSkipped,
          "reference " + it.reference.settings_label() + " " + to_string(ref.status) + ": " + ref.message);
    } else {
      judge(row, ref, runs);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace beamimpact::verification
