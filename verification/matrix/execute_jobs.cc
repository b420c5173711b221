#include <verification/matrix/execute_jobs.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <mutex>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <api/child_process.hpp>
#include <api/external_method.hpp>
#include <api/registry.hpp>
#include <solver/util/InputError.hpp>
#include <verification/matrix/finished_runs.hpp>
#include <verification/matrix/interruption.hpp>

namespace beamimpact::verification {

namespace {

/// execute_job without the record.
JobOutcome run_job(const JobSpec& spec, const std::filesystem::path& dir, const Launcher& launcher,
                   double timeout) {
  JobOutcome o{spec, dir, JobOutcome::Status::kFailed, {}, 0.0, 0.0, 0, 0.0, nullptr};
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);                    // never mistake an old result for this run's
  if (std::filesystem::create_directories(dir, ec); ec) {  // in a worker thread: never throw
    o.message = fmt::format("cannot create {}: {}", dir.string(), ec.message());
    return o;
  }
  std::vector<std::string> argv;
  try {
    argv = launcher.argv(spec, dir);
  } catch (const std::exception& e) {
    o.message = e.what();
    return o;
  }
  {
    std::ofstream log(dir / "run.log");
    for (const auto& a : argv) log << a << ' ';
    log << '\n';
  }
  const ProcessResult p = spawn_and_wait(argv, dir / "run.log", timeout, interruption);
  o.process_seconds = p.wall_seconds;
  if (p.error.empty() && p.exit_code == 2) {  // refused: "error: <file>: <why>" is its last line
    o.status = JobOutcome::Status::kNotApplicable;
    o.message = last_line(dir / "run.log");
    if (o.message.rfind("error: ", 0) == 0) o.message.erase(0, 7);
    return o;
  }
  if (!p.error.empty() || p.exit_code != 0) {
    o.message = !p.error.empty()
                    ? p.error
                    : fmt::format("exit code {} (see {})", p.exit_code, (dir / "run.log").string());
    return o;
  }
  if (!std::filesystem::exists(dir / "summary.json", ec)) {
    o.message = "exit code 0 but no summary.json (see " + (dir / "run.log").string() + ")";
    return o;
  }
  try {  // read once: evaluate compares this run in memory
    o.run = std::make_shared<const StoredRun>(StoredRun::read(dir));
    const nlohmann::json& j = o.run->summary();
    o.solver_seconds = j.value("wall_seconds", 0.0);
    o.steps = j.value("steps", 0L);
    o.dt = j.value("dt", 0.0);
  } catch (const std::exception& e) {
    o.message = std::string("unreadable run: ") + e.what();
    o.run.reset();
    return o;
  }
  o.status = JobOutcome::Status::kOk;
  return o;
}

}  // namespace

JobOutcome execute_job(const JobSpec& spec, const std::filesystem::path& dir, const Launcher& launcher,
                       const std::string& why, double timeout) {
  if (!why.empty())
    return JobOutcome{spec, dir, JobOutcome::Status::kSkipped, why, 0.0, 0.0, 0, 0.0, nullptr};
  if (launcher.reuse_finished)
    if (auto earlier = recorded_run(spec, dir)) return *earlier;
  const nlohmann::json input = run_input(spec);  // what the run is made from, before it starts
  JobOutcome o = run_job(spec, dir, launcher, timeout);
  record_run(o, input);
  return o;
}

nlohmann::json outcome_json(const JobOutcome& o) {
  return {{"status", to_string(o.status)},
          {"message", o.message},
          {"process_seconds", o.process_seconds},
          {"solver_seconds", o.solver_seconds},
          {"steps", o.steps},
          {"dt", o.dt},
          {"resumed", o.resumed}};
}

