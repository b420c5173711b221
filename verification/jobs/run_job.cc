#include <verification/jobs/run_job.hpp>

#include <chrono>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <api/child_process.hpp>
#include <api/run.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/RunLimit.hpp>
#include <verification/jobs/interruption.hpp>

namespace beamimpact::jobs {
namespace {

using Status = JobOutcome::Status;

/// The refusal an isolated run wrote (kRefusalFile); nullopt when there is none or it is unreadable.
std::optional<Refusal> read_refusal(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    return Refusal{j.at("file").get<std::string>(), j.at("key").get<std::string>(),
                   j.at("message").get<std::string>()};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

void refuse(JobOutcome& o, Refusal r) {
  o.status = Status::kNotApplicable;
  o.message = r.message;
  o.refusal = std::move(r);
}

/// The run through beamimpact::run in this thread, limited by timeout and interruption().
void run_in_process(JobOutcome& o, const Launcher& launcher, double timeout) {
  std::ofstream log(o.dir / "run.log");
  log << fmt::format("in process: beamimpact::run({}, {}) with {}\n", o.spec.scene.string(), o.spec.method,
                     o.spec.settings_label());
  const auto start = std::chrono::steady_clock::now();
  try {
    const RunLimit limit(timeout, interruption);
    (void)beamimpact::run(o.spec.scene, o.spec.method, launcher.run_options(o.spec, o.dir));
    o.status = Status::kOk;
  } catch (const InputError& e) {
    refuse(o, Refusal{e.file(), e.key(), e.what()});
  } catch (const std::exception& e) {
    o.message = e.what();
  } catch (...) {
    o.message = "the run threw something that is no std::exception";
  }
  o.process_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (o.status != Status::kOk) log << "error: " << o.message << '\n';
}

/// The run as a `beamimpact run` process of launcher.exe, killed after timeout.
void run_isolated(JobOutcome& o, const Launcher& launcher, double timeout) {
  const std::vector<std::string> argv = launcher.argv(o.spec, o.dir);
  {
    std::ofstream log(o.dir / "run.log");
    for (const auto& a : argv) log << a << ' ';
    log << '\n';
  }
  const ProcessResult p = spawn_and_wait(argv, o.dir / "run.log", timeout, interruption);
  o.process_seconds = p.wall_seconds;
  if (!p.error.empty() || p.exit_code != 0) {
    if (p.error.empty() && p.exit_code == 2)
      if (auto r = read_refusal(o.dir / kRefusalFile)) return refuse(o, std::move(*r));
    o.message = !p.error.empty()
                    ? p.error
                    : fmt::format("exit code {} (see {})", p.exit_code, (o.dir / "run.log").string());
    return;
  }
  o.status = Status::kOk;
}

/// Reads the run an ok outcome left (once: evaluate compares it in memory); a missing or
/// unreadable run turns the outcome into a failure.
void read_finished(JobOutcome& o) {
  std::error_code ec;
  if (!std::filesystem::exists(o.dir / "summary.json", ec)) {
    o.status = Status::kFailed;
    o.message = "finished without error but left no summary.json (see " + (o.dir / "run.log").string() + ")";
    return;
  }
  try {
    o.run = std::make_shared<const verification::StoredRun>(verification::StoredRun::read(o.dir));
    const nlohmann::json& j = o.run->summary();
    o.solver_seconds = j.value("wall_seconds", 0.0);
    o.steps = j.value("steps", 0L);
    o.dt = j.value("dt", 0.0);
  } catch (const std::exception& e) {
    o.status = Status::kFailed;
    o.message = std::string("unreadable run: ") + e.what();
    o.run.reset();
  }
}

}  // namespace

JobOutcome run_job(const JobSpec& spec, const std::filesystem::path& dir, const Launcher& launcher,
                   double timeout) {
  JobOutcome o{spec, dir, Status::kFailed, {}, 0.0, 0.0, 0, 0.0, nullptr};
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);                    // never mistake an old result for this run's
  if (std::filesystem::create_directories(dir, ec); ec) {  // in a worker thread: never throw
    o.message = fmt::format("cannot create {}: {}", dir.string(), ec.message());
    return o;
  }
  try {
    if (launcher.isolated())
      run_isolated(o, launcher, timeout);
    else
      run_in_process(o, launcher, timeout);
  } catch (const std::exception& e) {  // the launcher's own checks (a method not in the registry)
    o.status = Status::kFailed;
    o.message = e.what();
  }
  if (o.status == Status::kOk) read_finished(o);
  return o;
}

}  // namespace beamimpact::jobs
