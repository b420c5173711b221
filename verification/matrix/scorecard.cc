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
bool sets_key(const jobs::JobSpec& ref, const std::string& key) {
  return std::any_of(ref.set.begin(), ref.set.end(),
                     [&](const std::string& s) { return s.rfind(key + "=", 0) == 0; });
}

/// A card's reference converged beyond its defaults by its registry entry's settings
/// (Method::as_reference), keeping the card's own: each converged setting unless the card sets its
/// key, and with `stiffen` the stiffer settings unless the card sets its own stiffness. Without
/// `stiffen` it is the reference's check: the same run at the card's stiffness.
jobs::JobSpec converged_reference(jobs::JobSpec ref, const AsReference& facts, bool stiffen) {
  const bool own_stiffness = std::any_of(facts.stiffness_keys.begin(), facts.stiffness_keys.end(),
                                         [&](const std::string& k) { return sets_key(ref, k); });
  for (const std::string& setting : facts.converged)
    if (!sets_key(ref, setting.substr(0, setting.find('=')))) ref.set.push_back(setting);
  if (stiffen && !own_stiffness)
    for (const std::string& setting : facts.stiffer) ref.set.push_back(setting);
  return ref;
}

/// The registry entry of a card's reference (cards.cc checked that it is a reference).
const Method& reference_method(const BenchmarkCard& c) {
  return method(c.reference.method, c.scene.string(), "reference.method");
}

}  // namespace

std::string ida_reference(const ScoreOptions& o) {
  std::string words;
  for (const Method& m : methods())
    if (m.as_reference.rank == ReferenceRank::kConverged)
      words += (words.empty() ? "" : "; ") + (o.references == "converged"
                                                  ? m.as_reference.converged_words
                                                  : m.name +
                                                        " at the card's settings (not converged further: "
                                                        "--references matrix)");
  return words;
}

void ScoreOptions::validate(const Method& method) const {
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
  if (references == "matrix" && method.as_reference.rank == ReferenceRank::kConverged)
    throw InputError("command line", "--references",
                     "the scorecard of '" + method.name +
                         "', a converged reference, needs converged references (with matrix ones it would "
                         "score its own runs)");
  if (rungs < 3 || rungs > 6)
    throw InputError("command line", "--rungs", fmt::format("expected 3 to 6 rungs, got {}", rungs));
}

std::vector<ScoreItem> score_items(const std::vector<BenchmarkCard>& cards, const Method& method,
                                   const ScoreOptions& options) {
  options.validate(method);
  const bool converge = options.references == "converged";
  std::vector<ScoreItem> items;
  const auto picked = [&](const jobs::JobSpec& run) {
    return options.scenes.empty() ||
           std::find(options.scenes.begin(), options.scenes.end(), run.scene_name()) != options.scenes.end();
  };
  for (const std::string& set : options.sets)
    for (const BenchmarkCard& c : cards) {
      if (c.set != set) continue;
      ScoreItem it;
      it.run = jobs::JobSpec{c.scene, method.name, std::nullopt, "", {}};
      it.reference_kind = c.reference.method;
      it.reference = c.reference;
      const AsReference& facts = reference_method(c).as_reference;
      if (facts.rank == ReferenceRank::kConverged && converge) {
        it.reference = converged_reference(c.reference, facts, true);
        if (converged_reference(c.reference, facts, false).key() != it.reference.key())
          it.reference_check = converged_reference(c.reference, facts, false);
      }
      if (facts.rank == ReferenceRank::kExact && options.ladder)
        it.ladder = plan_ladder(it.run, method, options.rungs);
      it.gates = c.quantities;
      it.settled = c.settled;
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

QuantityStatus verdict(double error, double tol, std::optional<double> spread, double scale) {
  if (!std::isfinite(error)) return QuantityStatus::kFail;
  const double s = spread.value_or(0.0), slack = tolerance_slack(tol, error, scale);
  if (error + s <= tol + slack) return QuantityStatus::kPass;
  if (error - s > tol + slack) return QuantityStatus::kFail;
  return QuantityStatus::kReferenceUncertain;
}

}  // namespace beamimpact::verification
