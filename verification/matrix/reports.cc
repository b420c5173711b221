#include <verification/matrix/reports.hpp>

#include <algorithm>
#include <ctime>
#include <fstream>
#include <map>
#include <set>
#include <utility>

#include <fmt/format.h>

#include <verification/jobs/Table.hpp>

namespace beamimpact::verification {

std::string xml_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      case '\'': o += "&apos;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t')
          o += ' ';
        else
          o += c;
    }
  }
  return o;
}

namespace {

std::string md_escape(std::string s) {
  std::string o;
  for (char c : s) o += c == '|' ? std::string("\\|") : std::string(1, c);
  return o;
}

std::string value_text(const GateResult& g) { return g.value ? fmt::format("{:.4g}", *g.value) : "n/a"; }

std::map<std::string, std::vector<const ItemResult*>> by_scene(const std::vector<ItemResult>& items) {
  std::map<std::string, std::vector<const ItemResult*>> m;
  for (const auto& i : items) m[i.scene].push_back(&i);
  return m;
}

/// A ladder's tables: the errors and observed orders of every norm, then the Richardson limits.
std::string ladder_tables(const ItemResult& i) {
  std::string m = fmt::format(
      "\nObserved orders, {} ({}, then orders):\n\n", i.name,
      i.reference.empty() ? "errors of consecutive pairs" : "errors of each rung against the reference");
  const std::size_t ne = i.orders.begin()->second.first.size();
  std::vector<std::string> header{"norm"};
  for (std::size_t k = 0; k < ne; ++k) header.push_back(fmt::format("e{}", k + 1));
  for (std::size_t k = 0; k + 1 < ne; ++k) header.push_back(fmt::format("p{}", k + 1));
  jobs::Table orders(header);
  for (const auto& c : i.comparisons.front().norms) {
    const auto& [e, p] = i.orders.at(c.name);
    std::vector<std::string> row{c.name};
    for (const auto& v : e) row.push_back(v ? fmt::format("{:.3e}", *v) : "n/a");
    for (const auto& v : p) row.push_back(v ? fmt::format("{:.2f}", *v) : "-");
    orders.add(row);
  }
  m += orders.markdown();
  if (i.richardson.empty()) return m;
  jobs::Table rich({"norm", "order p", "limit Q_R", "reference", "abs(Q_R - ref) / ref", "E_R / ref"});
  for (const auto& [name, x] : i.richardson)
    rich.add({name, fmt::format("{:.2f}", x.order), fmt::format("{:.6g}", x.limit),
              fmt::format("{:.6g}", x.reference), fmt::format("{:.2e}", x.error),
              fmt::format("{:.2e}", x.estimate)});
  return m +
         "\nRichardson limits of the last three rungs (their own observed order; the reference not "
         "used):\n\n" +
         rich.markdown();
}

/// A gate row's run and reference cells. A ladder's run is its rungs and what they are judged
/// against: its reference run (Convergence::name()'s " vs REFERENCE" said once, in words), or,
/// without one, each rung against the next finer (self-convergence).
std::pair<std::string, std::string> row_labels(const ItemResult& i) {
  if (i.kind != "convergence") return {i.settings, i.reference};
  std::string rungs = i.name.substr(std::min(i.name.size(), i.scene.size() + 1));
  if (i.reference.empty()) return {rungs + " (self-convergence: each rung against the next finer)", "-"};
  const std::string vs = " vs " + i.reference;
  if (rungs.size() >= vs.size() && rungs.compare(rungs.size() - vs.size(), vs.size(), vs) == 0)
    rungs.resize(rungs.size() - vs.size());
  return {rungs + " (ladder: each rung against " + i.reference + ")", i.reference};
}

}  // namespace

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

void write_junit(const std::filesystem::path& file, const ReportContext& ctx,
                 const std::vector<ItemResult>& items) {
  const GateCounts all = count_gates(items);
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += fmt::format(
      "<testsuites name=\"beamimpact verify {}{}\" tests=\"{}\" failures=\"{}\" skipped=\"{}\" "
      "time=\"{:.3f}\">\n",
      xml_escape(ctx.tier), ctx.incomplete.empty() ? "" : " (INCOMPLETE: " + xml_escape(ctx.incomplete) + ")",
      all.gates, all.fail, all.skipped, ctx.wall_seconds);
  for (const auto& [scene, list] : by_scene(items)) {
    int n = 0, f = 0, s = 0;
    double time = 0.0;
    for (const auto* i : list) {
      time += i->wall_seconds;
      for (const auto& g : i->gates) {
        ++n;
        f += g.status == GateStatus::kFail;
        s += g.status == GateStatus::kSkipped;
      }
    }
    x +=
        fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" skipped=\"{}\" time=\"{:.3f}\">\n",
                    xml_escape(scene), n, f, s, time);
    for (const auto* i : list) {
      std::string cls = scene + "." + i->settings;
      for (char& c : cls)
        if (c == ' ') c = '.';
      for (const auto& g : i->gates) {
        const std::string name = i->name + ": " + g.gate.metric + (g.gate.min_order ? " order" : "");
        x += fmt::format("    <testcase classname=\"{}\" name=\"{}\" time=\"{:.3f}\">", xml_escape(cls),
                         xml_escape(name),
                         i->gates.empty() ? 0.0 : i->wall_seconds / static_cast<double>(i->gates.size()));
        const std::string detail =
            fmt::format("value {} limit {} | why: {}", value_text(g), g.limit(), g.gate.why);
        if (g.status == GateStatus::kFail)
          x += fmt::format("\n      <failure message=\"{}\">{}</failure>\n    ", xml_escape(g.message),
                           xml_escape(detail));
        else if (g.status == GateStatus::kSkipped)
          x += fmt::format("\n      <skipped message=\"{}\"/>\n    ", xml_escape(g.message));
        else
          x += fmt::format("<system-out>{}</system-out>", xml_escape(detail));
        x += "</testcase>\n";
      }
    }
    x += "  </testsuite>\n";
  }
  x += "</testsuites>\n";
  write_file_atomic(file, x);
}

