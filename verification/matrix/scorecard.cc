#include <verification/matrix/scorecard.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <solver/util/InputError.hpp>
#include <solver/util/write_file_atomic.hpp>
#include <verification/compare/compare_runs.hpp>
#include <verification/matrix/reports.hpp>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;

/// The quantities reported for a scene the matrix gives no tolerance for.
const std::vector<std::string>& default_metrics() {
  static const std::vector<std::string> m = {"impulse", "contact_start", "contact_end", "final_velocity"};
  return m;
}

fs::path normal(const fs::path& p) { return fs::absolute(p).lexically_normal(); }

/// Rank of a case as the source of a scene's reference and tolerances (lower is better).
int rank(const Case& c, const std::string& method) {
  const int ref = c.reference.method == "exact" ? 0 : c.reference.method == "ida" ? 3 : 100;
  const int run = c.run.method == method ? 0 : c.run.method == "paper" ? 1 : 2;
  return ref + run;
}

std::string text(const std::optional<double>& v) { return v ? fmt::format("{:.3g}", *v) : "-"; }

/// Whether `ref` sets `key` (as "key=value").
bool sets_key(const JobSpec& ref, const std::string& key) {
  return std::any_of(ref.set.begin(), ref.set.end(),
                     [&](const std::string& s) { return s.rfind(key + "=", 0) == 0; });
}

/// IDA converged beyond its defaults, keeping the reference's own settings: time tolerances 100
/// times tighter (rtol 1e-10, atol 1e-13), the friction regularisation at 1e-5 m/s (the matrix's
/// converged value; no effect on a frictionless contact) and, with `stiffen`, a penalty 10 times
/// stiffer (1e4 EA/le), so that IDA's step and penetration errors fall below the defaults' by
/// about those factors. Every method's scorecard takes it wherever its reference would be IDA:
/// IDA is never compared with its own run, and every method meets the same reference on a scene.
/// Without `stiffen` it is the reference's check: the same run at the case's penalty.
JobSpec converged_ida(JobSpec ref, bool stiffen) {
  const bool own_penalty = sets_key(ref, "ida.kn") || sets_key(ref, "ida.kn_factor");
  for (const auto& [key, value] : {std::pair{"ida.rtol", "1e-10"}, std::pair{"ida.atol", "1e-13"},
                                   std::pair{"ida.friction_velocity", "1e-5"}})
    if (!sets_key(ref, key)) ref.set.push_back(std::string(key) + "=" + value);
  if (stiffen && !own_penalty) ref.set.push_back("ida.kn_factor=1e4");
  return ref;
}

const std::vector<std::string> kSets = {"paper", "hard", "exact"};

/// The scenes of one set, sorted: a folder's scene files, or (exact) every scene outside the
/// paper and hard folders that a matrix case compares with the exact method, in matrix order.
std::vector<fs::path> set_scenes(const std::string& set, const VerificationMatrix& matrix,
                                 const fs::path& root) {
  std::vector<fs::path> in;
  if (set != "exact") {
    for (const auto& e : fs::directory_iterator(root / "verification/scenes" / set))
      if (e.path().extension() == ".toml") in.push_back(normal(e.path()));
    std::sort(in.begin(), in.end());
    return in;
  }
  const fs::path paper = normal(root / "verification/scenes/paper"),
                 hard = normal(root / "verification/scenes/hard");
  for (const Case& c : matrix.cases) {
    const fs::path scene = normal(c.run.scene), folder = scene.parent_path();
    if (c.reference.method == "exact" && folder != paper && folder != hard &&
        std::find(in.begin(), in.end(), scene) == in.end())
      in.push_back(scene);
  }
  return in;
}

/// The matrix case giving `scene`'s best reference for `method`, or nullptr.
const Case* best_case(const VerificationMatrix& matrix, const fs::path& scene, const std::string& method) {
  const Case* best = nullptr;
  for (const Case& c : matrix.cases)
    if (normal(c.run.scene) == scene && rank(c, method) < 100 &&
        (!best || rank(c, method) < rank(*best, method)))
      best = &c;
  return best;
}

}  // namespace

