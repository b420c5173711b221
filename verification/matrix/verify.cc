#include <verification/matrix/verify.hpp>

#include <api/methods_file.hpp>

#include <chrono>
#include <set>

#include <fmt/format.h>

#include <beamimpact/version.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/write_file_atomic.hpp>
#include <verification/jobs/finished_runs.hpp>
#include <verification/jobs/interruption.hpp>
#include <verification/matrix/VerificationMatrix.hpp>

namespace beamimpact::verification {
namespace {

/// The items of the tier whose names contain `only`, and the runs they need.
struct Selection {
  std::vector<const Case*> cases;
  std::vector<const Convergence*> ladders;
  std::vector<const RunCheck*> checks;
  std::vector<jobs::JobSpec> specs;
};

Selection select(const VerificationMatrix& m, const VerifyOptions& o) {
  Selection s;
  auto selected = [&](const std::string& name) {
    return o.only.empty() || name.find(o.only) != std::string::npos;
  };
  for (const auto& c : m.cases)
    if (VerificationMatrix::in_tier(c.tier, o.tier) && selected(c.name())) s.cases.push_back(&c);
  for (const auto& v : m.convergence)
    if (VerificationMatrix::in_tier(v.tier, o.tier) && selected(v.name())) s.ladders.push_back(&v);
  for (const auto& c : m.checks)
    if (VerificationMatrix::in_tier(c.tier, o.tier) && selected(c.name())) s.checks.push_back(&c);
  if (o.only.empty()) {
    s.specs = m.runs(o.tier);
    return s;
  }
  std::set<std::string> seen;  // only the runs the selected items need
  auto add = [&](const jobs::JobSpec& spec) {
    if (seen.insert(spec.key()).second) s.specs.push_back(spec);
  };
  for (const auto* c : s.cases) {
    add(c->run);
    add(c->reference);
  }
  for (const auto* v : s.ladders) {
    for (const auto& spec : v->runs) add(spec);
    if (v->reference) add(*v->reference);
  }
  for (const auto* c : s.checks) add(c->run);
  return s;
}

}  // namespace

std::optional<VerifyResult> verify(const VerifyOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const std::string started = utc_now();
  // An earlier verdict must not survive this run's refusal or failure (report.html: the HTML report's).
  remove_stale_outputs(o.out, {"report.md", "junit.xml", "norms.json", "report.html"});
  if (o.jobs < 1)
    throw InputError(o.matrix.string(), "--jobs", "expected a positive number of parallel runs");
  std::error_code ec;
  const bool baseline_exists = !o.baseline.empty() && std::filesystem::exists(o.baseline, ec);
  if (!o.baseline.empty() && !baseline_exists && !o.update_baseline)
    throw InputError(o.baseline.string(), "--baseline", "no such file (write one with --update-baseline)");
  if (o.update_baseline && o.baseline.empty())
    throw InputError(o.matrix.string(), "--update-baseline", "expected --baseline FILE: the file to write");
  const nlohmann::json baseline = baseline_exists ? read_baseline(o.baseline) : nlohmann::json();
  const VerificationMatrix m = VerificationMatrix::load(o.matrix);
  const Selection s = select(m, o);
  if (s.cases.empty() && s.ladders.empty() && s.checks.empty())
    throw InputError(o.matrix.string(), o.only.empty() ? "--tier" : "--only",
                     "expected a selection with at least one case, ladder or check; tier '" + o.tier + "'" +
                         (o.only.empty() ? "" : " has no item whose name contains '" + o.only + "'") +
                         " (a verify of nothing would pass)");
  jobs::Launcher launcher = jobs::launcher_for(o.exe, o.threads);
  launcher.reuse_finished = !o.fresh;
  std::filesystem::create_directories(o.out);
  if (!o.quiet) {
    fmt::print(stderr,
               "verify: {} case(s), {} convergence ladder(s), {} check(s), {} run(s), tier {}, {} job(s){}\n",
               s.cases.size(), s.ladders.size(), s.checks.size(), s.specs.size(), o.tier, o.jobs,
               jobs::executor_note());
    if (const std::size_t n = o.fresh ? 0 : jobs::count_recorded(s.specs, o.out / "runs"))
      fmt::print(stderr, "resumed: {} of {} runs finished earlier (--fresh runs them all again)\n", n,
                 s.specs.size());
  }
  const auto ran = jobs::execute_jobs(s.specs, o.out / "runs", launcher, o.jobs, m.timeout);
  if (!ran) return std::nullopt;  // an MPI worker rank: rank 0 evaluates
  VerifyResult r;
  for (const auto* c : s.cases) r.items.push_back(evaluate_case(*c, *ran));
  for (const auto* v : s.ladders) r.items.push_back(evaluate_ladder(*v, *ran));
  for (const auto* c : s.checks) r.items.push_back(evaluate_check(*c, *ran));
  ReportContext& ctx = r.context;
  ctx.command = !o.command.empty()
                    ? o.command
                    : fmt::format("beamimpact verify {} --tier {} --out {} --jobs {}{}{}{}",
                                  o.matrix.string(), o.tier, o.out.string(), o.jobs,
                                  o.only.empty() ? "" : " --only '" + o.only + "'", o.fresh ? " --fresh" : "",
                                  o.threads > 0 ? fmt::format(" --threads {}", o.threads) : "");
  ctx.matrix = o.matrix.string();
  ctx.tier = o.tier;
  ctx.version = kVersion;
  ctx.started = started;
  ctx.jobs = o.jobs;
  ctx.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (jobs::interruption())
    ctx.incomplete = fmt::format("interrupted by signal {}; runs not finished are failed or skipped",
                                 jobs::interruption());
  r.baseline_file = o.baseline;
  r.update_baseline = o.update_baseline;
  if (baseline_exists) r.baseline = compare_baseline(baseline, o.baseline.string(), r.items);
  return r;
}

std::filesystem::path write_verify_reports(const VerifyOptions& o, const VerifyResult& r) {
  write_junit(o.out / "junit.xml", r.context, r.items);
  write_json(o.out / "norms.json", r.context, r.items);
  write_markdown(o.out / "report.md", r.context, r.items);
  if (!o.update_baseline || !r.gates_passed()) return {};
  write_file_atomic(o.baseline, baseline_json(kVersion, r.context.tier, r.items).dump(1) + "\n");
  return o.baseline;
}

}  // namespace beamimpact::verification
