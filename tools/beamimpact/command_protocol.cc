#include "command_protocol.hpp"

#include "option_checks.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <api/methods_file.hpp>
#include <api/registry.hpp>
#include <beamimpact/version.hpp>
#include <solver/util/InputError.hpp>
#include <verification/matrix/cards.hpp>
#include <verification/matrix/conform.hpp>
#include <verification/matrix/execute_jobs.hpp>
#include <verification/matrix/interruption.hpp>
#include <verification/matrix/reports.hpp>
#include <verification/matrix/scorecard.hpp>

#include "CommandExit.hpp"
#include "command_verification.hpp"
#include "methods_option.hpp"
#include "output_lock.hpp"
#include "page.hpp"

namespace beamimpact {
namespace {

namespace fs = std::filesystem;
using namespace verification;

struct ProtocolArgs {
  std::string method, out, cards, cache, baseline;
  std::vector<std::string> methods;  ///< score: one or more
  std::vector<std::string> scenes;   ///< conform: the conformance scenes to run (empty: all)
  int jobs = 1;
  double timeout = 600.0;
  std::optional<double> score_timeout;  ///< s per run; 900 when not given
  ScoreOptions score;
};

/// The data folder (verification/ scenes and matrix), or bad input when there is none.
fs::path data_folder(const std::string& command) {
  const fs::path root = data_root();
  if (root.empty())
    throw InputError("verification/methods.toml", "",
                     "not found from the program or the working directory upwards; `beamimpact " + command +
                         "` needs the shipped scenes (run it inside the repository or an installed tree)");
  return root;
}

const Method& runnable(const std::string& name, const std::string& command) {
  const Method& m = method(name, "--methods", command);
  if (const std::string why = unavailable(m); !why.empty())
    throw InputError(m.origin, "check", "the method cannot run here: " + why);
  return m;
}

void conform_command(const ProtocolArgs& a) {
  const Method& m = runnable(a.method, "conform");
  if (m.in_process())
    throw InputError(m.origin, "conform", "'" + m.name + "' is built in; conform checks an external program");
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
  fmt::print("junit: {}\nresults: {}\n", (out / "junit.xml").string(), (out / "conform.json").string());
  print_page("conform", out);  // the verdict is conform.json's: the page never changes the exit code
  fmt::print("conform {}: {} check(s), {} broken rule(s), {} scene(s) not applicable\n",
             r.passed() ? "passed" : "FAILED", r.checks(), r.broken(), r.not_applicable());
  if (!r.passed()) throw CommandExit{1};
}

/// Prints a scored method's rows.
void print_score(const std::vector<ScoreRow>& rows) {
  const auto g3 = [](const std::optional<double>& v) { return v ? fmt::format("{:.3g}", *v) : "-"; };
  for (const ScoreRow& r : rows) {
    fmt::print("{:<26} {:<14} {:>8.3f} s  vs {}{}\n", r.item->run.scene_name(), status_name(r.outcome.status),
               r.outcome.solver_seconds, r.item->reference.settings_label(),
               r.item->ladder.kind.empty() ? "" : "; ladder " + r.item->ladder.kind);
    for (const ScoreQuantity& q : r.quantities) {
      const std::string order =
          q.ladder && q.ladder->order ? fmt::format(" order {:.2g}", *q.ladder->order) : "";
      fmt::print("    {:<16} {:<11} error {:<10} +- {:<10} tol {:<8} {}{}\n", q.metric, q.judged, g3(q.error),
                 g3(q.uncertainty), g3(q.tol), q.status, order);
    }
  }
}

/// The folder of cached references: --cache, else $BEAMIMPACT_REFERENCE_CACHE, else
/// $XDG_CACHE_HOME/beamimpact/references, else ~/.cache/beamimpact/references.
fs::path reference_cache(const std::string& option) {
  if (!option.empty()) return fs::absolute(option);
  if (const char* e = std::getenv("BEAMIMPACT_REFERENCE_CACHE"); e && *e) return fs::absolute(e);
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "beamimpact/references";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache/beamimpact/references";
  return fs::absolute(".beamimpact-cache/references");
}

/// Prints the ratchet against a baseline scorecard; returns 1 when an error grew, else 0.
int print_ratchet(const std::string& baseline, const std::string& method, const ScoreOptions& o,
                  const std::vector<ScoreRow>& rows) {
  const Ratchet r = ratchet(baseline, method, o, rows);
  for (const std::string& g : r.improved) fmt::print("  improved: {}\n", g);
  for (const std::string& g : r.grown) fmt::print("  GROWN:    {}\n", g);
  fmt::print("ratchet against {}: {} ({} grown beyond their uncertainty, {} improved)\n", baseline,
             r.grown.empty() ? "passed" : "FAILED", r.grown.size(), r.improved.size());
  return r.grown.empty() ? 0 : 1;
}

/// Every distinct run the items need from `pick`, in order.
template <class F>
std::vector<JobSpec> distinct(const std::vector<std::vector<ScoreItem>>& items, F pick) {
  std::vector<JobSpec> specs;
  std::set<std::string> seen;
  for (const auto& list : items)
    for (const ScoreItem& it : list)
      for (const JobSpec& s : pick(it))
        if (seen.insert(s.key()).second) specs.push_back(s);
  return specs;
}

/// Phase 2: the references (and their checks) of the items whose every run finished, in the
/// cache (a reference recorded there with the same input is taken, not run again).
void run_references(const std::vector<std::vector<ScoreItem>>& items, std::map<std::string, JobOutcome>& runs,
                    const fs::path& cache, int jobs, double timeout) {
  const auto ok = [&](const JobSpec& s) {
    const auto it = runs.find(s.key());
    return it != runs.end() && it->second.status == JobOutcome::Status::kOk;
  };
  const std::vector<JobSpec> refs = distinct(items, [&](const ScoreItem& it) {
    std::vector<JobSpec> out;
    const bool finished = ok(it.run) && std::all_of(it.ladder.rungs.begin(), it.ladder.rungs.end(), ok);
    if (finished) out.push_back(it.reference);
    if (finished && it.reference_check) out.push_back(*it.reference_check);
    return out;
  });
  fmt::print(stderr,
             "score: phase 2 of 2: {} reference run(s) of the scenes the method(s) ran, cached in {}\n",
             refs.size(), cache.string());
  Launcher cached = launcher();
  cached.reuse_finished = true;
  for (auto& [key, o] : execute_jobs(refs, cache, cached, jobs, timeout))
    runs.insert_or_assign(key, std::move(o));
}

/// Scores one method or several: phase 1 the methods' runs (ladders included) under DIR/runs,
/// phase 2 the references of the scenes they ran, in the reference cache; one method's
/// scorecard in DIR, several methods' in DIR/NAME. Exit 0 when every scorecard passed and no
/// error grew since --baseline, 1 otherwise, 2 for bad input, 130 on interruption.
void score_command(const ProtocolArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<const Method*> ms;
  for (const std::string& name : a.methods) {
    ms.push_back(&runnable(name, "score"));
    a.score.validate(*ms.back());
    if (std::count(a.methods.begin(), a.methods.end(), name) > 1)
      throw InputError("command line", "NAME", "'" + name + "' is named twice");
  }
  if (a.score_timeout && !(*a.score_timeout > 0.0))
    throw InputError("command line", "--timeout",
                     fmt::format("expected seconds > 0, got {}", *a.score_timeout));
  if (!a.baseline.empty() && ms.size() != 1)
    throw InputError("command line", "--baseline", "expected one method with a baseline scorecard");
  const fs::path root = data_folder("score");
  const std::vector<BenchmarkCard> cards =
      load_cards(a.cards.empty() ? root / "verification/cards.toml" : fs::path(a.cards), root);
  std::vector<std::vector<ScoreItem>> items;
  for (const Method* m : ms) items.push_back(score_items(cards, *m, a.score));
  const std::vector<JobSpec> own = distinct(items, [](const ScoreItem& it) {
    return it.ladder.rungs.empty() ? std::vector<JobSpec>{it.run} : it.ladder.rungs;
  });
  const std::string names = fmt::format("{}", fmt::join(a.methods, " "));
  const fs::path out =
      a.out.empty() ? fs::path("score-" + fmt::format("{}", fmt::join(a.methods, "-"))) : fs::path(a.out);
  const fs::path cache = reference_cache(a.cache);
  const OutputLock lock = lock_output(out);
  forward_interruptions();
  fmt::print(stderr, "score {}: {} scene(s) of {}; {}; phase 1 of 2: {} run(s) of the method(s), {} job(s)\n",
             names, items.front().size(), fmt::join(a.score.sets, ", "),
             a.score.ladder
                 ? fmt::format("a ladder of {} rungs on each scene with an exact answer", a.score.rungs)
                 : std::string("single resolution (--no-ladder)"),
             own.size(), a.jobs);
  const double timeout = a.score_timeout.value_or(900.0);
  std::map<std::string, JobOutcome> runs = execute_jobs(own, out / "runs", launcher(), a.jobs, timeout);
  if (!interruption()) run_references(items, runs, cache, a.jobs, timeout);
  const std::string command =
      fmt::format("beamimpact score {} --out {} --jobs {} --sets {}{} --references {} --timeout {}{}", names,
                  out.string(), a.jobs, fmt::join(a.score.sets, ","),
                  a.score.scenes.empty() ? "" : fmt::format(" --scenes {}", fmt::join(a.score.scenes, ",")),
                  a.score.references, timeout,
                  a.score.ladder ? fmt::format(" --rungs {}", a.score.rungs) : std::string(" --no-ladder"));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int exit_code = 0;
  for (std::size_t i = 0; i < ms.size(); ++i) {
    const std::vector<ScoreRow> rows = score_rows(items[i], runs);
    const ScoreVerdict v = score_verdict(ms[i]->name, rows);
    const fs::path dir = ms.size() == 1 ? out : out / ms[i]->name;
    write_scorecard(
        dir,
        ScoreContext{ms[i]->name, ms[i]->origin, command, kVersion, utc_now(), wall, a.score, cache.string()},
        rows, v);
    print_score(rows);
    fmt::print("scorecard: {}\n", (dir / "scorecard.json").string());
    print_page("scorecard", dir);  // the verdict is scorecard.json's: the page never changes the exit code
    fmt::print("reference cache: {}\n{}\n", cache.string(), v.line);
    exit_code = std::max(exit_code, v.exit_code);
    if (!a.baseline.empty())
      exit_code = std::max(exit_code, print_ratchet(a.baseline, ms[i]->name, a.score, rows));
  }
  if (interruption()) throw CommandExit{interrupted_exit_code()};
  if (exit_code != 0) throw CommandExit{exit_code};
}

}  // namespace

void add_protocol_commands(CLI::App& app) {
  auto ca = std::make_shared<ProtocolArgs>();
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

  auto sa = std::make_shared<ProtocolArgs>();
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
  s->add_option("--timeout", sa->score_timeout, "s per run (default 900)")->check(positive_seconds());
  s->add_option(
       "--sets", sa->score.sets,
       "Scene sets scored: paper (verification/scenes/paper), hard (verification/scenes/hard), exact "
       "(the other scenes with an exact answer)")
      ->delimiter(',')
      ->capture_default_str();
  s->add_option(
       "--scenes", sa->score.scenes,
       "Scenes scored, by name, comma-separated (default: every scene of the sets; `beamimpact scenes`)")
      ->delimiter(',');
  s->add_option("--references", sa->score.references,
                "IDA references: converged (rtol 1e-10, atol 1e-13, penalty 1e4 EA/le) or matrix (the card's "
                "settings: quicker, less strict; not for IDA itself)")
      ->capture_default_str();
  s->add_flag("--no-ladder{false}", sa->score.ladder,
              "One run a scene at its own resolution (no ladder on the scenes with an exact answer); the "
              "scorecard says so");
  s->add_option("--rungs", sa->score.rungs, "Runs of a ladder, 3 to 6 (resolution x2 a rung)")
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