std::string ida_reference(const ScoreOptions& o) {
  return o.references == "converged"
             ? "IDA converged beyond its defaults: rtol 1e-10, atol 1e-13, friction regularised at 1e-5 "
               "m/s, penalty 1e4 EA/le, with the case's own settings; its spread against the same run at "
               "the case's penalty is its uncertainty"
             : "IDA at the matrix case's settings (not converged further: --references matrix)";
}

void ScoreOptions::validate(const std::string& method) const {
  if (sets.empty()) throw InputError("command line", "--sets", "expected one or more of paper, hard, exact");
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (std::find(kSets.begin(), kSets.end(), sets[i]) == kSets.end())
      throw InputError("command line", "--sets", "expected paper, hard or exact, got '" + sets[i] + "'");
    if (std::find(sets.begin(), sets.begin() + i, sets[i]) != sets.begin() + i)
      throw InputError("command line", "--sets", "'" + sets[i] + "' is named twice");
  }
  if (references != "converged" && references != "matrix")
    throw InputError("command line", "--references",
                     "expected converged or matrix, got '" + references + "'");
  if (references == "matrix" && method == "ida")
    throw InputError(
        "command line", "--references",
        "IDA's own scorecard needs converged references (with matrix ones IDA would score its own runs)");
}

std::vector<ScoreItem> score_items(const VerificationMatrix& matrix, const std::string& method,
                                   const fs::path& data_root, const ScoreOptions& options) {
  options.validate(method);
  const bool converge = options.references == "converged";
  const auto reference = [&](ScoreItem& it, const JobSpec& ref) {
    it.reference = ref.method == "ida" && converge ? converged_ida(ref, true) : ref;
    if (ref.method == "ida" && converge && converged_ida(ref, false).key() != it.reference.key())
      it.reference_check = converged_ida(ref, false);
  };
  std::vector<ScoreItem> items;
  for (const std::string& set : options.sets)
    for (const fs::path& scene : set_scenes(set, matrix, data_root)) {
      ScoreItem it;
      it.run = JobSpec{scene, method, std::nullopt, "", {}, {}};
      if (const Case* best = best_case(matrix, scene, method)) {
        if (best->run.method == method) it.run = best->run;
        reference(it, best->reference);
        it.reference_kind = best->reference.method;
        it.gates = best->gates;
        it.source = best->name();
      } else {
        reference(it, JobSpec{scene, "ida", std::nullopt, "", {}, {}});
        it.reference_kind = "ida";
      }
      items.push_back(std::move(it));
    }
  return items;
}

std::string verdict(double error, double tol, std::optional<double> spread) {
  if (!std::isfinite(error)) return "fail";
  const double s = spread.value_or(0.0);
  if (error + s <= tol) return "pass";
  if (error - s > tol) return "fail";
  return "reference uncertain";
}

namespace {

using Status = JobOutcome::Status;

/// The reference compared with its check (its spread), or none: no check, or the check did not
/// finish or compare (said in `note`).
std::optional<Comparison> reference_spread(const ScoreItem& it, const JobOutcome& ref,
                                           const std::map<std::string, JobOutcome>& runs, std::string& note) {
  if (!it.reference_check || ref.status != Status::kOk) return std::nullopt;
  const JobOutcome& check = runs.at(it.reference_check->key());
  const std::string label = "reference check " + it.reference_check->settings_label();
  if (check.status != Status::kOk) {
    note = label + " " + status_name(check.status) + " (spread unknown): " + check.message;
    return std::nullopt;
  }
  try {
    return compare_runs(StoredRun::read(ref.dir), StoredRun::read(check.dir));
  } catch (const std::exception& e) {
    note = label + " did not compare (spread unknown): " + e.what();
    return std::nullopt;
  }
}

/// One quantity: the run's error, the reference's spread and the verdict under the gate's
/// tolerance; without a comparison, the row's status and its reason.
ScoreQuantity quantity(const Gate& g, const std::optional<Comparison>& cmp,
                       const std::optional<Comparison>& spread, const std::string& status,
                       const std::string& why, const std::string& spread_note) {
  ScoreQuantity q{g.metric, std::nullopt, g.tol, std::nullopt, status, why};
  if (!cmp) return q;
  const Norm* n = cmp->find(g.metric);
  q.error = n ? n->value : std::nullopt;
  const Norm* s = spread ? spread->find(g.metric) : nullptr;
  q.reference_spread = s ? s->value : std::nullopt;
  const std::string tail = spread_note.empty() ? "" : "; " + spread_note;
  if (!g.tol) {
    q.status = "no tolerance";
    q.note = "the matrix has no case for this scene: the error is reported, not judged" + tail;
    return q;
  }
  const GateResult r = check_gate(g, *cmp);
  if (!r.value) {
    q.status = to_string(r.status);
    q.note = r.message;
    return q;
  }
  q.status = verdict(*r.value, *g.tol, q.reference_spread);
  const std::string spread_text =
      q.reference_spread ? fmt::format("the reference's spread {:.3g}", *q.reference_spread) : "";
  if (q.status == "pass")
    q.note = g.why + tail;
  else if (q.status == "fail")
    q.note = r.message + (spread_text.empty() ? "" : " by more than " + spread_text) + tail;
  else
    q.note = fmt::format("{} = {:.4g} against {:g}: {} could reverse the verdict", g.metric, *r.value, *g.tol,
                         spread_text);
  return q;
}

}  // namespace

