// scorecard.json and scorecard.html (scorecard.hpp).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <api/methods_file.hpp>
#include <solver/util/write_file_atomic.hpp>
#include <verification/matrix/reports.hpp>
#include <verification/matrix/scorecard.hpp>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;

nlohmann::json number(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

/// A path as the scorecard shows it: relative to the data root (the repository or the installed
/// share/beamimpact) when it lies there, else to the working folder when it lies there, so that a
/// committed scorecard names no machine's folders.
std::string shown_path(const std::string& p) {
  std::error_code ec;
  if (p.empty() || !fs::exists(p, ec)) return p;
  const fs::path a = fs::absolute(p).lexically_normal();
  for (const fs::path& base : {data_root(), fs::current_path()}) {
    if (base.empty()) continue;
    const fs::path rel = a.lexically_relative(fs::absolute(base).lexically_normal());
    if (!rel.empty() && *rel.begin() != "..") return rel.string();
  }
  return p;
}

std::string text(const std::optional<double>& v) { return v ? fmt::format("{:.3g}", *v) : "-"; }

/// One quantity in scorecard.json.
nlohmann::json quantity_json(const ScoreQuantity& q) {
  nlohmann::json j = {{"metric", q.metric},
                      {"error", number(q.error)},
                      {"tol", number(q.tol)},
                      {"uncertainty", number(q.uncertainty)},
                      {"status", q.status},
                      {"judged", q.judged},
                      {"exact", number(q.exact)},
                      {"allowed", number(q.allowed)},
                      {"note", q.note}};
  // The reference's spread under its earlier name (reports/scorecard_table.py reads it).
  j["reference_spread"] = q.judged == "limit" ? nlohmann::json() : number(q.uncertainty);
  if (q.ladder)
    j["ladder"] = {{"values", q.ladder->values},
                   {"order", number(q.ladder->order)},
                   {"limit", number(q.ladder->limit)},
                   {"limit_uncertainty", number(q.ladder->uncertainty)},
                   {"why_not", q.ladder->why_not}};
  return j;
}

/// One quantity as a row of the page's table.
std::string quantity_row(const ScoreRow& r, const ScoreQuantity& q) {
  const std::string cls = q.status == "pass"                                                          ? "pass"
                          : q.status == "fail" || q.status == "failed" || q.status == "not converged" ? "fail"
                          : q.status == "reference uncertain"                                         ? "unc"
                                                                                                      : "na";
  return fmt::format(
      "<tr class=\"{}\"><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
      "<td>{}</td><td>{:.3f}</td><td>{}</td></tr>\n",
      cls, xml_escape(r.item->run.scene_name()), xml_escape(r.item->reference.settings_label()),
      xml_escape(q.metric), xml_escape(q.judged), text(q.error), text(q.uncertainty), text(q.tol),
      xml_escape(q.status), r.outcome.solver_seconds, xml_escape(q.note));
}

/// One scored scene in scorecard.json.
nlohmann::json scene_json(const ScoreRow& r, nlohmann::json quantities) {
  const ScoreItem& it = *r.item;
  nlohmann::json rungs = nlohmann::json::array();
  for (const JobOutcome& o : r.rungs)
    if (!it.ladder.rungs.empty())
      rungs.push_back({{"run", o.spec.settings_label()},
                       {"status", status_name(o.status)},
                       {"dt", o.dt},
                       {"steps", o.steps},
                       {"solver_seconds", o.solver_seconds},
                       {"process_seconds", o.process_seconds}});
  return {{"scene", it.run.scene_name()},
          {"file", shown_path(it.run.scene.string())},
          {"set", it.set},
          {"run", it.run.settings_label()},
          {"reference", it.reference.settings_label()},
          {"reference_kind", it.reference_kind},
          {"reference_check",
           it.reference_check ? nlohmann::json(it.reference_check->settings_label()) : nlohmann::json()},
          {"tolerances_from", it.source},
          {"ladder", {{"kind", it.ladder.kind}, {"why", it.ladder.why}, {"rungs", rungs}}},
          {"status", status_name(r.outcome.status)},
          {"message", r.outcome.message},
          {"solver_seconds", r.outcome.solver_seconds},
          {"process_seconds", r.outcome.process_seconds},
          {"steps", r.outcome.steps},
          {"dt", r.outcome.dt},
          {"quantities", std::move(quantities)}};
}

/// The self-contained page: how it was made, what the columns mean, the table's rows.
std::string scorecard_page(const ScoreContext& ctx, const ScoreVerdict& v, const std::string& body) {
  return fmt::format(
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Scorecard: {0}</title>\n<style>\n"
      "body{{font-family:sans-serif;margin:2em}} table{{border-collapse:collapse}} "
      "td,th{{border:1px solid #bbb;padding:3px 8px;text-align:left}} th{{background:#eee}} "
      ".pass td:nth-child(8){{background:#d8f5d8}} .fail td:nth-child(8){{background:#f8d0d0}} "
      ".unc td:nth-child(8){{background:#fff3c4}} .na td:nth-child(8){{background:#eee}}\n"
      "</style></head><body>\n"
      "<h1>Scorecard: {0}</h1>\n<p>{1}</p>\n<p><strong>{6}</strong></p>\n<p>Command: <code>{2}</code>; "
      "version {3}; "
      "made {4} (UTC); wall time {5:.1f} s.</p>\n<p>{9}. Each scene is judged under its benchmark card "
      "(docs/benchmark-cards.md: one reference and one tolerance per quantity, for every method). judged "
      "<em>limit</em>: the method ran a resolution ladder and the quantity's Richardson limit is compared "
      "with the exact value, passing within 1.25 x its uncertainty + tol / 10; <em>single run</em>: the run "
      "against the reference (exact, or {8}) under the tolerance; error: the norm of <code>beamimpact "
      "compare</code> (relative unless the metric says otherwise); uncertainty: the limit's, or the "
      "reference's spread (a verdict it could reverse is <em>reference uncertain</em>); solver s: the "
      "method's own time (summary.json wall_seconds).</p>\n"
      "<table>\n<tr><th>scene</th><th>reference</th><th>quantity</th><th>judged</th><th>error</th>"
      "<th>uncertainty</th><th>tolerance</th><th>status</th><th>solver s</th><th>note</th></tr>\n{7}"
      "</table>\n</body></html>\n",
      xml_escape(ctx.method), xml_escape(ctx.origin), xml_escape(ctx.command), xml_escape(ctx.version),
      xml_escape(ctx.made), ctx.wall_seconds, xml_escape(v.line), body, ida_reference(ctx.options),
      ctx.options.ladder ? "Ladders on the scenes with an exact answer"
                         : "Single resolution (--no-ladder): one run a scene");
}

}  // namespace

