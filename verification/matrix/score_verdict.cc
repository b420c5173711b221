// The overall verdict of a scorecard and the accuracy ratchet against an earlier one
// (scorecard.hpp).
#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include <solver/util/InputError.hpp>
#include <verification/matrix/scorecard.hpp>

namespace beamimpact::verification {

ScoreVerdict score_verdict(const std::string& name, const std::vector<ScoreRow>& rows) {
  ScoreVerdict v;
  int quantities = 0, ok = 0;
  for (const ScoreRow& r : rows)
    for (const ScoreQuantity& q : r.quantities) {
      ++v.counts[q.status];
      ++quantities;
      ok += passes(q.status);
    }
  v.exit_code = ok == quantities ? 0 : 1;
  std::string tally;
  for (const auto& [status, n] : v.counts)
    tally += fmt::format("{}{} {}", tally.empty() ? "" : ", ", n, describe(status));
  if (v.exit_code == 0)
    v.line = fmt::format("score {}: PASSED (every one of {} quantities: {})", name, quantities, tally);
  else
    v.line = fmt::format("score {}: FAILED ({} of {} quantities neither pass nor not applicable: {})", name,
                         quantities - ok, quantities, tally);
  return v;
}

namespace {

namespace fs = std::filesystem;

nlohmann::json read_baseline(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), "", "expected a readable scorecard.json");
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object() || !j.contains("scenes") || !j["scenes"].is_array() || !j.contains("method"))
    throw InputError(file.string(), "", "expected a scorecard.json written by `beamimpact score`");
  return j;
}

/// The baseline's scene -> metric -> {error, uncertainty}.
std::map<std::string, std::map<std::string, std::pair<double, double>>> baseline_errors(
    const nlohmann::json& j) {
  std::map<std::string, std::map<std::string, std::pair<double, double>>> out;
  for (const auto& s : j["scenes"])
    for (const auto& q : s.value("quantities", nlohmann::json::array()))
      if (q.contains("error") && q["error"].is_number())
        out[s.value("scene", "")][q.value("metric", "")] = {
            q["error"].get<double>(),
            q.contains("uncertainty") && q["uncertainty"].is_number() ? q["uncertainty"].get<double>() : 0.0};
  return out;
}

}  // namespace

Ratchet ratchet(const fs::path& file, const std::string& method, const ScoreOptions& options,
                const std::vector<ScoreRow>& rows) {
  const nlohmann::json j = read_baseline(file);
  const std::string f = file.string();
  if (j.value("method", "") != method)
    throw InputError(f, "method",
                     "expected a scorecard of '" + method + "', got '" + j.value("method", "") + "'");
  if (!j.contains("sets") || j["sets"] != nlohmann::json(options.sets))
    throw InputError(f, "sets",
                     fmt::format("expected the sets {}, got {}", nlohmann::json(options.sets).dump(),
                                 j.value("sets", nlohmann::json()).dump()));
  if (j.value("ladder", !options.ladder) != options.ladder)
    throw InputError(f, "ladder",
                     options.ladder ? "expected a scorecard with ladders (made without --no-ladder)"
                                    : "expected a scorecard made with --no-ladder");
  const auto before = baseline_errors(j);
  Ratchet r;
  for (const ScoreRow& row : rows) {
    const auto s = before.find(row.item->run.scene_name());
    if (s == before.end()) continue;
    for (const ScoreQuantity& q : row.quantities) {
      const auto m = s->second.find(q.metric);
      if (m == s->second.end() || !q.error) continue;
      const auto [e0, u0] = m->second;
      const double u = std::max(u0, q.uncertainty.value_or(0.0)), e1 = *q.error;
      const double slack = tolerance_slack(0.0, std::max(e0, e1), 0.0);
      const std::string what =
          fmt::format("{} {}: {:.4g} -> {:.4g} (uncertainty {:.3g})", s->first, q.metric, e0, e1, u);
      if (e1 > e0 + u + slack) r.grown.push_back(what);
      if (e1 < e0 - u - slack) r.improved.push_back(what);
    }
  }
  return r;
}

}  // namespace beamimpact::verification
