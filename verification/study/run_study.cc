#include <verification/study/run_study.hpp>

#include <algorithm>
#include <chrono>
#include <map>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <beamimpact/version.hpp>
#include <solver/util/Progress.hpp>
#include <solver/util/write_file_atomic.hpp>
#include <verification/jobs/Table.hpp>
#include <verification/jobs/task_farm.hpp>
#include <verification/study/finished_points.hpp>

namespace beamimpact::study {
namespace {

namespace fs = std::filesystem;

std::string num(const std::optional<double>& v) { return v ? fmt::format("{:.6g}", *v) : ""; }

std::string point_label(const Study& s, const Point& p) {
  std::string l;
  for (std::size_t k = 0; k < s.parameters.size(); ++k)
    l += fmt::format("{}{}={:g}", l.empty() ? "" : " ", s.parameters[k].name, p.values[k]);
  return l;
}

std::optional<double> metric(const Study& s, const CaseResult& c, const std::string& name) {
  const auto it = std::find(s.norms.begin(), s.norms.end(), name);
  if (it == s.norms.end()) return std::nullopt;
  return c.norms[static_cast<std::size_t>(it - s.norms.begin())];
}

/// True when the case counts as a breakdown of the method: not "ok", or the study's metric of
/// one of its `breaks` rules above that rule's bound.
bool broke(const Study& s, const CaseResult& c) {
  if (c.status != "ok") return c.status != "no_reference";
  for (const auto& rule : s.breaks) {
    const auto v = metric(s, c, rule.metric);
    if (v && *v > rule.above) return true;
  }
  return false;
}

/// Rank 0, before the points are handed out: the points finished earlier (recorded with the same
/// input) go into r.results with cost -1 (not run again), the others get their cost. Returns how
/// many were finished.
std::size_t take_finished(const Study& s, const fs::path& out, const nlohmann::json& base, bool fresh,
                          StudyResult& r, std::vector<double>& cost) {
  prepare_point_records(out, fresh);
  std::size_t reused = 0;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    if (auto p = fresh ? std::nullopt : recorded_point(out, base, i, r.points[i])) {
      r.results[i] = std::move(*p);
      cost[i] = -1.0;
      ++reused;
    } else {
      cost[i] = point_cost(s, r.points[i]);
    }
  }
  return reused;
}

}  // namespace