nlohmann::json scorecard_json(const ScoreContext& ctx, const std::vector<ScoreRow>& rows,
                              const ScoreVerdict& v) {
  nlohmann::json scenes = nlohmann::json::array();
  for (const ScoreRow& r : rows) {
    nlohmann::json qs = nlohmann::json::array();
    for (const ScoreQuantity& q : r.quantities) qs.push_back(quantity_json(q));
    scenes.push_back(scene_json(r, std::move(qs)));
  }
  return {{"method", ctx.method},
          {"origin", shown_path(ctx.origin)},
          {"command", ctx.command},
          {"version", ctx.version},
          {"made", ctx.made},
          {"sets", ctx.options.sets},
          {"references", ctx.options.references},
          {"ladder", ctx.options.ladder},
          {"rungs", ctx.options.ladder ? ctx.options.rungs : 1},
          {"reference_cache", shown_path(ctx.cache)},
          {"wall_seconds", ctx.wall_seconds},
          {"verdict", v.exit_code == 0 ? "passed" : "failed"},
          {"verdict_line", v.line},
          {"exit_code", v.exit_code},
          {"counts", v.counts},
          {"scenes", scenes},
          {"rules",
           {{"limit", "pass when |limit - exact| <= 1.25 x uncertainty + tol / 10 (4-ulp slack)"},
            {"single run", "pass when error + spread <= tol, fail when error - spread > tol (4-ulp slack)"},
            {"not converged", "observed order < 0.5, or rung differences that do not shrink monotonically"}}},
          {"units",
           {{"solver_seconds", "s, summary.json wall_seconds: the method's own time"},
            {"process_seconds", "s, the process from start to end"},
            {"error", "the metric's norm (relative unless in s or a count)"},
            {"uncertainty", "same unit as error: the limit's, or the reference's spread"}}}};
}

void write_scorecard(const fs::path& dir, const ScoreContext& ctx, const std::vector<ScoreRow>& rows,
                     const ScoreVerdict& v) {
  fs::create_directories(dir);
  write_file_atomic(dir / "scorecard.json", scorecard_json(ctx, rows, v).dump(1) + "\n");
  std::string body;
  for (const ScoreRow& r : rows)
    for (const ScoreQuantity& q : r.quantities) body += quantity_row(r, q);
  write_file_atomic(dir / "scorecard.html", scorecard_page(ctx, v, body));
}

}  // namespace beamimpact::verification
