#pragma once
/// @file baseline.hpp
/// @brief The ratchet: a verify result against a baseline of an earlier one (`beamimpact verify
/// --baseline FILE`). A gated value that got worse beyond its noise fails; one that got better
/// beyond it is listed, a sign that the baseline may be updated (`--update-baseline`).
///
/// Noise: a value counts as changed when it moved by more than
///   max(relative * |baseline value|, absolute)
/// (defaults 1 % and 1e-9 in the gate's unit: relative errors, s or counts). Worse is larger
/// for an error or a Richardson distance, smaller for an observed order. A gate whose value is
/// missing now (its run failed or was skipped) is worse; a gate the baseline lacks is new, and
/// one this run did not evaluate (a tier or --only selection) is not run: neither fails.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <verification/matrix/evaluate.hpp>

namespace beamimpact::verification {

/// @brief How far a value may move and still be the same (see the file's comment).
struct BaselineNoise {
  double relative = 0.01;  ///< fraction of the baseline value
  double absolute = 1e-9;  ///< in the gate's unit
};

/// @brief One gate's value then and now.
struct BaselineDelta {
  std::string gate;              ///< "ITEM / METRIC" (and " (order)" or " (richardson)")
  std::optional<double> before;  ///< the baseline's value
  std::optional<double> now;     ///< this run's value (none: not evaluated)
};

/// @brief A result against a baseline.
struct BaselineComparison {
  std::vector<BaselineDelta> worse, better;
  std::vector<std::string> added, not_run;  ///< gates new in this run; gates of the baseline not evaluated
  int unchanged = 0;                        ///< gates within the noise
  BaselineNoise noise;
  /// @brief True when no gate got worse.
  bool passed() const { return worse.empty(); }
  /// @brief A summary line, then one line per worse and better gate.
  std::string to_text() const;
};

/// @brief The baseline of a result: version, tier and each gate's value and limits, in the
/// shape of norms.json's "items" (so a norms.json is a baseline too), without paths or times.
nlohmann::json baseline_json(const std::string& version, const std::string& tier,
                             const std::vector<ItemResult>& items);

/// @brief Compares a result's gates with a baseline (baseline_json() or a norms.json).
/// Throws InputError naming `file` when the baseline has no "items" list.
BaselineComparison compare_baseline(const nlohmann::json& baseline, const std::string& file,
                                    const std::vector<ItemResult>& items, const BaselineNoise& noise = {});

/// @brief Reads a baseline file (InputError when it is missing or not JSON).
nlohmann::json read_baseline(const std::filesystem::path& file);

}  // namespace beamimpact::verification
