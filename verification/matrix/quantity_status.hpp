#pragma once
/// @file quantity_status.hpp
/// @brief The verdict on one quantity of a scorecard (`beamimpact score`, docs/protocol.md
/// "Quantity statuses"): one enum, its word in scorecard.json (to_string / parse_quantity_status,
/// a public format) and its words for a reader (describe: the console and the page), which keep
/// "fail" (judged, outside its tolerance) and "failed" (the run did not finish) apart.

#include <string>
#include <string_view>
#include <vector>

namespace beamimpact::verification {

/// @brief What became of one quantity of a scored scene.
enum class QuantityStatus {
  kPass,                ///< judged, within its tolerance (or a ladder's limit within its allowance)
  kFail,                ///< judged, outside its tolerance
  kNotConverged,        ///< a ladder whose rung differences do not shrink (observed order < 0.5)
  kReferenceUncertain,  ///< the reference's own spread could reverse the verdict
  kFailed,              ///< the method's run (or a ladder rung) did not finish, or did not compare
  kSkipped,             ///< the reference did not finish: no verdict
  kNotApplicable,       ///< the method refused the scene (exit 2 with its reason)
};

/// @brief Every status, in the order above (the order of the verdict line's tally).
const std::vector<QuantityStatus>& quantity_statuses();

/// @brief The status's word in scorecard.json: "pass", "fail", "not converged", "reference
/// uncertain", "failed", "skipped", "not applicable".
const char* to_string(QuantityStatus s);

/// @brief The status whose word (to_string) is `text`. Throws InputError(file, key, the words
/// allowed) for any other text.
/// @param text the word; @param file the file it was read from; @param key its key there
QuantityStatus parse_quantity_status(std::string_view text, const std::string& file, const std::string& key);

/// @brief The status as the console and the page say it: to_string's word, but "fail (outside
/// tolerance)" for kFail and "run failed" for kFailed, two words a reader would otherwise confuse.
const char* describe(QuantityStatus s);

/// @brief True for the statuses a passing scorecard may hold: pass, and not applicable (a scene
/// the method refused is not a failure); every other status fails the verdict (exit code 1).
bool passes(QuantityStatus s);

}  // namespace beamimpact::verification
