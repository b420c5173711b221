#include <verification/matrix/score.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <api/methods_file.hpp>
#include <beamimpact/version.hpp>
#include <solver/util/InputError.hpp>
#include <verification/jobs/execute_jobs.hpp>
#include <verification/jobs/interruption.hpp>
#include <verification/jobs/task_farm.hpp>
#include <verification/matrix/cards.hpp>
#include <verification/matrix/protocol_inputs.hpp>
#include <verification/matrix/reports.hpp>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;
using Items = std::vector<ScoreItem>;

/// Every distinct run the methods' items need from `pick`, in order.
template <class F>
std::vector<jobs::JobSpec> distinct(const std::vector<MethodScore>& scores, F pick) {
  std::vector<jobs::JobSpec> specs;
  std::set<std::string> seen;
  for (const MethodScore& s : scores)
    for (const ScoreItem& it : *s.items)
      for (const jobs::JobSpec& spec : pick(it))
        if (seen.insert(spec.key()).second) specs.push_back(spec);
  return specs;
}

/// Phase 2: the references (and their checks) of the items whose every run finished, in the
/// cache (a reference recorded there with the same input is taken, not run again). `runs` is
/// rank 0's (nullopt on the other ranks of an MPI job, which learn the list from rank 0).
void run_references(const std::vector<MethodScore>& scores,
                    std::optional<std::map<std::string, jobs::JobOutcome>>& runs, const fs::path& cache,
                    jobs::Launcher launcher, const ScoreOptions& o) {
  const auto ok = [&](const jobs::JobSpec& s) {
    const auto it = runs->find(s.key());
    return it != runs->end() && it->second.status == jobs::JobOutcome::Status::kOk;
  };
  std::string wanted;  // the keys of the references to run, one per line
  if (runs)
    for (const MethodScore& m : scores)
      for (const ScoreItem& it : *m.items)
        if (ok(it.run) && std::all_of(it.ladder.rungs.begin(), it.ladder.rungs.end(), ok)) {
          wanted += it.reference.key() + "\n";
          if (it.reference_check) wanted += it.reference_check->key() + "\n";
        }
  std::set<std::string> keys;
  std::istringstream lines(jobs::World::broadcast(wanted));
  for (std::string key; std::getline(lines, key);) keys.insert(key);
  const std::vector<jobs::JobSpec> refs = distinct(scores, [&](const ScoreItem& it) {
    std::vector<jobs::JobSpec> out;
    for (const jobs::JobSpec* s : {&it.reference, it.reference_check ? &*it.reference_check : nullptr})
      if (s && keys.count(s->key())) out.push_back(*s);
    return out;
  });
  if (runs)
    fmt::print(stderr,
               "score: phase 2 of 2: {} reference run(s) of the scenes the method(s) ran, cached in {}{}\n",
               refs.size(), cache.string(), jobs::executor_note());
  launcher.reuse_finished = true;
  auto ran = jobs::execute_jobs(refs, cache, launcher, o.jobs, o.timeout);
  if (ran && runs)
    for (auto& [key, outcome] : *ran) runs->insert_or_assign(key, std::move(outcome));
}

/// Phase 1: the methods' own runs (every ladder rung, else the one run) under out/runs; nullopt
/// on the ranks of an MPI job other than 0.
std::optional<std::map<std::string, jobs::JobOutcome>> run_methods(const std::vector<MethodScore>& scores,
                                                                   const jobs::Launcher& launcher,
                                                                   const ScoreOptions& o) {
  const std::vector<jobs::JobSpec> own = distinct(scores, [](const ScoreItem& it) {
    return it.ladder.rungs.empty() ? std::vector<jobs::JobSpec>{it.run} : it.ladder.rungs;
  });
  if (jobs::World::rank() == 0)
    fmt::print(stderr,
               "score {}: {} scene(s) of {}; {}; phase 1 of 2: {} run(s) of the method(s), {} job(s){}\n",
               fmt::join(o.methods, " "), scores.front().items->size(), fmt::join(o.sets, ", "),
               o.ladder ? fmt::format("a ladder of {} rungs on each scene with an exact answer", o.rungs)
                        : std::string("single resolution (--no-ladder)"),
               own.size(), o.jobs, jobs::executor_note());
  return jobs::execute_jobs(own, o.out_dir() / "runs", launcher, o.jobs, o.timeout);
}

/// The command line that makes this score again (written into every scorecard).
std::string command_line(const ScoreOptions& o) {
  return fmt::format("beamimpact score {} --out {} --jobs {} --sets {}{} --references {} --timeout {}{}",
                     fmt::join(o.methods, " "), o.out_dir().string(), o.jobs, fmt::join(o.sets, ","),
                     o.scenes.empty() ? "" : fmt::format(" --scenes {}", fmt::join(o.scenes, ",")),
                     o.references, o.timeout,
                     o.ladder ? fmt::format(" --rungs {}", o.rungs) : std::string(" --no-ladder"));
}