JobOutcome outcome_from_json(const JobSpec& spec, const std::filesystem::path& dir, const nlohmann::json& j) {
  const nlohmann::json& word = j.at("status");
  const JobOutcome::Status status =
      word.is_string() ? parse_run_status(word.get<std::string>(), dir.string(), "status")
                       : parse_run_status(to_string(static_cast<JobOutcome::Status>(word.get<int>())),
                                          dir.string(), "status");
  JobOutcome o{spec,
               dir,
               status,
               j.at("message").get<std::string>(),
               j.at("process_seconds").get<double>(),
               j.at("solver_seconds").get<double>(),
               j.at("steps").get<long>(),
               j.at("dt").get<double>(),
               nullptr};
  o.resumed = j.value("resumed", false);
  return o;
}

std::shared_ptr<const StoredRun> stored_run(const JobOutcome& o) {
  return o.run ? o.run : std::make_shared<const StoredRun>(StoredRun::read(o.dir));
}

std::vector<JobSpec> schedule_order(const std::vector<JobSpec>& specs) {
  std::vector<JobSpec> order = specs;
  auto slow = [](const JobSpec& s) {
    const Method* m = find_method(s.method);
    return m && m->slow;
  };
  std::stable_sort(order.begin(), order.end(), [&](const JobSpec& a, const JobSpec& b) {
    const bool fa = slow(a), fb = slow(b);
    if (fa != fb) return fa;
    return a.dt.value_or(1e300) < b.dt.value_or(1e300);
  });
  return order;
}

std::string progress_line(std::size_t done, std::size_t total, const JobOutcome& o) {
  return fmt::format("[{}/{}] {}: {}{} ({:.2f} s{})\n", done, total, o.spec.label(), to_string(o.status),
                     o.message.empty() ? "" : ": " + o.message, o.process_seconds,
                     o.resumed ? ", finished earlier" : "");
}

const char* to_string(JobOutcome::Status s) {
  switch (s) {
    case JobOutcome::Status::kOk: return "ok";
    case JobOutcome::Status::kFailed: return "failed";
    case JobOutcome::Status::kSkipped: return "skipped";
    case JobOutcome::Status::kNotApplicable: return "not applicable";
  }
  return "?";
}

JobOutcome::Status parse_run_status(std::string_view text, const std::string& file, const std::string& key) {
  for (auto s : {JobOutcome::Status::kOk, JobOutcome::Status::kFailed, JobOutcome::Status::kSkipped,
                 JobOutcome::Status::kNotApplicable})
    if (text == to_string(s)) return s;
  throw InputError(
      file, key,
      fmt::format("expected a run status ('ok', 'failed', 'skipped', 'not applicable'), got '{}'", text));
}

std::map<std::string, JobOutcome> execute_jobs(const std::vector<JobSpec>& specs,
                                               const std::filesystem::path& out_dir, const Launcher& launcher,
                                               int jobs, double timeout_seconds) {
  const std::vector<JobSpec> order = schedule_order(specs);
  // Availability is checked up front, in this thread (an external method's check runs once).
  std::vector<std::string> why;
  for (const auto& s : order) why.push_back(launcher.unavailable(s));
  std::map<std::string, JobOutcome> out;
  std::mutex mu;
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  const auto start = std::chrono::steady_clock::now();
  auto worker = [&] {
    for (std::size_t i = next++; i < order.size(); i = next++) {
      const std::string skip = interruption() ? "not started: interrupted" : why[i];
      JobOutcome o = execute_job(order[i], out_dir / order[i].key(), launcher, skip, timeout_seconds);
      std::lock_guard lock(mu);
      std::string line = progress_line(++done, order.size(), o);
      if (done < order.size()) {  // the time left if the rest take as long as these did on average
        const double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        line.insert(line.size() - 1,
                    fmt::format("; about {:.0f} s left", spent / static_cast<double>(done) *
                                                             static_cast<double>(order.size() - done)));
      }
      fmt::print(stderr, "{}", line);
      std::fflush(stderr);
      out.emplace(o.spec.key(), std::move(o));
    }
  };
  std::vector<std::thread> pool;
  const int n = std::max(1, std::min<int>(jobs, static_cast<int>(order.size())));
  for (int i = 0; i < n; ++i) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  return out;
}

}  // namespace beamimpact::verification
