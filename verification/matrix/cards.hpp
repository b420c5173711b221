#pragma once
/// @file cards.hpp
/// @brief The benchmark cards (verification/cards.toml): for every scene `beamimpact score`
/// scores, its reference and its gated quantities, each with a tolerance and its reason. One card
/// per scene, the same for every method (docs/benchmark-cards.md shows them as one table).

#include <filesystem>
#include <string>
#include <vector>

#include <verification/matrix/JobSpec.hpp>
#include <verification/matrix/VerificationMatrix.hpp>

namespace beamimpact::verification {

/// @brief One benchmark scene's card.
struct BenchmarkCard {
  std::filesystem::path scene;   ///< absolute, normalised
  std::string set;               ///< "paper", "hard" or "exact"
  JobSpec reference;             ///< a reference method (exact, or ida with the card's settings)
  std::string source;            ///< the matrix row the tolerances come from ("" derived)
  std::string note;              ///< why a quantity of the scene is not on the card ("" none)
  std::vector<Gate> quantities;  ///< each with tol and why
};

/// @brief The scene sets of the cards, in scoring order.
const std::vector<std::string>& card_sets();

/// @brief Reads a cards file. Scene paths are relative to `root`. Throws InputError (file, key,
/// what was expected) for bad TOML, unknown keys, a missing scene file, a scene carded twice, an
/// unknown set or metric, a reference that is no reference method of the registry (Method::as_reference), a
/// quantity without tol or why.
/// @param file the cards file (verification/cards.toml)
/// @param root the repository root (the folder holding verification/scenes)
std::vector<BenchmarkCard> load_cards(const std::filesystem::path& file, const std::filesystem::path& root);

}  // namespace beamimpact::verification
