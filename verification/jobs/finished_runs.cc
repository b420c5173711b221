#include <verification/jobs/finished_runs.hpp>

#include <cstdio>
#include <fstream>

#include <fmt/format.h>

#include <api/methods_file.hpp>
#include <api/registry.hpp>
#include <beamimpact/version.hpp>
#include <solver/util/sha256.hpp>
#include <solver/util/write_file_atomic.hpp>
#include <verification/jobs/program_id.hpp>

namespace beamimpact::jobs {

namespace fs = std::filesystem;

nlohmann::json program_input() {
  nlohmann::json files = nlohmann::json::array();
  for (const auto& f : loaded_methods_files())
    files.push_back({{"file", f.string()}, {"sha256", file_sha256(f)}});
  return {{"version", kVersion}, {"program_sha256", program_sha256()}, {"methods_files", files}};
}

void write_record(const fs::path& file, const nlohmann::json& input, const nlohmann::json& result) {
  write_file_atomic(file, nlohmann::json{{"input", input}, {"result", result}}.dump(1) + "\n");
}

std::optional<nlohmann::json> read_record(const fs::path& file, const nlohmann::json& input) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object() || !j.contains("input") || !j.contains("result") || j["input"] != input)
    return std::nullopt;
  return j["result"];
}

nlohmann::json run_input(const JobSpec& spec) {
  nlohmann::json program = program_input();
  // A built-in method's run depends on no methods file: its record (and `score`'s reference
  // cache) holds whichever files a command loaded.
  if (const Method* m = find_method(spec.method); m && m->in_process()) program.erase("methods_files");
  return {{"program", program},
          {"scene", spec.scene.string()},
          {"scene_sha256", file_sha256(spec.scene)},
          {"method", spec.method},
          {"dt", spec.dt ? nlohmann::json(*spec.dt) : nlohmann::json(nullptr)},
          {"mesh", spec.mesh},
          {"set", spec.set}};
}

void record_run(const JobOutcome& o, const nlohmann::json& input) {
  if (o.status != JobOutcome::Status::kOk && o.status != JobOutcome::Status::kNotApplicable) return;
  try {
    write_record(o.dir / kRunRecord, input, outcome_json(o));
  } catch (const std::exception& e) {
    fmt::print(stderr, "warning: {}: a restart will do this run again\n", e.what());
  }
}

std::optional<JobOutcome> recorded_run(const JobSpec& spec, const fs::path& dir) {
  const auto result = read_record(dir / kRunRecord, run_input(spec));
  if (!result) return std::nullopt;
  try {
    JobOutcome o = outcome_from_json(spec, dir, *result);
    std::error_code ec;
    if (o.status == JobOutcome::Status::kOk &&
        !(fs::exists(dir / "summary.json", ec) && fs::exists(dir / "history.csv", ec)))
      return std::nullopt;  // a run that was removed since: run it again
    o.resumed = true;
    return o;
  } catch (const std::exception&) {  // not a record this version writes: run it again
    return std::nullopt;
  }
}

std::size_t count_recorded(const std::vector<JobSpec>& specs, const fs::path& runs_dir) {
  std::size_t n = 0;
  for (const auto& s : specs) n += recorded_run(s, runs_dir / s.key()).has_value();
  return n;
}

}  // namespace beamimpact::jobs
