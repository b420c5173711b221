#include "command_protocol.hpp"

#include "option_checks.hpp"

#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include <api/methods_file.hpp>
#include <verification/jobs/interruption.hpp>
#include <verification/matrix/conform.hpp>
#include <verification/matrix/score.hpp>

#include "CommandExit.hpp"
#include "command_verification.hpp"
#include "methods_option.hpp"
#include "output_lock.hpp"
#include "page.hpp"

namespace beamimpact {
namespace {

namespace fs = std::filesystem;
using namespace verification;

/// Prints a conformance check rule by rule, with each broken check's scene, file and message.
void print_conform(const ConformResult& r) {
  fmt::print("conform {} ({}):\n", r.method, r.origin);
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
}

void conform_command(ConformOptions o) {
  o.validate();  // before the output folder is locked (created)
  o.out = o.out_dir();
  const OutputLock lock = lock_output(o.out);
  const ConformResult r = conform(o);
  print_conform(r);
  const std::vector<fs::path> written = write_conform_reports(o, r);
  fmt::print("junit: {}\nresults: {}\n", written[0].string(), written[1].string());
  print_page("conform", o.out);  // the verdict is conform.json's: the page never changes the exit code
  fmt::print("conform {}: {} check(s), {} broken rule(s), {} scene(s) not applicable\n",
             r.passed() ? "passed" : "FAILED", r.checks(), r.broken(), r.not_applicable());
  if (!r.passed()) throw CommandExit{1};
}

/// Prints a scored method's rows.
void print_score(const std::vector<ScoreRow>& rows) {
  const auto g3 = [](const std::optional<double>& v) { return v ? fmt::format("{:.3g}", *v) : "-"; };
  for (const ScoreRow& r : rows) {
    fmt::print("{:<26} {:<14} {:>8.3f} s  vs {}{}\n", r.item->run.scene_name(), to_string(r.outcome.status),
               r.outcome.solver_seconds, r.item->reference.settings_label(),
               r.item->ladder.kind.empty() ? "" : "; ladder " + r.item->ladder.kind);
    for (const ScoreQuantity& q : r.quantities) {
      const std::string order =
          q.ladder && q.ladder->order ? fmt::format(" order {:.2g}", *q.ladder->order) : "";
      fmt::print("    {:<16} {:<11} error {:<10} +- {:<10} tol {:<8} {}{}\n", q.metric, q.judged, g3(q.error),
                 g3(q.uncertainty), g3(q.tol), describe(q.status), order);
    }
  }
}

/// Prints the ratchet of one method against the baseline scorecard.
void print_ratchet(const Ratchet& r, const fs::path& baseline) {
  for (const std::string& g : r.improved) fmt::print("  improved: {}\n", g);
  for (const std::string& g : r.grown) fmt::print("  GROWN:    {}\n", g);
  fmt::print("ratchet against {}: {} ({} grown beyond their uncertainty, {} improved)\n", baseline.string(),
             r.grown.empty() ? "passed" : "FAILED", r.grown.size(), r.improved.size());
}

/// Scores one method or several (verification::score); exit 0 when every scorecard passed and no
/// error grew since --baseline, 1 otherwise, 2 for bad input, 128 + the signal on interruption.
void score_command(ScoreOptions o) {
  o.validate();  // before the output folder is locked (created)
  o.out = o.out_dir();
  const OutputLock lock = lock_output(o.out);
  jobs::forward_interruptions();
  const std::optional<ScoreResult> ran = score(o);
  if (!ran) return;  // an MPI worker rank: rank 0 judges and writes the scorecards
  const ScoreResult& r = *ran;
  const std::vector<fs::path> written = write_score_reports(o, r);
  for (std::size_t i = 0; i < r.methods.size(); ++i) {
    const MethodScore& m = r.methods[i];
    print_score(m.rows);
    fmt::print("scorecard: {}\n", written[i].string());
    print_page("scorecard", m.dir);  // the verdict is scorecard.json's: the page never changes the exit code
    fmt::print("reference cache: {}\n{}\n", r.cache.string(), m.verdict.line);
    if (m.ratchet) print_ratchet(*m.ratchet, o.baseline);
  }
  if (r.exit_code() != 0) throw CommandExit{r.exit_code()};
}

}  // namespace

void add_protocol_commands(CLI::App& app) {
  auto ca = std::make_shared<ConformOptions>();
  CLI::App* c = app.add_subcommand(
      "conform",
      "Check an external method against every rule of the protocol (docs/protocol.md); exit 1 if one "
      "is broken");
  c->add_option("NAME", ca->method, "The method (`beamimpact methods`)")->required();
  c->add_option("--out", ca->out,
                "Output directory (runs/, scenes/, junit.xml, conform.json, its page conform.html; default "
                "conform-NAME)");
  c->add_option("--timeout", ca->timeout, "s, per run")->capture_default_str()->check(positive_seconds());
  c->add_option("--scenes", ca->scenes,
                "The conformance scenes to run, comma-separated (default: all): end_to_end, transverse, "
                "node_to_surface, oblique_rotation, rigid_friction, two_contacts, friction; the malformed "
                "scene is always run")
      ->delimiter(',');
  add_methods_option(c);
  c->callback([ca] { conform_command(*ca); });

  auto sa = std::make_shared<ScoreOptions>();
  CLI::App* s = app.add_subcommand(
      "score",
      "Score a method on the benchmark set under each scene's benchmark card: scorecard.json, its "
      "page scorecard.html (reports/render.py, when python3 and Jinja2 are there) and a verdict (exit 0 "
      "passed, 1 failed or an error grew since --baseline, 2 bad input)");
  s->add_option("NAME", sa->methods,
                "The method (`beamimpact methods`), or several: their runs in one set of jobs, a reference "
                "they share run once, each scorecard in DIR/NAME")
      ->required();
  s->add_option(
      "--out", sa->out,
      "Output directory (runs/, scorecard.json, scorecard.html, or NAME/ for each of several methods; "
      "default score-NAME)");
  s->add_option("--cards", sa->cards,
                "The benchmark cards giving each scene's reference and tolerances (default "
                "verification/cards.toml; docs/benchmark-cards.md)");
  s->add_option("--jobs", sa->jobs, "Runs in parallel")->capture_default_str()->check(job_count());
  add_isolate_flag(s, sa->exe);
  s->add_option("--timeout", sa->timeout, "s per run (default 900)")->check(positive_seconds());
  s->add_option(
       "--sets", sa->sets,
       "Scene sets scored: paper (verification/scenes/paper), hard (verification/scenes/hard), exact "
       "(the other scenes with an exact answer)")
      ->delimiter(',')
      ->capture_default_str();
  s->add_option(
       "--scenes", sa->scenes,
       "Scenes scored, by name, comma-separated (default: every scene of the sets; `beamimpact scenes`)")
      ->delimiter(',');
  s->add_option("--references", sa->references,
                "IDA references: converged (rtol 1e-10, atol 1e-13, penalty 1e4 EA/le) or matrix (the card's "
                "settings: quicker, less strict; not for IDA itself)")
      ->capture_default_str();
  s->add_flag("--no-ladder{false}", sa->ladder,
              "One run a scene at its own resolution (no ladder on the scenes with an exact answer); the "
              "scorecard says so");
  s->add_option("--rungs", sa->rungs, "Runs of a ladder, 3 to 6 (resolution x2 a rung)")
      ->capture_default_str();
  s->add_option("--cache", sa->cache,
                "Folder of cached reference runs (default $BEAMIMPACT_REFERENCE_CACHE, else "
                "$XDG_CACHE_HOME/beamimpact/references, else ~/.cache/beamimpact/references)");
  s->add_option("--baseline", sa->baseline,
                "An earlier scorecard.json of the same method and sets: exit 1 when an error grew beyond its "
                "uncertainty since (the accuracy ratchet); improvements are listed");
  add_methods_option(s);
  s->callback([sa] { score_command(*sa); });
}

}  // namespace beamimpact