/// Each method with its items (the cards' scenes for it) and the folder of its scorecard.
std::vector<MethodScore> plan(const ScoreOptions& o) {
  const fs::path root = shipped_data("score");
  const std::vector<BenchmarkCard> cards =
      load_cards(o.cards.empty() ? root / "verification/cards.toml" : o.cards, root);
  std::vector<MethodScore> scores;
  for (const std::string& name : o.methods) {
    const Method& m = runnable_method(name, "score");
    const fs::path dir = o.methods.size() == 1 ? o.out_dir() : o.out_dir() / m.name;
    scores.push_back(MethodScore{m.name,
                                 m.origin,
                                 dir,
                                 std::make_shared<const Items>(score_items(cards, m, o)),
                                 {},
                                 {},
                                 std::nullopt});
  }
  // A baseline of another method, other sets or the other ladder setting is refused before any run.
  if (!o.baseline.empty()) ratchet(o.baseline, scores.front().method, o, {});
  return scores;
}

}  // namespace

void ScoreOptions::validate() const {
  if (methods.empty()) throw InputError("command line", "NAME", "expected one or more methods to score");
  for (const std::string& name : methods) {
    validate(runnable_method(name, "score"));
    if (std::count(methods.begin(), methods.end(), name) > 1)
      throw InputError("command line", "NAME", "'" + name + "' is named twice");
  }
  if (!(timeout > 0.0) || !std::isfinite(timeout))
    throw InputError("command line", "--timeout", fmt::format("expected seconds > 0, got {}", timeout));
  if (jobs < 1)
    throw InputError("command line", "--jobs", fmt::format("expected 1 or more jobs, got {}", jobs));
  if (!baseline.empty() && methods.size() != 1)
    throw InputError("command line", "--baseline", "expected one method with a baseline scorecard");
}

fs::path ScoreOptions::out_dir() const {
  return out.empty() ? fs::path(fmt::format("score-{}", fmt::join(methods, "-"))) : out;
}

fs::path ScoreOptions::cache_dir() const {
  if (!cache.empty()) return fs::absolute(cache);
  if (const char* e = std::getenv("BEAMIMPACT_REFERENCE_CACHE"); e && *e) return fs::absolute(e);
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "beamimpact/references";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache/beamimpact/references";
  return fs::absolute(".beamimpact-cache/references");
}

int MethodScore::exit_code() const {
  return std::max(verdict.exit_code, ratchet && !ratchet->grown.empty() ? 1 : 0);
}

int ScoreResult::exit_code() const {
  if (interrupted) return 128 + interrupted;
  int code = 0;
  for (const MethodScore& m : methods) code = std::max(code, m.exit_code());
  return code;
}

std::optional<ScoreResult> score(const ScoreOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  o.validate();
  ScoreResult r;
  r.methods = plan(o);
  r.cache = o.cache_dir();
  const jobs::Launcher launcher = jobs::launcher_for(o.exe, 0);
  std::optional<std::map<std::string, jobs::JobOutcome>> ran = run_methods(r.methods, launcher, o);
  // Every rank takes the same turn: an interruption reaches every rank of the job.
  if (!jobs::interruption()) run_references(r.methods, ran, r.cache, launcher, o);
  if (!ran) return std::nullopt;  // an MPI worker rank: rank 0 judges
  std::map<std::string, jobs::JobOutcome>& runs = *ran;
  r.command = command_line(o);
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (MethodScore& m : r.methods) {
    m.rows = score_rows(*m.items, runs);
    m.verdict = score_verdict(m.method, m.rows);
    if (!o.baseline.empty()) m.ratchet = ratchet(o.baseline, m.method, o, m.rows);
  }
  r.interrupted = jobs::interruption();
  r.made = utc_now();
  return r;
}

ScoreContext score_context(const ScoreOptions& o, const ScoreResult& r, const MethodScore& m) {
  return ScoreContext{m.method, m.origin, r.command, kVersion, r.made, r.wall_seconds, o, r.cache.string()};
}

std::vector<fs::path> write_score_reports(const ScoreOptions& o, const ScoreResult& r) {
  std::vector<fs::path> written;
  for (const MethodScore& m : r.methods) {
    write_scorecard(m.dir, score_context(o, r, m), m.rows, m.verdict);
    written.push_back(m.dir / "scorecard.json");
  }
  return written;
}

}  // namespace beamimpact::verification
