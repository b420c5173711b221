#include <verification/study/distributed_jobs.hpp>

#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <verification/matrix/interruption.hpp>
#include <verification/study/task_farm.hpp>

namespace beamimpact::study {

using verification::JobOutcome;

std::optional<std::map<std::string, JobOutcome>> distributed_jobs(
    const std::vector<verification::JobSpec>& specs, const std::filesystem::path& out_dir,
    const verification::Launcher& launcher, int jobs, double timeout_seconds) {
  if (World::size() == 1) return verification::execute_jobs(specs, out_dir, launcher, jobs, timeout_seconds);
  const std::vector<verification::JobSpec> order = verification::schedule_order(specs);
  std::vector<double> cost(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) cost[i] = static_cast<double>(order.size() - i);
  std::map<std::string, JobOutcome> out;
  std::size_t done = 0;
  const bool root = farm(
      cost,
      [&](std::size_t i) {
        const auto& s = order[i];
        const std::string why =
            verification::interruption() ? "not started: interrupted" : launcher.unavailable(s);
        return verification::outcome_json(
                   verification::execute_job(s, out_dir / s.key(), launcher, why, timeout_seconds))
            .dump();
      },
      [&](std::size_t i, const std::string& payload, int rank) {
        // The run stays on disk: evaluate reads it (stored_run).
        JobOutcome o = verification::outcome_from_json(order[i], out_dir / order[i].key(),
                                                       nlohmann::json::parse(payload));
        std::string line = verification::progress_line(++done, order.size(), o);
        line.insert(line.size() - 1, fmt::format(" rank {}", rank));
        fmt::print(stderr, "{}", line);
        std::fflush(stderr);
        out.emplace(o.spec.key(), std::move(o));
      },
      [&](std::size_t i) { return "run " + order[i].label(); });
  if (!root) return std::nullopt;
  return out;
}

}  // namespace beamimpact::study