std::optional<StudyResult> execute_study(const Study& s, const fs::path& out, bool fresh) {
  const auto start = std::chrono::steady_clock::now();
  StudyResult r;
  r.points = design_points(s);
  r.ranks = jobs::World::size();
  const std::size_t n = r.points.size();
  r.results.resize(n);
  std::vector<double> cost(n);
  std::size_t finished = 0;  // points done, those of an earlier, interrupted study included
  nlohmann::json base;
  if (jobs::World::rank() == 0) {
    base = study_input(s);
    finished = r.resumed = take_finished(s, out, base, fresh, r, cost);
    fmt::print(stderr, "study {}: {} point(s) x {} method(s), reference {}, {} rank(s)\n", s.name, n,
               s.methods.size(), s.reference.method, r.ranks);
    if (finished > 0)
      fmt::print(stderr,
                 "resumed: {} of {} points finished earlier ({}/points; --fresh runs them all again)\n",
                 finished, n, out.string());
  }
  const fs::path runs = out / "runs";
  r.results.resize(n);
  // One line per point instead of the methods' own progress; the caller's setting comes back.
  const Progress::Silence quiet;
  bool warned = false;
  const bool root = jobs::farm(
      cost, [&](std::size_t i) { return run_point(s, r.points[i], i, runs).to_json().dump(); },
      [&](std::size_t i, const std::string& payload, int rank) {
        PointResult p = PointResult::from_json(nlohmann::json::parse(payload));
        p.rank = rank;
        std::string line;
        double secs = p.reference_seconds;
        for (const auto& c : p.cases) {
          secs += c.seconds;
          line += fmt::format(" {} {}", c.method, c.status);
          for (const auto& rule : s.breaks)
            if (const auto v = metric(s, c, rule.metric)) line += fmt::format(" {} {:.3g}", rule.metric, *v);
        }
        fmt::print(stderr, "[{}/{}] #{} {}:{} ({:.2f} s, rank {})\n", ++finished, n, i,
                   point_label(s, r.points[i]), line, secs, rank);
        try {
          record_point(out, base, i, r.points[i], p);
        } catch (const std::exception& e) {  // the study goes on; only its resumption is lost
          if (!std::exchange(warned, true))
            fmt::print(stderr, "warning: {}: an interrupted study would run such points again\n", e.what());
        }
        r.results[i] = std::move(p);
      },
      [&](std::size_t i) { return fmt::format("study point #{} ({})", i, point_label(s, r.points[i])); });
  if (!root) return std::nullopt;
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

namespace {

/// What the study's outputs tabulate, filled in one pass over the cases.
struct StudyTables {
  jobs::Table csv, timing, broken;                 ///< study.csv, timing.csv, study.md's breakdowns
  nlohmann::json cases = nlohmann::json::array();  ///< study.json's cases
  std::map<std::string, int> counts;               ///< cases by "method status"
  std::size_t n_cases = 0, n_broken = 0;
};

StudyTables empty_tables(const Study& s) {
  std::vector<std::string> head{"index"};
  for (const auto& p : s.parameters) head.push_back(p.name);
  head.insert(head.end(), {"method", "status", "steps", "dt"});
  head.insert(head.end(), s.norms.begin(), s.norms.end());
  head.insert(head.end(), {"energy_growth", "broke", "message"});
  std::vector<std::string> broken_head{"#", "point", "method", "status"};
  for (const auto& rule : s.breaks) broken_head.push_back(rule.metric);
  broken_head.push_back("message");
  StudyTables t{jobs::Table(head),
                jobs::Table({"index", "method", "rank", "seconds", "reference_seconds"}),
                jobs::Table(broken_head),
                nlohmann::json::array(),
                {},
                0,
                0};
  t.csv.quote_column(head.size() - 1);  // the message: free text
  return t;
}

/// Adds case c of point i to every table.
void add_case(const Study& s, std::size_t i, const Point& pt, const PointResult& pr, const CaseResult& c,
              StudyTables& t) {
  ++t.n_cases;
  ++t.counts[c.method + " " + c.status];
  const bool b = broke(s, c);
  std::vector<std::string> row{fmt::format("{}", i)};
  for (double v : pt.values) row.push_back(fmt::format("{:.10g}", v));
  row.insert(row.end(), {c.method, c.status, fmt::format("{}", c.steps), fmt::format("{:.6g}", c.dt)});
  for (const auto& v : c.norms) row.push_back(num(v));
  row.insert(row.end(), {num(c.energy_growth), b ? "yes" : "no", c.message});
  t.csv.add(row);
  t.timing.add({fmt::format("{}", i), c.method, fmt::format("{}", pr.rank), fmt::format("{:.4f}", c.seconds),
                fmt::format("{:.4f}", pr.reference_seconds)});
  nlohmann::json norms = nlohmann::json::object();
  for (std::size_t k = 0; k < s.norms.size(); ++k) norms[s.norms[k]] = json_or_null(c.norms[k]);
  nlohmann::json values = nlohmann::json::object();
  for (std::size_t k = 0; k < s.parameters.size(); ++k) values[s.parameters[k].name] = pt.values[k];
  t.cases.push_back({{"index", i},
                     {"parameters", values},
                     {"method", c.method},
                     {"status", c.status},
                     {"message", c.message},
                     {"steps", c.steps},
                     {"dt", c.dt},
                     {"norms", norms},
                     {"energy_growth", json_or_null(c.energy_growth)},
                     {"reference_status", pr.reference_status},
                     {"broke", b}});
  if (!b) return;
  ++t.n_broken;
  std::vector<std::string> cells{fmt::format("{}", i), point_label(s, pt), c.method, c.status};
  for (const auto& rule : s.breaks) cells.push_back(num(metric(s, c, rule.metric)));
  cells.push_back(c.message.substr(0, 160));
  t.broken.add(cells);
}

/// study.json: the study's definition and its cases.
nlohmann::json study_json(const Study& s, const std::string& version, const nlohmann::json& cases) {
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : s.parameters) {
    const char* kind = p.kind == Parameter::Kind::kKey    ? "key"
                       : p.kind == Parameter::Kind::kMesh ? "mesh"
                                                          : "rake";
    params.push_back({{"name", p.name}, {"kind", kind}, {"target", p.target}, {"values", p.values}});
  }
  nlohmann::json rules = nlohmann::json::array();
  for (const auto& rule : s.breaks) rules.push_back({{"metric", rule.metric}, {"above", rule.above}});
  return {{"study", s.name},
          {"description", s.description},
          {"file", s.file.filename().string()},
          {"scene", s.scene.filename().string()},
          {"version", version},
          {"methods", s.methods},
          {"reference", {{"method", s.reference.method}, {"set", s.reference.set}}},
          {"set", s.set},
          {"design", s.design == Study::Design::kGrid ? "grid" : "lhs"},
          {"seed", s.seed},
          {"parameters", params},
          {"norms", s.norms},
          {"energy_growth_bound", s.energy_growth},
          {"breaks", rules},
          {"cases", cases}};
}

/// study.md: how it was made, the outcomes by method and status, and where the method broke.
std::string study_markdown(const Study& s, const StudyResult& r, const StudyTables& t,
                           const std::string& command, const std::string& version) {
  std::string rule_text;
  for (const auto& rule : s.breaks) rule_text += fmt::format(", or {} above {:g}", rule.metric, rule.above);
  std::string md = fmt::format(
      "# Study {}\n\n{}\n\n- command: `{}`\n- version: `{}`\n- scene: `{}` with `{}`\n- reference: {} {}\n"
      "- {} point(s) ({}), {} case(s); timing in timing.json\n\n## Outcomes\n\n",
      s.name, s.description, command, version, s.scene.filename().string(), fmt::join(s.set, "`, `"),
      s.reference.method, fmt::join(s.reference.set, " "), r.points.size(),
      s.design == Study::Design::kGrid ? "grid" : "Latin hypercube", t.n_cases);
  jobs::Table outcomes({"method status", "cases"});
  for (const auto& [k, v] : t.counts) outcomes.add({k, fmt::format("{}", v)});
  md += outcomes.markdown();
  md += fmt::format(
      "\n## Where the method broke ({} case(s))\n\nStatus not ok (error: refused; diverged: the run failed; "
      "energy: energy created above {:g} of E0){}.\n\n",
      t.n_broken, s.energy_growth, rule_text);
  return md + t.broken.markdown();
}

/// Every table of the study's results, in design order.
StudyTables tables_of(const Study& s, const StudyResult& r) {
  StudyTables t = empty_tables(s);
  for (std::size_t i = 0; i < r.points.size(); ++i)
    for (const auto& c : r.results[i].cases) add_case(s, i, r.points[i], r.results[i], c, t);
  return t;
}

}  // namespace

