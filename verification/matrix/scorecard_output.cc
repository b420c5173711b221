// scorecard.json (scorecard.hpp); its page is reports/render.py's (tools/beamimpact/page.hpp).
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

/// One quantity in scorecard.json.
nlohmann::json quantity_json(const ScoreQuantity& q) {
  nlohmann::json j = {{"metric", q.metric},
                      {"error", number(q.error)},
                      {"tol", number(q.tol)},
                      {"uncertainty", number(q.uncertainty)},
                      {"status", to_string(q.status)},
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

/// One scored scene in scorecard.json.
nlohmann::json scene_json(const ScoreRow& r, nlohmann::json quantities) {
  const ScoreItem& it = *r.item;
  nlohmann::json rungs = nlohmann::json::array();
  for (const jobs::JobOutcome& o : r.rungs)
    if (!it.ladder.rungs.empty())
      rungs.push_back({{"run", o.spec.settings_label()},
                       {"status", to_string(o.status)},
                       {"dt", o.dt},
                       {"steps", o.steps},
                       {"solver_seconds", o.solver_seconds},
                       {"process_seconds", o.process_seconds}});
  nlohmann::json settled = nlohmann::json::array();
  for (const SettledValue& v : it.settled)
    settled.push_back(
        {{"metric", v.metric}, {"value", v.value}, {"uncertainty", v.uncertainty}, {"why", v.why}});
  return {{"scene", it.run.scene_name()},
          {"file", shown_path(it.run.scene.string())},
          {"set", it.set},
          {"run", it.run.settings_label()},
          {"reference", it.reference.settings_label()},
          {"reference_kind", it.reference_kind},
          {"reference_check",
           it.reference_check ? nlohmann::json(it.reference_check->settings_label()) : nlohmann::json()},
          {"settled", std::move(settled)},
          {"tolerances_from", it.source},
          {"ladder", {{"kind", it.ladder.kind}, {"why", it.ladder.why}, {"rungs", rungs}}},
          {"status", to_string(r.outcome.status)},
          {"message", r.outcome.message},
          {"solver_seconds", r.outcome.solver_seconds},
          {"process_seconds", r.outcome.process_seconds},
          {"steps", r.outcome.steps},
          {"dt", r.outcome.dt},
          {"quantities", std::move(quantities)}};
}

/// The quantities by status, under their scorecard.json words.
nlohmann::json counts_json(const std::map<QuantityStatus, int>& counts) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [status, n] : counts) j[to_string(status)] = n;
  return j;
}

/// Each status's scorecard.json word with the words a reader is shown (the page's table).
nlohmann::json status_words() {
  nlohmann::json j = nlohmann::json::object();
  for (QuantityStatus s : quantity_statuses()) j[to_string(s)] = describe(s);
  return j;
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
          {"ida_reference", ida_reference(ctx.options)},
          {"ladder", ctx.options.ladder},
          {"rungs", ctx.options.ladder ? ctx.options.rungs : 1},
          {"reference_cache", shown_path(ctx.cache)},
          {"wall_seconds", ctx.wall_seconds},
          {"verdict", v.exit_code == 0 ? "passed" : "failed"},
          {"verdict_line", v.line},
          {"exit_code", v.exit_code},
          {"counts", counts_json(v.counts)},
          {"statuses", status_words()},
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
}

}  // namespace beamimpact::verification