std::vector<ScoreRow> score_rows(const std::vector<ScoreItem>& items,
                                 const std::map<std::string, JobOutcome>& runs) {
  std::vector<ScoreRow> rows;
  for (const ScoreItem& it : items) {
    ScoreRow row{&it, runs.at(it.run.key()), {}};
    const JobOutcome& ref = runs.at(it.reference.key());
    std::vector<Gate> gates = it.gates;
    if (gates.empty())
      for (const auto& m : default_metrics())
        gates.push_back(Gate{m, std::nullopt, std::nullopt, "", std::nullopt});
    std::optional<Comparison> cmp;
    std::string status, why, spread_note;
    if (row.outcome.status != Status::kOk) {
      status = status_name(row.outcome.status);
      why = row.outcome.message;
    } else if (ref.status != Status::kOk) {
      status = "skipped";
      why = "reference " + it.reference.settings_label() + " " + status_name(ref.status) + ": " + ref.message;
    } else {
      try {
        cmp = compare_runs(StoredRun::read(row.outcome.dir), StoredRun::read(ref.dir));
      } catch (const std::exception& e) {
        status = "failed";
        why = e.what();
      }
    }
    const std::optional<Comparison> spread =
        cmp ? reference_spread(it, ref, runs, spread_note) : std::nullopt;
    for (const Gate& g : gates) row.quantities.push_back(quantity(g, cmp, spread, status, why, spread_note));
    rows.push_back(std::move(row));
  }
  return rows;
}

