#include <api/external_method.hpp>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <api/child_process.hpp>
#include <api/methods_file.hpp>
#include <api/output_rules.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/Progress.hpp>
#include <solver/util/RunLimit.hpp>
#include <solver/util/write_file_atomic.hpp>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

/// The scalar summary keys and each contact's impulse and intervals: what `beamimpact run`
/// prints and the study records; the comparisons read the run directory.
SimulationResult read_back(const Method& m, const fs::path& summary) {
  std::ifstream in(summary);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw std::runtime_error("method '" + m.name + "' wrote an unreadable " + summary.string() + ": " +
                             e.what());
  }
  SimulationResult r;
  r.method = m.name;
  auto number = [&](const char* key) {
    return j.contains(key) && j[key].is_number() ? j[key].get<double>() : 0.0;
  };
  r.dt = number("dt");
  r.critical_dt = number("critical_dt");
  r.steps = static_cast<long>(number("steps"));
  r.wall_seconds = number("wall_seconds");
  r.energy_initial = number("energy_initial");
  r.energy_final = number("energy_final");
  if (j.contains("effects") && j["effects"].is_array())
    for (const auto& e : j["effects"])
      if (e.is_string()) r.effects.push_back(e.get<std::string>());
  if (j.contains("contacts") && j["contacts"].is_array())
    for (const auto& c : j["contacts"]) {
      ContactSummary s;
      s.striker = c.value("striker", "");
      s.target = c.value("target", "");
      s.impulse_normal = c.value("impulse_normal", 0.0);
      if (c.contains("intervals") && c["intervals"].is_array())
        for (const auto& iv : c["intervals"])
          if (iv.is_array() && iv.size() == 2 && iv[0].is_number() && iv[1].is_number())
            s.intervals.push_back({iv[0].get<double>(), iv[1].get<double>()});
      r.contacts.push_back(std::move(s));
    }
  return r;
}

std::string number_text(double v) { return fmt::format("{:.17g}", v); }

}  // namespace

std::vector<std::string> external_argv(const Method& m, const ExternalRun& run) {
  const std::map<std::string, std::string> values = {{"scene", run.scene.string()},
                                                     {"out", run.out.string()},
                                                     {"dt", run.dt},
                                                     {"mesh", run.mesh},
                                                     {"end", run.end}};
  std::vector<std::string> argv;
  for (std::string a : m.command) {
    const bool had_placeholder = a.find('{') != std::string::npos;
    if (expand_placeholders(a, values)) {
      argv.push_back(a);
    } else if (had_placeholder && !argv.empty() && argv.back().rfind('-', 0) == 0 &&
               argv.size() > 1) {  // "--dt {dt}" with no dt: both left out
      argv.pop_back();
    }
  }
  return argv;
}

std::string last_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return last;
}

SimulationResult run_external(const Method& m, const Scene& scene, const fs::path& out,
                              const std::string& mesh) {
  std::error_code ec;
  if (!fs::is_regular_file(scene.file, ec))
    throw InputError(scene.file, "", "expected a scene file: the external method '" + m.name + "' reads one");
  fs::create_directories(out);
  ExternalRun run{scene.file, out, "", mesh, number_text(scene.time.end)};
  if (scene.time.dt) run.dt = number_text(*scene.time.dt);
  if (!scene.overrides.empty()) {  // the program reads the scene as this run sees it
    run.scene = out / "scene.toml";
    write_file_atomic(run.scene, scene_toml(scene));
  }
  const fs::path log = out / "method.log";
  fs::remove(log, ec);
  // The program gets what is left of this thread's RunLimit (none: no limit) and its interruption.
  const double budget = std::min(RunLimit::seconds_left(), 1e9);
  const ProcessResult p = spawn_and_wait(external_argv(m, run), log, budget, RunLimit::interruption());
  if (p.timed_out || (RunLimit::interruption() && RunLimit::interruption()())) RunLimit::check();
  const bool ok = p.error.empty() && p.exit_code == 0;
  if (!ok || Progress::enabled()) {  // quiet on success, as an in-process run
    std::ifstream text(log);
    std::cerr << text.rdbuf();
  }
  const std::string said = last_line(log);
  if (ok) {
    // Exit 0 vouches for nothing by itself: the outputs keep every rule, or the run failed and
    // its summary is moved aside (a broken result must never look complete).
    const std::string broken = first_broken_rule(
        check_outputs(out, OutputExpectation{run.scene, scene.contacts.size(), scene.time.end}));
    if (!broken.empty()) {
      if (fs::exists(out / "summary.json", ec)) fs::rename(out / "summary.json", out / kRejectedSummary, ec);
      throw std::runtime_error("method '" + m.name + "' exited 0 but its outputs break the protocol's " +
                               broken +
                               (fs::exists(out / kRejectedSummary, ec)
                                    ? " (summary.json moved to " + std::string(kRejectedSummary) + ")"
                                    : ""));
    }
    return read_back(m, out / "summary.json");
  }
  fs::remove(out / "summary.json", ec);  // a failed run's summary vouches for nothing
  if (p.error.empty() && p.exit_code == 2)
    throw InputError(scene.file, "", "not applicable: method '" + m.name + "' refused the scene: " + said);
  throw std::runtime_error("method '" + m.name + "' failed (" +
                           (p.error.empty() ? "exit code " + std::to_string(p.exit_code) : p.error) +
                           "): " + said);
}

}  // namespace beamimpact
