#include "command_protocol.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <api/methods_file.hpp>
#include <api/registry.hpp>
#include <beamimpact/version.hpp>
#include <solver/scene/SceneError.hpp>
#include <solver/util/InputError.hpp>
#include <verification/matrix/conform.hpp>
#include <verification/matrix/execute_jobs.hpp>
#include <verification/matrix/interruption.hpp>
#include <verification/matrix/reports.hpp>
#include <verification/matrix/scorecard.hpp>

#include "CommandExit.hpp"
#include "command_verification.hpp"
#include "methods_option.hpp"
#include "output_lock.hpp"

namespace beamimpact {
namespace {

namespace fs = std::filesystem;
using namespace verification;

struct ProtocolArgs {
  std::string method, out, matrix;
  std::vector<std::string> methods;  ///< score: one or more
  std::vector<std::string> scenes;   ///< conform: the conformance scenes to run (empty: all)
  int jobs = 1;
  double timeout = 600.0;
  std::optional<double> score_timeout;  ///< s per run; the matrix's timeout when not given
  ScoreOptions score;
};

/// The data folder (verification/ scenes and matrix), or bad input when there is none.
fs::path data_folder(const std::string& command) {
  const fs::path root = data_root();
  if (root.empty())
    throw SceneError("verification/methods.toml", "",
                     "not found from the program or the working directory upwards; `beamimpact " + command +
                         "` needs the shipped scenes (run it inside the repository or an installed tree)");
  return root;
}

const Method& runnable(const std::string& name, const std::string& command) {
  const Method& m = method(name, "--methods", command);
  if (const std::string why = unavailable(m); !why.empty())
    throw SceneError(m.origin, "check", "the method cannot run here: " + why);
  return m;
}

void conform_command(const ProtocolArgs& a) {
  const Method& m = runnable(a.method, "conform");
  if (m.in_process())
    throw SceneError(m.origin, "conform", "'" + m.name + "' is built in; conform checks an external program");
  const fs::path out = a.out.empty() ? fs::path("conform-" + m.name) : fs::path(a.out);
  const OutputLock lock = lock_output(out);
  const ConformResult r{m.name, m.origin, conform(m, data_folder("conform"), out, a.timeout, a.scenes)};
  fmt::print("conform {} ({}):\n", m.name, m.origin);
  for (const RuleResult& x : r.results)
    if (x.skipped) fmt::print("  [n/a ] {:<25} refused (exit 2): {}\n", x.scene, x.message);
  for (const auto& [rule, says] : protocol_rules()) {
    int n = 0, bad = 0;
    for (const RuleResult& x : r.results)
      if (x.rule == rule && !x.skipped) {
        ++n;
        bad += !x.passed;
      }
    fmt::print("  [{}] {:<25} {} ({} check(s))\n", n == 0 ? "  " : bad ? "FAIL" : " ok ", rule, says, n);
    for (const RuleResult& x : r.results)
      if (x.rule == rule && !x.passed && !x.skipped)
        fmt::print("         {}: {}: {}\n", x.scene, x.file, x.message);
  }
  const std::string command =
      fmt::format("beamimpact conform {} --out {} --timeout {}", m.name, out.string(), a.timeout);
  write_conform_reports(out, r, command, a.timeout);
  fmt::print(
      "conform {}: {} check(s), {} broken rule(s), {} scene(s) not applicable\njunit: {}\nresults: {} "
      "(page: /usr/bin/python3 reports/render.py conform {})\n",
      r.passed() ? "passed" : "FAILED", r.checks(), r.broken(), r.not_applicable(),
      (out / "junit.xml").string(), (out / "conform.json").string(), out.string());
  if (!r.passed()) throw CommandExit{1};
}

/// Prints a scored method's rows and its tally; the tally is returned for the summary line.
std::string print_score(const std::vector<ScoreRow>& rows) {
  std::map<std::string, int> counts;
  for (const ScoreRow& r : rows) {
    fmt::print("{:<26} {:<14} {:>8.3f} s  vs {}\n", r.item->run.scene_name(), status_name(r.outcome.status),
               r.outcome.solver_seconds, r.item->reference.settings_label());
    for (const ScoreQuantity& q : r.quantities) {
      ++counts[q.status];
      const auto g3 = [](const std::optional<double>& v) { return v ? fmt::format("{:.3g}", *v) : "-"; };
      fmt::print("    {:<16} error {:<10} spread {:<10} tol {:<8} {}\n", q.metric, g3(q.error),
                 g3(q.reference_spread), g3(q.tol), q.status);
    }
  }
  std::string tally;
  for (const auto& [status, n] : counts)
    tally += fmt::format("{}{} {}", tally.empty() ? "" : ", ", n, status);
  return tally;
}

/// Scores one method or several: every run (a reference shared by several methods once) in one
/// set of jobs under DIR/runs; one method's scorecard in DIR, several methods' in DIR/NAME.
void score_command(const ProtocolArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<const Method*> ms;
  for (const std::string& name : a.methods) {
    ms.push_back(&runnable(name, "score"));
    a.score.validate(name);
    if (std::count(a.methods.begin(), a.methods.end(), name) > 1)
      throw InputError("command line", "NAME", "'" + name + "' is named twice");
  }
  if (a.score_timeout && !(*a.score_timeout > 0.0))
    throw InputError("command line", "--timeout",
                     fmt::format("expected seconds > 0, got {}", *a.score_timeout));
  const fs::path root = data_folder("score");
  const VerificationMatrix matrix =
      VerificationMatrix::load(a.matrix.empty() ? root / "verification/matrix.toml" : fs::path(a.matrix));
  std::vector<std::vector<ScoreItem>> items;
  std::vector<JobSpec> specs;
  std::set<std::string> seen;
  for (const Method* m : ms) {
    items.push_back(score_items(matrix, m->name, root, a.score));
    for (const ScoreItem& it : items.back())
      for (const JobSpec* s : {&it.run, &it.reference, it.reference_check ? &*it.reference_check : nullptr})
        if (s && seen.insert(s->key()).second) specs.push_back(*s);
  }
  const std::string names = fmt::format("{}", fmt::join(a.methods, " "));
  const fs::path out =
      a.out.empty() ? fs::path("score-" + fmt::format("{}", fmt::join(a.methods, "-"))) : fs::path(a.out);
  const OutputLock lock = lock_output(out);
  forward_interruptions();
  fmt::print(stderr, "score {}: {} scene(s) of {}, {} run(s), {} job(s); reference where no exact: {}\n",
             names, items.front().size(), fmt::join(a.score.sets, ", "), specs.size(), a.jobs,
             ida_reference(a.score));
  const double timeout = a.score_timeout.value_or(matrix.timeout);
  const auto runs = execute_jobs(specs, out / "runs", launcher(), a.jobs, timeout);
  const std::string command =
      fmt::format("beamimpact score {} --out {} --jobs {} --sets {} --references {} --timeout {}", names,
                  out.string(), a.jobs, fmt::join(a.score.sets, ","), a.score.references, timeout);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (std::size_t i = 0; i < ms.size(); ++i) {
    const std::vector<ScoreRow> rows = score_rows(items[i], runs);
    const fs::path dir = ms.size() == 1 ? out : out / ms[i]->name;
    write_scorecard(
        dir, ScoreContext{ms[i]->name, ms[i]->origin, command, kVersion, utc_now(), wall, a.score}, rows);
    const std::string tally = print_score(rows);
    fmt::print("score {}: {}\nscorecard: {} {}\n", ms[i]->name, tally, (dir / "scorecard.json").string(),
               (dir / "scorecard.html").string());
  }
  if (interruption()) throw CommandExit{interrupted_exit_code()};
}

}  // namespace

void add_protocol_commands(CLI::App& app) {
  auto ca = std::make_shared<ProtocolArgs>();
  CLI::App* c = app.add_subcommand(
      "conform",
      "Check an external method against every rule of the protocol (docs/protocol.md); exit 1 if one "
      "is broken");
  c->add_option("NAME", ca->method, "The method (`beamimpact methods`)")->required();
  c->add_option("--out", ca->out, "Output directory (runs/, scenes/, junit.xml; default conform-NAME)");
  c->add_option("--timeout", ca->timeout, "s, per run")->capture_default_str();
  c->add_option("--scenes", ca->scenes,
                "The conformance scenes to run, comma-separated (default: all): end_to_end, transverse, "
                "node_to_surface, oblique_rotation, rigid_friction, two_contacts, friction; the malformed "
                "scene is always run")
      ->delimiter(',');
  add_methods_option(c);
  c->callback([ca] { conform_command(*ca); });

  auto sa = std::make_shared<ProtocolArgs>();
  CLI::App* s = app.add_subcommand(
      "score",
      "Score a method on the benchmark set against the best reference of each scene: scorecard.json and "
      "scorecard.html");
  s->add_option("NAME", sa->methods,
                "The method (`beamimpact methods`), or several: their runs in one set of jobs, a reference "
                "they share run once, each scorecard in DIR/NAME")
      ->required();
  s->add_option(
      "--out", sa->out,
      "Output directory (runs/, scorecard.json, scorecard.html, or NAME/ for each of several methods; "
      "default score-NAME)");
  s->add_option("--matrix", sa->matrix,
                "The verification matrix giving references and tolerances "
                "(default verification/matrix.toml)");
  s->add_option("--jobs", sa->jobs, "Runs in parallel")->capture_default_str();
  s->add_option("--timeout", sa->score_timeout, "s per run (default: the matrix's timeout)");
  s->add_option(
       "--sets", sa->score.sets,
       "Scene sets scored: paper (verification/scenes/paper), hard (verification/scenes/hard), exact "
       "(the other scenes with an exact answer)")
      ->delimiter(',')
      ->capture_default_str();
  s->add_option("--references", sa->score.references,
                "IDA references: converged (rtol 1e-10, atol 1e-13, penalty 1e4 EA/le) or matrix (the matrix "
                "case's settings: quicker, less strict; not for IDA itself)")
      ->capture_default_str();
  add_methods_option(s);
  s->callback([sa] { score_command(*sa); });
}

}  // namespace beamimpact
