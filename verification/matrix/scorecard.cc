#include <verification/matrix/scorecard.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <solver/util/InputError.hpp>
#include <verification/compare/compare_runs.hpp>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;

/// Whether `ref` sets `key` (as "key=value").
bool sets_key(const JobSpec& ref, const std::string& key) {
  return std::any_of(ref.set.begin(), ref.set.end(),
                     [&](const std::string& s) { return s.rfind(key + "=", 0) == 0; });
}

/// IDA converged beyond its defaults, keeping the reference's own settings: time tolerances 100
/// times tighter (rtol 1e-10, atol 1e-13), the friction regularisation at 1e-5 m/s (the matrix's
/// converged value; no effect on a frictionless contact) and, with `stiffen`, a penalty 10 times
/// stiffer (1e4 EA/le), so that IDA's step and penetration errors fall below the defaults' by
/// about those factors. Without `stiffen` it is the reference's check: the same run at the
/// card's penalty.
JobSpec converged_ida(JobSpec ref, bool stiffen) {
  const bool own_penalty = sets_key(ref, "ida.kn") || sets_key(ref, "ida.kn_factor");
  for (const auto& [key, value] : {std::pair{"ida.rtol", "1e-10"}, std::pair{"ida.atol", "1e-13"},
                                   std::pair{"ida.friction_velocity", "1e-5"}})
    if (!sets_key(ref, key)) ref.set.push_back(std::string(key) + "=" + value);
  if (stiffen && !own_penalty) ref.set.push_back("ida.kn_factor=1e4");
  return ref;
}

}  // namespace

std::string ida_reference(const ScoreOptions& o) {
  return o.references == "converged"
             ? "IDA converged beyond its defaults: rtol 1e-10, atol 1e-13, friction regularised at 1e-5 "
               "m/s, penalty 1e4 EA/le, with the card's own settings; its spread against the same run at "
               "the card's penalty is its uncertainty"
             : "IDA at the card's settings (not converged further: --references matrix)";
}

void ScoreOptions::validate(const std::string& method) const {
  const auto& all = card_sets();
  if (sets.empty()) throw InputError("command line", "--sets", "expected one or more of paper, hard, exact");
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (std::find(all.begin(), all.end(), sets[i]) == all.end())
      throw InputError("command line", "--sets", "expected paper, hard or exact, got '" + sets[i] + "'");
    if (std::find(sets.begin(), sets.begin() + i, sets[i]) != sets.begin() + i)
      throw InputError("command line", "--sets", "'" + sets[i] + "' is named twice");
  }
  if (references != "converged" && references != "matrix")
    throw InputError("command line", "--references",
                     "expected converged or matrix, got '" + references + "'");
  if (references == "matrix" && method == "ida")
    throw InputError(
        "command line", "--references",
        "IDA's own scorecard needs converged references (with matrix ones IDA would score its own runs)");
  if (rungs < 3 || rungs > 6)
    throw InputError("command line", "--rungs", fmt::format("expected 3 to 6 rungs, got {}", rungs));
}

std::vector<ScoreItem> score_items(const std::vector<BenchmarkCard>& cards, const Method& method,
                                   const ScoreOptions& options) {
  options.validate(method.name);
  const bool converge = options.references == "converged";
  std::vector<ScoreItem> items;
  const auto picked = [&](const JobSpec& run) {
    return options.scenes.empty() ||
           std::find(options.scenes.begin(), options.scenes.end(), run.scene_name()) != options.scenes.end();
  };
  for (const std::string& set : options.sets)
    for (const BenchmarkCard& c : cards) {
      if (c.set != set) continue;
      ScoreItem it;
      it.run = JobSpec{c.scene, method.name, std::nullopt, "", {}, {}};
      it.reference_kind = c.reference.method;
      it.reference = c.reference;
      if (c.reference.method == "ida" && converge) {
        it.reference = converged_ida(c.reference, true);
        if (converged_ida(c.reference, false).key() != it.reference.key())
          it.reference_check = converged_ida(c.reference, false);
      }
      if (c.reference.method == "exact" && options.ladder)
        it.ladder = plan_ladder(it.run, method, options.rungs);
      it.gates = c.quantities;
      it.source = c.source;
      it.set = c.set;
      if (picked(it.run)) items.push_back(std::move(it));
    }
  for (const std::string& name : options.scenes)
    if (std::none_of(items.begin(), items.end(),
                     [&](const ScoreItem& it) { return it.run.scene_name() == name; }))
      throw InputError("command line", "--scenes",
                       fmt::format("expected the name of a scene of the sets {} (a card's scene), got '{}'",
                                   fmt::join(options.sets, ","), name));
  return items;
}

double tolerance_slack(double tol, double error, double scale) {
  return 4.0 * DBL_EPSILON * std::max({std::abs(tol), std::abs(error), std::abs(scale)});
}

std::string verdict(double error, double tol, std::optional<double> spread, double scale) {
  if (!std::isfinite(error)) return "fail";
  const double s = spread.value_or(0.0), slack = tolerance_slack(tol, error, scale);
  if (error + s <= tol + slack) return "pass";
  if (error - s > tol + slack) return "fail";
  return "reference uncertain";
}

}  // namespace beamimpact::verification
