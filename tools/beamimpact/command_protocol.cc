#include "command_protocol.hpp"

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
  const std::vector<RuleResult> results = conform(m, data_folder("conform"), out, a.timeout);
  int failed = 0;
  fmt::print("conform {} ({}):\n", m.name, m.origin);
  for (const auto& [rule, says] : protocol_rules()) {
    int n = 0, bad = 0;
    for (const RuleResult& r : results)
      if (r.rule == rule) {
        ++n;
        bad += !r.passed;
      }
    fmt::print("  [{}] {:<25} {} ({} check(s))\n", n == 0 ? "  " : bad ? "FAIL" : " ok ", rule, says, n);
    for (const RuleResult& r : results)
      if (r.rule == rule && !r.passed) fmt::print("         {}: {}: {}\n", r.scene, r.file, r.message);
    failed += bad;
  }
  write_conform_junit(out / "junit.xml", m.name, results);
  fmt::print("conform {}: {} check(s), {} broken rule(s)\njunit: {}\n", failed ? "FAILED" : "passed",
             results.size(), failed, (out / "junit.xml").string());
  if (failed) throw CommandExit{1};
}

void score_command(const ProtocolArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  const Method& m = runnable(a.method, "score");
  a.score.validate(m.name);
  if (a.score_timeout && !(*a.score_timeout > 0.0))
    throw InputError("command line", "--timeout",
                     fmt::format("expected seconds > 0, got {}", *a.score_timeout));
  const fs::path root = data_folder("score");
  const VerificationMatrix matrix =
      VerificationMatrix::load(a.matrix.empty() ? root / "verification/matrix.toml" : fs::path(a.matrix));
  const std::vector<ScoreItem> items = score_items(matrix, m.name, root, a.score);
  std::vector<JobSpec> specs;
  std::set<std::string> seen;
  for (const ScoreItem& it : items)
    for (const JobSpec* s : {&it.run, &it.reference})
      if (seen.insert(s->key()).second) specs.push_back(*s);
  const fs::path out = a.out.empty() ? fs::path("score-" + m.name) : fs::path(a.out);
  const OutputLock lock = lock_output(out);
  forward_interruptions();
  fmt::print(stderr, "score {}: {} scene(s) of {}, {} run(s), {} job(s); reference where no exact: {}\n",
             m.name, items.size(), fmt::join(a.score.sets, ", "), specs.size(), a.jobs,
             ida_reference(a.score));
  const auto runs =
      execute_jobs(specs, out / "runs", launcher(), a.jobs, a.score_timeout.value_or(matrix.timeout));
  const std::vector<ScoreRow> rows = score_rows(items, runs);
  ScoreContext ctx{
      m.name,
      m.origin,
      fmt::format("beamimpact score {} --out {} --jobs {} --sets {} --references {} --timeout {}", m.name,
                  out.string(), a.jobs, fmt::join(a.score.sets, ","), a.score.references,
                  a.score_timeout.value_or(matrix.timeout)),
      kVersion,
      utc_now(),
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
      a.score};
  write_scorecard(out, ctx, rows);
  std::map<std::string, int> counts;
  for (const ScoreRow& r : rows) {
    fmt::print("{:<26} {:<14} {:>8.3f} s  vs {}\n", r.item->run.scene_name(), status_name(r.outcome.status),
               r.outcome.solver_seconds, r.item->reference.settings_label());
    for (const ScoreQuantity& q : r.quantities) {
      ++counts[q.status];
      fmt::print("    {:<16} error {:<10} tol {:<8} {}\n", q.metric,
                 q.error ? fmt::format("{:.3g}", *q.error) : "-", q.tol ? fmt::format("{:g}", *q.tol) : "-",
                 q.status);
    }
  }
  std::string tally;
  for (const auto& [status, n] : counts)
    tally += fmt::format("{}{} {}", tally.empty() ? "" : ", ", n, status);
  fmt::print("score {}: {}\nscorecard: {} {}\n", m.name, tally, (out / "scorecard.json").string(),
             (out / "scorecard.html").string());
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
  add_methods_option(c);
  c->callback([ca] { conform_command(*ca); });

  auto sa = std::make_shared<ProtocolArgs>();
  CLI::App* s = app.add_subcommand(
      "score",
      "Score a method on the benchmark set against the best reference of each scene: scorecard.json and "
      "scorecard.html");
  s->add_option("NAME", sa->method, "The method (`beamimpact methods`)")->required();
  s->add_option("--out", sa->out,
                "Output directory (runs/, scorecard.json, scorecard.html; default score-NAME)");
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
