#include <verification/matrix/reports.hpp>

#include <fstream>
#include <map>
#include <set>

#include <fmt/format.h>

namespace beamimpact::verification {
namespace {

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

struct Totals {
  int gates = 0, pass = 0, fail = 0, skipped = 0;
};

Totals totals(const std::vector<ItemResult>& items) {
  Totals t;
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

}  // namespace

void write_junit(const std::filesystem::path& file, const ReportContext& ctx,
                 const std::vector<ItemResult>& items) {
  const Totals all = totals(items);
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

void write_json(const std::filesystem::path& file, const ReportContext& ctx,
                const std::vector<ItemResult>& items) {
  const Totals t = totals(items);
  nlohmann::json j{
      {"command", ctx.command}, {"matrix", ctx.matrix},       {"tier", ctx.tier},
      {"version", ctx.version}, {"started_utc", ctx.started}, {"wall_seconds", ctx.wall_seconds},
      {"jobs", ctx.jobs},       {"gates", t.gates},           {"passed", t.pass},
      {"failed", t.fail},       {"skipped", t.skipped},       {"complete", ctx.incomplete.empty()}};
  if (!ctx.incomplete.empty()) j["incomplete"] = ctx.incomplete;
  auto& arr = j["items"] = nlohmann::json::array();
  for (const auto& i : items) arr.push_back(to_json(i));
  write_file_atomic(file, j.dump(1) + "\n");
}

void write_markdown(const std::filesystem::path& file, const ReportContext& ctx,
                    const std::vector<ItemResult>& items) {
  const Totals t = totals(items);
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
  m += fmt::format("\n**{}**: {} gates, {} passed, {} failed, {} skipped.\n\n", t.fail == 0 ? "PASS" : "FAIL",
                   t.gates, t.pass, t.fail, t.skipped);
  m += "Value: the error of the run against its reference (relative unless the unit says s or count; "
       "definitions at the end), or the observed order p = log(e_coarse/e_fine)/log(r) for convergence "
       "ladders. "
       "Wall: process time of the run under test (ladders: all rungs).\n";

  for (const auto& [scene, list] : by_scene(items)) {
    m += fmt::format(
        "\n## {}\n\n| run | reference | norm | value | limit | result | wall s "
        "|\n|---|---|---|---|---|---|---|\n",
        scene);
    for (const auto* i : list) {
      const std::string run =
          i->kind == "convergence" ? i->name.substr(scene.size() + 1) + " (self-convergence)" : i->settings;
      for (const auto& g : i->gates) {
        const std::string res = g.status == GateStatus::kPass   ? "pass"
                                : g.status == GateStatus::kFail ? "**FAIL**: " + g.message
                                                                : "skipped: " + g.message;
        m +=
            fmt::format("| {} | {} | {} | {} | {} | {} | {:.2f} |\n", md_escape(run), md_escape(i->reference),
                        g.gate.metric, value_text(g), g.limit(), md_escape(res), i->wall_seconds);
      }
    }
    for (const auto* i : list) {
      if (i->kind != "convergence" || i->orders.empty()) continue;
      m += fmt::format("\nObserved orders, {} ({}, then orders):\n\n", i->name,
                       i->reference.empty() ? "errors of consecutive pairs" : "errors of each rung against the reference");
      const std::size_t ne = i->orders.begin()->second.first.size();
      m += "| norm |";
      for (std::size_t k = 0; k < ne; ++k) m += fmt::format(" e{} |", k + 1);
      for (std::size_t k = 0; k + 1 < ne; ++k) m += fmt::format(" p{} |", k + 1);
      m += "\n|---|";
      for (std::size_t k = 0; k + 1 < 2 * ne; ++k) m += "---|";
      m += "\n";
      for (const auto& c : i->comparisons.front().norms) {
        const auto& [e, p] = i->orders.at(c.name);
        m += "| " + c.name + " |";
        for (const auto& v : e) m += v ? fmt::format(" {:.3e} |", *v) : std::string(" n/a |");
        for (const auto& v : p) m += v ? fmt::format(" {:.2f} |", *v) : std::string(" - |");
        m += "\n";
      }
      if (!i->richardson.empty()) {
        m += "\nRichardson limits of the last three rungs (their own observed order; the reference not used):\n\n"
             "| norm | order p | limit Q_R | reference | abs(Q_R - ref) / ref | E_R / ref |\n|---|---|---|---|---|---|\n";
        for (const auto& [name, x] : i->richardson)
          m += fmt::format("| {} | {:.2f} | {:.6g} | {:.6g} | {:.2e} | {:.2e} |\n", name, x.order, x.limit, x.reference,
                           x.error, x.estimate);
      }
    }
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