nlohmann::json norms_json(const ReportContext& ctx, const std::vector<ItemResult>& items) {
  const GateCounts t = count_gates(items);
  nlohmann::json j{{"command", ctx.command},
                   {"matrix", ctx.matrix},
                   {"tier", ctx.tier},
                   {"version", ctx.version},
                   {"started_utc", ctx.started},
                   {"wall_seconds", ctx.wall_seconds},
                   {"jobs", ctx.jobs},
                   {"gates", t.gates},
                   {"passed", t.pass},
                   {"failed", t.fail},
                   {"skipped", t.skipped},
                   {"complete", ctx.incomplete.empty()},
                   {"verdict", verification_passed(items, ctx.incomplete.empty()) ? "PASS" : "FAIL"}};
  if (!ctx.incomplete.empty()) j["incomplete"] = ctx.incomplete;
  auto& arr = j["items"] = nlohmann::json::array();
  for (const auto& i : items) arr.push_back(to_json(i));
  return j;
}

void write_json(const std::filesystem::path& file, const ReportContext& ctx,
                const std::vector<ItemResult>& items) {
  write_file_atomic(file, norms_json(ctx, items).dump(1) + "\n");
}

void write_markdown(const std::filesystem::path& file, const ReportContext& ctx,
                    const std::vector<ItemResult>& items) {
  const GateCounts t = count_gates(items);
  std::string m = "# beamimpact verification report\n\n";
  if (!ctx.incomplete.empty()) m += "**INCOMPLETE: " + ctx.incomplete + "**\n\n";
  m += fmt::format(
      "- command: `{}`\n- matrix: `{}`, tier **{}**, {} parallel job(s)\n- version: `{}`\n"
      "- started {} (UTC), wall time {:.1f} s\n",
      ctx.command, ctx.matrix, ctx.tier, ctx.jobs, ctx.version, ctx.started, ctx.wall_seconds);
  std::set<std::string> scenes;
  for (const auto& i : items) scenes.insert(i.scene);
  std::string sl;
  for (const auto& s : scenes) sl += (sl.empty() ? "" : ", ") + s;
  m += "- scenes: " + sl + "\n";
  m += fmt::format("\n**{}**: {} gates, {} passed, {} failed, {} skipped.\n\n",
                   verification_passed(items, ctx.incomplete.empty()) ? "PASS" : "FAIL", t.gates, t.pass,
                   t.fail, t.skipped);
  m += "Value: the error of the run against its reference (relative unless the unit says s or count; "
       "definitions at the end), or the observed order p = log(e_coarse/e_fine)/log(r) for convergence "
       "ladders. "
       "Wall: process time of the run under test (ladders: all rungs).\n";

  for (const auto& [scene, list] : by_scene(items)) {
    jobs::Table gates({"run", "reference", "norm", "value", "limit", "result", "wall s"});
    for (const auto* i : list) {
      const auto [run, reference] = row_labels(*i);
      for (const auto& g : i->gates) {
        const std::string res = g.status == GateStatus::kPass   ? "pass"
                                : g.status == GateStatus::kFail ? "**FAIL**: " + g.message
                                                                : "skipped: " + g.message;
        gates.add({run, reference, g.gate.metric, value_text(g), g.limit(), res,
                   fmt::format("{:.2f}", i->wall_seconds)});
      }
    }
    m += fmt::format("\n## {}\n\n", scene) + gates.markdown();
    for (const auto* i : list)
      if (i->kind == "convergence" && !i->orders.empty()) m += ladder_tables(*i);
  }
  // Definitions, once per norm name.
  std::map<std::string, std::string> defs;
  for (const auto& i : items)
    for (const auto& c : i.comparisons)
      for (const auto& n : c.norms) defs.emplace(n.name, n.definition);
  if (!defs.empty()) {
    m += "\n## Norm definitions (a = run, b = reference)\n\n";
    m += "Both histories are resampled by linear interpolation onto a uniform grid at the finer output step "
         "over their common time span; integrals use the trapezoid rule. Window W = 10 coarser output steps; "
         "contact samples closer than 3.5 coarser output steps form one interval.\n\n";
    for (const auto& [n, d] : defs) m += "- `" + n + "`: " + md_escape(d) + "\n";
  }
  m += "\n## Why each tolerance\n\n";
  std::set<std::string> seen;
  for (const auto& i : items)
    for (const auto& g : i.gates)
      if (seen.insert(i.name + g.gate.metric).second)
        m += fmt::format("- {} / `{}` ({}): {}\n", i.name, g.gate.metric, g.limit(), g.gate.why);
  write_file_atomic(file, m);
}

}  // namespace beamimpact::verification