nlohmann::json study_json(const StudyResult& r, const std::string& version) {
  return study_json(r.study, version, tables_of(r.study, r).cases);
}

StudyCounts write_study(const Study& s, const StudyResult& r, const fs::path& out, const std::string& command,
                        const std::string& version) {
  fs::create_directories(out);
  StudyTables t = tables_of(s, r);
  const std::size_t run_now = t.n_cases - r.resumed * s.methods.size();
  const double rate = r.wall_seconds > 0 ? static_cast<double>(run_now) / r.wall_seconds : 0.0;
  const nlohmann::json timing{
      {"ranks", r.ranks},   {"points", r.points.size()},      {"points_finished_earlier", r.resumed},
      {"cases", t.n_cases}, {"wall_seconds", r.wall_seconds}, {"cases_per_second", rate}};
  write_file_atomic(out / "study.csv", t.csv.csv());
  write_file_atomic(out / "study.json", study_json(s, version, t.cases).dump(1) + "\n");
  write_file_atomic(out / "study.md", study_markdown(s, r, t, command, version));
  write_file_atomic(out / "timing.csv", t.timing.csv());
  write_file_atomic(out / "timing.json", timing.dump(1) + "\n");
  return {t.n_cases, t.n_broken, rate};
}

std::optional<StudyResult> run_study(const StudyOptions& o) {
  remove_stale_outputs(o.out, {"study.csv", "study.json", "study.md", "timing.csv", "timing.json"});
  Study s = Study::load(o.file);
  s.keep_runs = s.keep_runs || o.keep_runs;
  auto r = execute_study(s, o.out, o.fresh);
  if (!r) return std::nullopt;  // an MPI worker rank: rank 0 writes the tables
  r->study = std::move(s);
  r->command = fmt::format("beamimpact study {} --out {}{}{}", o.file.string(), o.out.string(),
                           o.keep_runs ? " --keep-runs" : "", o.fresh ? " --fresh" : "");
  return r;
}

StudyCounts write_study_reports(const StudyOptions& o, const StudyResult& r) {
  return write_study(r.study, r, o.out, r.command, kVersion);
}

}  // namespace beamimpact::study
