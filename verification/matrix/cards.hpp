#pragma once
/// @file cards.hpp
/// @brief The benchmark cards (verification/cards.toml): for every scene `beamimpact score`
/// scores, its reference and its gated quantities, each with a tolerance and its reason. One card
/// per scene, the same for every method (docs/benchmark-cards.md shows them as one table).

#include <filesystem>
#include <string>
#include <vector>

#include <verification/jobs/JobSpec.hpp>
#include <verification/matrix/VerificationMatrix.hpp>

namespace beamimpact::verification {

/// @brief A quantity's settled value: what a scene's independent references converge to, with its
/// uncertainty (docs/s4.md). `score` judges the quantity against it instead of the reference
/// run's value, the uncertainty taking the place of the reference's spread.
struct SettledValue {
  std::string metric;        ///< a quantity of the card with a scalar value (settled_metric)
  double value = 0.0;        ///< in the quantity's unit: N s (impulse, impulse_2, ...), N (peak_R), s
  double uncertainty = 0.0;  ///< same unit, >= 0
  std::string why;           ///< where the numbers come from
};

/// @brief Whether `metric` may carry a settled value: a norm comparing the run's own scalar with
/// the reference's, |a - b| / |b| (impulse, impulse_2, ..., peak_R) or |a - b| in s (contact_start,
/// contact_end).
bool settled_metric(const std::string& metric);

/// @brief One benchmark scene's card.
struct BenchmarkCard {
  std::filesystem::path scene;        ///< absolute, normalised
  std::string set;                    ///< "paper", "hard" or "exact"
  jobs::JobSpec reference;            ///< a reference method (exact, or ida with the card's settings)
  std::string source;                 ///< the matrix row the tolerances come from ("" derived)
  std::string note;                   ///< why a quantity of the scene is not on the card ("" none)
  std::vector<Gate> quantities;       ///< each with tol and why
  std::vector<SettledValue> settled;  ///< quantities judged against a settled value (none: the reference run)
};

/// @brief The scene sets of the cards, in scoring order.
const std::vector<std::string>& card_sets();

/// @brief Reads a cards file. Scene paths are relative to `root`. Throws InputError (file, key,
/// what was expected) for bad TOML, unknown keys, a missing scene file, a scene carded twice, an
/// unknown set or metric, a reference that is no reference method of the registry (Method::as_reference), a
/// quantity without tol or why, a settled value of a metric the card does not gate (or without a
/// scalar value), twice, or without a finite non-zero value, an uncertainty >= 0 or why.
/// @param file the cards file (verification/cards.toml)
/// @param root the repository root (the folder holding verification/scenes)
std::vector<BenchmarkCard> load_cards(const std::filesystem::path& file, const std::filesystem::path& root);

}  // namespace beamimpact::verification
