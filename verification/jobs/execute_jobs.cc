#include <verification/jobs/execute_jobs.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <api/registry.hpp>
#include <solver/util/Progress.hpp>
#include <verification/jobs/finished_runs.hpp>
#include <verification/jobs/interruption.hpp>
#include <verification/jobs/run_job.hpp>
#include <verification/jobs/task_farm.hpp>

namespace beamimpact::jobs {

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

namespace {

/// Prints each finished run's progress line with the time left if the rest take as long as
/// these did on average (and the rank that ran it, under MPI).
class ProgressLines {
 public:
  explicit ProgressLines(std::size_t total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  void print(const JobOutcome& o, int rank) {
    std::string line = progress_line(++done_, total_, o);
    if (rank >= 0) line.insert(line.size() - 1, fmt::format(" rank {}", rank));
    if (done_ < total_) {
      const double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      line.insert(line.size() - 1,
                  fmt::format("; about {:.0f} s left",
                              spent / static_cast<double>(done_) * static_cast<double>(total_ - done_)));
    }
    fmt::print(stderr, "{}", line);
    std::fflush(stderr);
  }

 private:
  std::size_t total_, done_ = 0;
  std::chrono::steady_clock::time_point start_;
};

/// One rank: `jobs` worker threads take the runs in order.
std::map<std::string, JobOutcome> on_threads(const std::vector<JobSpec>& order,
                                             const std::vector<std::string>& why,
                                             const std::filesystem::path& out_dir, const Launcher& launcher,
                                             int jobs, double timeout) {
  std::map<std::string, JobOutcome> out;
  std::mutex mu;
  std::atomic<std::size_t> next{0};
  ProgressLines lines(order.size());
  auto worker = [&] {
    for (std::size_t i = next++; i < order.size(); i = next++) {
      const std::string skip = interruption() ? "not started: interrupted" : why[i];
      JobOutcome o = execute_job(order[i], out_dir / order[i].key(), launcher, skip, timeout);
      std::lock_guard lock(mu);
      lines.print(o, -1);
      out.emplace(o.spec.key(), std::move(o));
    }
  };
  std::vector<std::thread> pool;
  const int n = std::max(1, std::min<int>(jobs, static_cast<int>(order.size())));
  for (int i = 0; i < n; ++i) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  return out;
}

/// N ranks: the task farm hands the runs out in order; outcomes travel as JSON (the runs stay
/// on disk, where stored_run() reads them).
std::optional<std::map<std::string, JobOutcome>> on_ranks(const std::vector<JobSpec>& order,
                                                          const std::vector<std::string>& why,
                                                          const std::filesystem::path& out_dir,
                                                          const Launcher& launcher, double timeout) {
  std::vector<double> cost(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) cost[i] = static_cast<double>(order.size() - i);
  std::map<std::string, JobOutcome> out;
  ProgressLines lines(order.size());
  const bool root = farm(
      cost,
      [&](std::size_t i) {
        const std::string skip = interruption() ? "not started: interrupted" : why[i];
        return outcome_json(execute_job(order[i], out_dir / order[i].key(), launcher, skip, timeout)).dump();
      },
      [&](std::size_t i, const std::string& payload, int rank) {
        JobOutcome o = outcome_from_json(order[i], out_dir / order[i].key(), nlohmann::json::parse(payload));
        lines.print(o, rank);
        out.emplace(o.spec.key(), std::move(o));
      },
      [&](std::size_t i) { return "run " + order[i].label(); });
  if (!root) return std::nullopt;
  return out;
}

}  // namespace

std::optional<std::map<std::string, JobOutcome>> execute_jobs(const std::vector<JobSpec>& specs,
                                                              const std::filesystem::path& out_dir,
                                                              const Launcher& launcher, int jobs,
                                                              double timeout_seconds) {
  const std::vector<JobSpec> order = schedule_order(specs);
  // Availability is checked up front, in this thread (an external method's check runs once).
  std::vector<std::string> why;
  for (const auto& s : order) why.push_back(launcher.unavailable(s));
  // Runs in this process would print progress lines over each other and over the set's own.
  std::optional<Progress::Silence> quiet;
  if (!launcher.isolated()) quiet.emplace();
  if (World::size() > 1) return on_ranks(order, why, out_dir, launcher, timeout_seconds);
  return on_threads(order, why, out_dir, launcher, jobs, timeout_seconds);
}

std::string executor_note() { return World::size() > 1 ? fmt::format(", {} MPI ranks", World::size()) : ""; }

}  // namespace beamimpact::jobs
