#include <verification/matrix/scorecard.hpp>

#include <algorithm>
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

/// IDA converged beyond its defaults, keeping the reference's own settings: time tolerances 100
/// times tighter (rtol 1e-10, atol 1e-13) and a penalty 10 times stiffer (1e4 EA/le), so that
/// IDA's step and penetration errors fall below the defaults' by about those factors. Every
/// method's scorecard takes it wherever its reference would be IDA: IDA is never compared with
/// its own run, and every method meets the same reference on a scene.
JobSpec converged_ida(JobSpec ref) {
  const auto has = [&](const std::string& key) {
    return std::any_of(ref.set.begin(), ref.set.end(),
                       [&](const std::string& s) { return s.rfind(key + "=", 0) == 0; });
  };
  for (const char* s : {"ida.rtol=1e-10", "ida.atol=1e-13", "ida.kn_factor=1e4"}) {
    const std::string key = std::string(s).substr(0, std::string(s).find('='));
    if (!has(key) && !(key == "ida.kn_factor" && has("ida.kn"))) ref.set.push_back(s);
  }
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
             ? "IDA converged beyond its defaults: rtol 1e-10, atol 1e-13, penalty 1e4 EA/le, with the "
               "case's own "
               "settings"
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
  const auto reference = [&](const JobSpec& ref) {
    return ref.method == "ida" && options.references == "converged" ? converged_ida(ref) : ref;
  };
  std::vector<ScoreItem> items;
  for (const std::string& set : options.sets)
    for (const fs::path& scene : set_scenes(set, matrix, data_root)) {
      ScoreItem it;
      it.run = JobSpec{scene, method, std::nullopt, "", {}, {}};
      if (const Case* best = best_case(matrix, scene, method)) {
        if (best->run.method == method) it.run = best->run;
        it.reference = reference(best->reference);
        it.reference_kind = best->reference.method;
        it.gates = best->gates;
        it.source = best->name();
      } else {
        it.reference = reference(JobSpec{scene, "ida", std::nullopt, "", {}, {}});
        it.reference_kind = "ida";
      }
      items.push_back(std::move(it));
    }
  return items;
}

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
    std::string status, why;
    if (row.outcome.status != JobOutcome::Status::kOk) {
      status = status_name(row.outcome.status);
      why = row.outcome.message;
    } else if (ref.status != JobOutcome::Status::kOk) {
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
    for (const Gate& g : gates) {
      ScoreQuantity q{g.metric, std::nullopt, g.tol, status, why};
      if (cmp && g.tol) {
        const GateResult r = check_gate(g, *cmp);
        q.error = r.value;
        q.status = to_string(r.status);
        q.note = r.status == GateStatus::kPass ? g.why : r.message;
      } else if (cmp) {
        const Norm* n = cmp->find(g.metric);
        q.error = n ? n->value : std::nullopt;
        q.status = "no tolerance";
        q.note = "the matrix has no case for this scene: the error is reported, not judged";
      }
      row.quantities.push_back(std::move(q));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

void write_scorecard(const fs::path& dir, const ScoreContext& ctx, const std::vector<ScoreRow>& rows) {
  fs::create_directories(dir);
  std::map<std::string, int> counts;
  nlohmann::json scenes = nlohmann::json::array();
  std::string body;
  for (const ScoreRow& r : rows) {
    const ScoreItem& it = *r.item;
    nlohmann::json qs = nlohmann::json::array();
    for (const ScoreQuantity& q : r.quantities) {
      ++counts[q.status];
      qs.push_back({{"metric", q.metric},
                    {"error", q.error ? nlohmann::json(*q.error) : nlohmann::json()},
                    {"tol", q.tol ? nlohmann::json(*q.tol) : nlohmann::json()},
                    {"status", q.status},
                    {"note", q.note}});
      body += fmt::format(
          "<tr class=\"{}\"><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.3f}</td>"
          "<td>{}</td></tr>\n",
          q.status == "pass"                           ? "pass"
          : q.status == "fail" || q.status == "failed" ? "fail"
                                                       : "na",
          xml_escape(it.run.scene_name()), xml_escape(it.reference.settings_label()), xml_escape(q.metric),
          text(q.error), text(q.tol), xml_escape(q.status), r.outcome.solver_seconds, xml_escape(q.note));
    }
    scenes.push_back({{"scene", it.run.scene_name()},
                      {"file", it.run.scene.string()},
                      {"run", it.run.settings_label()},
                      {"reference", it.reference.settings_label()},
                      {"reference_kind", it.reference_kind},
                      {"tolerances_from", it.source},
                      {"status", status_name(r.outcome.status)},
                      {"message", r.outcome.message},
                      {"solver_seconds", r.outcome.solver_seconds},
                      {"process_seconds", r.outcome.process_seconds},
                      {"steps", r.outcome.steps},
                      {"dt", r.outcome.dt},
                      {"quantities", qs}});
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
                              {"process_seconds", "s, the process from start to end"}}}};
  write_file_atomic(dir / "scorecard.json", j.dump(1) + "\n");
  std::string tally;
  for (const auto& [status, n] : counts) tally += fmt::format("{} {}, ", n, status);
  if (!tally.empty()) tally.resize(tally.size() - 2);
  const std::string html = fmt::format(
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Scorecard: {0}</title>\n<style>\n"
      "body{{font-family:sans-serif;margin:2em}} table{{border-collapse:collapse}} "
      "td,th{{border:1px solid #bbb;padding:3px 8px;text-align:left}} th{{background:#eee}} "
      ".pass td:nth-child(6){{background:#d8f5d8}} .fail td:nth-child(6){{background:#f8d0d0}} "
      ".na td:nth-child(6){{background:#eee}}\n</style></head><body>\n"
      "<h1>Scorecard: {0}</h1>\n<p>{1}</p>\n<p>Command: <code>{2}</code>; version {3}; made {4} (UTC); "
      "wall time {5:.1f} s.</p>\n<p>Quantities: {6}. Each run is compared with the best reference of its "
      "scene "
      "(exact where the verification matrix has one, else {8}) under the matrix's own tolerance for that "
      "scene; "
      "error: the norm of <code>beamimpact compare</code> (relative unless the metric says otherwise); "
      "solver s: the method's own time (summary.json wall_seconds).</p>\n"
      "<table>\n<tr><th>scene</th><th>reference</th><th>quantity</th><th>error</th><th>tolerance</th>"
      "<th>status</th><th>solver s</th><th>note</th></tr>\n{7}</table>\n</body></html>\n",
      xml_escape(ctx.method), xml_escape(ctx.origin), xml_escape(ctx.command), xml_escape(ctx.version),
      xml_escape(ctx.made), ctx.wall_seconds, xml_escape(tally), body, ida_reference(ctx.options));
  write_file_atomic(dir / "scorecard.html", html);
}

}  // namespace beamimpact::verification
