#include <verification/study/run_point.hpp>

#include <chrono>

#include <fmt/format.h>

#include <api/registry.hpp>
#include <api/run.hpp>
#include <solver/scene/run_cost.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/InputError.hpp>
#include <verification/compare/compare_runs.hpp>
#include <verification/compare/run_checks.hpp>

namespace beamimpact::study {
namespace {

namespace fs = std::filesystem;
using verification::RunView;

/// Runs one method; the run in memory when it finished, else status and message set. The run
/// directory is written only when the study keeps its runs (or the scene asks for fields).
std::optional<RunView> run_one(const Study& s, const std::vector<std::string>& set, const std::string& method,
                               const fs::path& dir, CaseResult& c) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<RunView> out;
  try {
    const Scene scene = load_scene(s.scene, set);
    RunOptions options;
    if (s.keep_runs || scene.output.fields) options.out = dir;
    const SimulationResult r = beamimpact::run(scene, method, options);
    c.steps = r.steps;
    c.dt = r.dt;
    out = RunView::from_result(scene, r, dir.string());
    c.status = "ok";
  } catch (const InputError& e) {
    c.status = "error";
    c.message = e.what();
  } catch (const std::exception& e) {
    c.status = "diverged";
    c.message = e.what();
  }
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::optional<double> opt(const nlohmann::json& j) {
  return j.is_null() ? std::nullopt : std::optional<double>(j.get<double>());
}

/// A case of `method` with one empty norm cell per Study::norms (every row has them all).
CaseResult blank_case(const Study& s, const std::string& method) {
  CaseResult c;
  c.method = method;
  c.norms.assign(s.norms.size(), std::nullopt);
  return c;
}

}  // namespace

PointResult run_point(const Study& s, const Point& p, std::size_t index, const fs::path& runs_dir) {
  PointResult pr;
  std::vector<std::string> set;
  try {
    set = overrides(s, p);
  } catch (const std::exception& e) {
    pr.reference_message = e.what();
    for (const auto& m : s.methods) {
      CaseResult c = blank_case(s, m);
      c.message = e.what();
      pr.cases.push_back(std::move(c));
    }
    return pr;
  }
  std::vector<std::string> ref_set = set;
  ref_set.insert(ref_set.end(), s.reference.set.begin(), s.reference.set.end());
  const fs::path ref_dir = runs_dir / fmt::format("{}.reference", index);
  CaseResult ref;
  const std::optional<RunView> reference = run_one(s, ref_set, s.reference.method, ref_dir, ref);
  pr.reference_status = ref.status;
  pr.reference_message = ref.message;
  pr.reference_seconds = ref.seconds;
  for (const auto& m : s.methods) {
    CaseResult c = blank_case(s, m);
    const fs::path dir = runs_dir / fmt::format("{}.{}", index, m);
    const std::optional<RunView> run = run_one(s, set, m, dir, c);
    if (run) {
      const verification::Comparison health = verification::check_run(*run);
      if (const auto* g = health.find("energy_growth")) c.energy_growth = g->value;
      if (c.energy_growth && *c.energy_growth > s.energy_growth) {
        c.status = "energy";
        c.message =
            fmt::format("energy created {:.3g} of E0 > bound {:g}", *c.energy_growth, s.energy_growth);
      }
      if (reference) {
        try {
          const verification::Comparison cmp = verification::compare_runs(*run, *reference);
          for (std::size_t k = 0; k < s.norms.size(); ++k)
            if (const auto* n = cmp.find(s.norms[k])) c.norms[k] = n->value;
        } catch (const std::exception& e) {
          c.message += (c.message.empty() ? "" : "; ") + std::string("comparison failed: ") + e.what();
        }
      } else if (c.status == "ok") {
        c.status = "no_reference";
        c.message = "reference " + ref.status + ": " + ref.message;
      }
    }
    if (!s.keep_runs) fs::remove_all(dir);  // fields, when the scene asked for them
    pr.cases.push_back(std::move(c));
  }
  if (!s.keep_runs) fs::remove_all(ref_dir);
  return pr;
}

double point_cost(const Study& s, const Point& p) {
  auto cost = [&](const std::vector<std::string>& set) {  // the run-cost check's estimate
    const Scene sc = load_scene(s.scene, set);
    return estimate_run_cost(sc, planned_dt(sc)).work;
  };
  try {
    std::vector<std::string> set = overrides(s, p);
    double c = static_cast<double>(s.methods.size()) * cost(set);
    set.insert(set.end(), s.reference.set.begin(), s.reference.set.end());
    return c + cost(set);
  } catch (const std::exception&) {
    return 0.0;
  }
}

nlohmann::json PointResult::to_json() const {
  nlohmann::json cs = nlohmann::json::array();
  for (const auto& c : cases) {
    nlohmann::json n = nlohmann::json::array();
    for (const auto& v : c.norms) n.push_back(json_or_null(v));
    cs.push_back({{"method", c.method},
                  {"status", c.status},
                  {"message", c.message},
                  {"steps", c.steps},
                  {"dt", c.dt},
                  {"norms", n},
                  {"energy_growth", json_or_null(c.energy_growth)},
                  {"seconds", c.seconds}});
  }
  return {{"reference_status", reference_status},
          {"reference_message", reference_message},
          {"reference_seconds", reference_seconds},
          {"cases", cs}};
}

PointResult PointResult::from_json(const nlohmann::json& j) {
  PointResult p;
  p.reference_status = j.at("reference_status").get<std::string>();
  p.reference_message = j.at("reference_message").get<std::string>();
  p.reference_seconds = j.at("reference_seconds").get<double>();
  for (const auto& c : j.at("cases")) {
    CaseResult r;
    r.method = c.at("method").get<std::string>();
    r.status = c.at("status").get<std::string>();
    r.message = c.at("message").get<std::string>();
    r.steps = c.at("steps").get<long>();
    r.dt = c.at("dt").get<double>();
    for (const auto& v : c.at("norms")) r.norms.push_back(opt(v));
    r.energy_growth = opt(c.at("energy_growth"));
    r.seconds = c.at("seconds").get<double>();
    p.cases.push_back(std::move(r));
  }
  return p;
}

}  // namespace beamimpact::study