namespace {

nlohmann::json number(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

/// One quantity in scorecard.json.
nlohmann::json quantity_json(const ScoreQuantity& q) {
  return {{"metric", q.metric},   {"error", number(q.error)},
          {"tol", number(q.tol)}, {"reference_spread", number(q.reference_spread)},
          {"status", q.status},   {"note", q.note}};
}

/// One quantity as a row of the page's table.
std::string quantity_row(const ScoreRow& r, const ScoreQuantity& q) {
  const std::string cls = q.status == "pass"                           ? "pass"
                          : q.status == "fail" || q.status == "failed" ? "fail"
                          : q.status == "reference uncertain"          ? "unc"
                                                                       : "na";
  return fmt::format(
      "<tr class=\"{}\"><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
      "<td>{:.3f}</td><td>{}</td></tr>\n",
      cls, xml_escape(r.item->run.scene_name()), xml_escape(r.item->reference.settings_label()),
      xml_escape(q.metric), text(q.error), text(q.reference_spread), text(q.tol), xml_escape(q.status),
      r.outcome.solver_seconds, xml_escape(q.note));
}

/// One scored scene in scorecard.json.
nlohmann::json scene_json(const ScoreRow& r, nlohmann::json quantities) {
  const ScoreItem& it = *r.item;
  return {{"scene", it.run.scene_name()},
          {"file", it.run.scene.string()},
          {"run", it.run.settings_label()},
          {"reference", it.reference.settings_label()},
          {"reference_kind", it.reference_kind},
          {"reference_check",
           it.reference_check ? nlohmann::json(it.reference_check->settings_label()) : nlohmann::json()},
          {"tolerances_from", it.source},
          {"status", status_name(r.outcome.status)},
          {"message", r.outcome.message},
          {"solver_seconds", r.outcome.solver_seconds},
          {"process_seconds", r.outcome.process_seconds},
          {"steps", r.outcome.steps},
          {"dt", r.outcome.dt},
          {"quantities", std::move(quantities)}};
}

/// The self-contained page: how it was made, what the columns mean, the table's rows.
std::string scorecard_page(const ScoreContext& ctx, const std::string& tally, const std::string& body) {
  return fmt::format(
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Scorecard: {0}</title>\n<style>\n"
      "body{{font-family:sans-serif;margin:2em}} table{{border-collapse:collapse}} "
      "td,th{{border:1px solid #bbb;padding:3px 8px;text-align:left}} th{{background:#eee}} "
      ".pass td:nth-child(7){{background:#d8f5d8}} .fail td:nth-child(7){{background:#f8d0d0}} "
      ".unc td:nth-child(7){{background:#fff3c4}} .na td:nth-child(7){{background:#eee}}\n"
      "</style></head><body>\n"
      "<h1>Scorecard: {0}</h1>\n<p>{1}</p>\n<p>Command: <code>{2}</code>; version {3}; made {4} (UTC); "
      "wall time {5:.1f} s.</p>\n<p>Quantities: {6}. Each run is compared with the best reference of its "
      "scene (exact where the verification matrix has one, else {8}) under the matrix's own tolerance "
      "for that scene; error: the norm of <code>beamimpact compare</code> (relative unless the metric "
      "says otherwise); reference spread: the reference against the same run at the case's penalty, "
      "its own uncertainty (a verdict it could reverse is <em>reference uncertain</em>); solver s: the "
      "method's own time (summary.json wall_seconds).</p>\n"
      "<table>\n<tr><th>scene</th><th>reference</th><th>quantity</th><th>error</th><th>reference "
      "spread</th><th>tolerance</th><th>status</th><th>solver s</th><th>note</th></tr>\n{7}</table>\n"
      "</body></html>\n",
      xml_escape(ctx.method), xml_escape(ctx.origin), xml_escape(ctx.command), xml_escape(ctx.version),
      xml_escape(ctx.made), ctx.wall_seconds, xml_escape(tally), body, ida_reference(ctx.options));
}

}  // namespace

void write_scorecard(const fs::path& dir, const ScoreContext& ctx, const std::vector<ScoreRow>& rows) {
  fs::create_directories(dir);
  std::map<std::string, int> counts;
  nlohmann::json scenes = nlohmann::json::array();
  std::string body;
  for (const ScoreRow& r : rows) {
    nlohmann::json qs = nlohmann::json::array();
    for (const ScoreQuantity& q : r.quantities) {
      ++counts[q.status];
      qs.push_back(quantity_json(q));
      body += quantity_row(r, q);
    }
    scenes.push_back(scene_json(r, std::move(qs)));
  }
  const nlohmann::json j = {{"method", ctx.method},
                            {"origin", ctx.origin},
                            {"command", ctx.command},
                            {"version", ctx.version},
                            {"made", ctx.made},
                            {"sets", ctx.options.sets},
                            {"references", ctx.options.references},
                            {"wall_seconds", ctx.wall_seconds},
                            {"counts", counts},
                            {"scenes", scenes},
                            {"units",
                             {{"solver_seconds", "s, summary.json wall_seconds: the method's own time"},
                              {"process_seconds", "s, the process from start to end"},
                              {"reference_spread", "the error's norm: the reference against its check"}}}};
  write_file_atomic(dir / "scorecard.json", j.dump(1) + "\n");
  std::string tally;
  for (const auto& [status, n] : counts)
    tally += fmt::format("{}{} {}", tally.empty() ? "" : ", ", n, status);
  write_file_atomic(dir / "scorecard.html", scorecard_page(ctx, tally, body));
}

}  // namespace beamimpact::verification
