#include <verification/jobs/JobOutcome.hpp>

#include <fmt/format.h>

#include <solver/util/InputError.hpp>

namespace beamimpact::jobs {

nlohmann::json outcome_json(const JobOutcome& o) {
  nlohmann::json j = {{"status", to_string(o.status)},
                      {"message", o.message},
                      {"process_seconds", o.process_seconds},
                      {"solver_seconds", o.solver_seconds},
                      {"steps", o.steps},
                      {"dt", o.dt},
                      {"resumed", o.resumed}};
  if (o.refusal)
    j["refusal"] = {{"file", o.refusal->file}, {"key", o.refusal->key}, {"message", o.refusal->message}};
  return j;
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
  if (const auto r = j.find("refusal"); r != j.end())
    o.refusal = Refusal{r->at("file").get<std::string>(), r->at("key").get<std::string>(),
                        r->at("message").get<std::string>()};
  return o;
}

std::shared_ptr<const verification::StoredRun> stored_run(const JobOutcome& o) {
  return o.run ? o.run
               : std::make_shared<const verification::StoredRun>(verification::StoredRun::read(o.dir));
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

}  // namespace beamimpact::jobs
