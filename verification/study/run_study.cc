#include <verification/study/run_study.hpp>

#include <algorithm>
#include <chrono>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <verification/study/task_farm.hpp>
#include <solver/util/Progress.hpp>
#include <solver/util/write_file_atomic.hpp>

namespace beamimpact::study {
namespace {

namespace fs = std::filesystem;

std::string num(const std::optional<double>& v) { return v ? fmt::format("{:.6g}", *v) : ""; }

std::string csv_text(const std::string& s) {
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + "\"";
}

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

}  // namespace

std::optional<StudyResult> execute_study(const Study& s, const fs::path& out) {
  const auto start = std::chrono::steady_clock::now();
  StudyResult r;
  r.points = design_points(s);
  r.ranks = World::size();
  const std::size_t n = r.points.size();
  std::vector<double> cost(n);
  if (World::rank() == 0) {
    for (std::size_t i = 0; i < n; ++i) cost[i] = point_cost(s, r.points[i]);
    fmt::print(stderr, "study {}: {} point(s) x {} method(s), reference {}, {} rank(s)\n", s.name, n,
               s.methods.size(), s.reference.method, r.ranks);
  }
  const fs::path runs = out / "runs";
  r.results.resize(n);
  // One line per point instead of the methods' own progress; the caller's setting comes back.
  const Progress::Silence quiet;
  std::size_t finished = 0;
  const bool root = farm(
      cost,
      [&](std::size_t i) {
        return run_point(s, r.points[i], i, runs).to_json().dump();
      },
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
        r.results[i] = std::move(p);
      },
      [&](std::size_t i) { return fmt::format("study point #{} ({})", i, point_label(s, r.points[i])); });
  if (!root) return std::nullopt;
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

StudyCounts write_study(const Study& s, const StudyResult& r, const fs::path& out, const std::string& command,
                 const std::string& version) {
  fs::create_directories(out);
  std::string csv = "index";
  for (const auto& p : s.parameters) csv += "," + p.name;
  csv += ",method,status,steps,dt";
  for (const auto& n : s.norms) csv += "," + n;
  csv += ",energy_growth,broke,message\n";
  std::string timing = "index,method,rank,seconds,reference_seconds\n";
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : s.parameters) {
    const char* kind = p.kind == Parameter::Kind::kKey ? "key" : p.kind == Parameter::Kind::kMesh ? "mesh" : "rake";
    params.push_back({{"name", p.name}, {"kind", kind}, {"target", p.target}, {"values", p.values}});
  }
  nlohmann::json cases = nlohmann::json::array();
  std::map<std::string, int> counts;
  std::string broken;
  std::size_t n_broken = 0, n_cases = 0;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const Point& pt = r.points[i];
    const PointResult& pr = r.results[i];
    for (const auto& c : pr.cases) {
      ++n_cases;
      ++counts[c.method + " " + c.status];
      const bool b = broke(s, c);
      csv += fmt::format("{}", i);
      for (double v : pt.values) csv += fmt::format(",{:.10g}", v);
      csv += fmt::format(",{},{},{},{:.6g}", c.method, c.status, c.steps, c.dt);
      for (const auto& v : c.norms) csv += "," + num(v);
      csv += fmt::format(",{},{},{}\n", num(c.energy_growth), b ? "yes" : "no", csv_text(c.message));
      timing += fmt::format("{},{},{},{:.4f},{:.4f}\n", i, c.method, pr.rank, c.seconds, pr.reference_seconds);
      nlohmann::json norms = nlohmann::json::object();
      for (std::size_t k = 0; k < s.norms.size(); ++k)
        norms[s.norms[k]] = json_or_null(c.norms[k]);
      nlohmann::json values = nlohmann::json::object();
      for (std::size_t k = 0; k < s.parameters.size(); ++k) values[s.parameters[k].name] = pt.values[k];
      cases.push_back({{"index", i},
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
      if (b) {
        ++n_broken;
        broken += fmt::format("| {} | {} | {} | {} |", i, point_label(s, pt), c.method, c.status);
        for (const auto& rule : s.breaks) broken += " " + num(metric(s, c, rule.metric)) + " |";
        broken += " " + c.message.substr(0, 160) + " |\n";
      }
    }
  }
  nlohmann::json rules = nlohmann::json::array();
  std::string rule_text, rule_head, rule_bar;
  for (const auto& rule : s.breaks) {
    rules.push_back({{"metric", rule.metric}, {"above", rule.above}});
    rule_text += fmt::format(", or {} above {:g}", rule.metric, rule.above);
    rule_head += " " + rule.metric + " |";
    rule_bar += "---|";
  }
  nlohmann::json j{{"study", s.name},
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
  const double rate = r.wall_seconds > 0 ? static_cast<double>(n_cases) / r.wall_seconds : 0.0;
  nlohmann::json t{{"ranks", r.ranks},
                   {"points", r.points.size()},
                   {"cases", n_cases},
                   {"wall_seconds", r.wall_seconds},
                   {"cases_per_second", rate}};
  std::string md = fmt::format(
      "# Study {}\n\n{}\n\n- command: `{}`\n- version: `{}`\n- scene: `{}` with `{}`\n- reference: {} {}\n"
      "- {} point(s) ({}), {} case(s); timing in timing.json\n\n## Outcomes\n\n| method status | cases |\n|---|---|\n",
      s.name, s.description, command, version, s.scene.filename().string(), fmt::join(s.set, "`, `"),
      s.reference.method, fmt::join(s.reference.set, " "), r.points.size(),
      s.design == Study::Design::kGrid ? "grid" : "Latin hypercube", n_cases);
  for (const auto& [k, v] : counts) md += fmt::format("| {} | {} |\n", k, v);
  md += fmt::format(
      "\n## Where the method broke ({} case(s))\n\nStatus not ok (error: refused; diverged: the run failed; energy: "
      "energy created above {:g} of E0){}.\n\n| # | point | method | status |{} message |\n|---|---|---|---|{}---|\n{}",
      n_broken, s.energy_growth, rule_text, rule_head, rule_bar, broken);
  write_file_atomic(out / "study.csv", csv);
  write_file_atomic(out / "study.json", j.dump(1) + "\n");
  write_file_atomic(out / "study.md", md);
  write_file_atomic(out / "timing.csv", timing);
  write_file_atomic(out / "timing.json", t.dump(1) + "\n");
  return {n_cases, n_broken, rate};
}

}  // namespace beamimpact::study
