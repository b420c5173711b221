#pragma once
/// @file scorecard.hpp
/// @brief A method's scorecard on the benchmark set (docs/protocol.md): the paper's scenes, the
/// hard scenes and every scene with an exact answer, each run compared with the best reference
/// (exact where the matrix has one, else IDA converged beyond its defaults: time tolerances 100
/// times tighter, penalty 10 times stiffer) under the matrix's own tolerances. Every method meets
/// the same reference on a scene, and IDA is never scored against its own run.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <verification/matrix/VerificationMatrix.hpp>
#include <verification/matrix/evaluate.hpp>

namespace beamimpact::verification {

/// @brief One benchmark scene: the method's run, its reference and the quantities compared.
struct ScoreItem {
  JobSpec run, reference;
  std::string reference_kind;  ///< "exact" or "ida" (its settings in reference.set)
  std::vector<Gate> gates;     ///< the matrix case's gates (tol and why); none: errors reported only
  std::string source;          ///< the matrix case the reference and tolerances come from ("" none)
};

/// @brief What `beamimpact score` scores, and against which IDA.
struct ScoreOptions {
  /// Scene sets, in this order: "paper" (verification/scenes/paper), "hard"
  /// (verification/scenes/hard), "exact" (every other scene the matrix compares with exact).
  std::vector<std::string> sets = {"paper", "hard", "exact"};
  /// "converged": an IDA reference is converged beyond its defaults (rtol 1e-10, atol 1e-13,
  /// kn_factor 1e4, keeping the case's own settings); "matrix": the matrix case's IDA settings as
  /// written (quicker, less strict; refused for IDA's own scorecard, which would score itself).
  std::string references = "converged";

  /// @brief Throws InputError naming the option and the values allowed.
  /// @param method the scored method ("ida" may not take matrix references)
  void validate(const std::string& method) const;
};

/// @brief The IDA reference of `o`, in words (the scorecard page and the terminal say it).
std::string ida_reference(const ScoreOptions& o);

/// @brief The benchmark set for `method`: the scenes of `options.sets`; for each, the matrix case
/// giving the best reference (exact before IDA) and its tolerances, preferring a case of the
/// method itself, then one of the paper integrator (whose run settings are taken only for the
/// method itself). A scene with no such case is compared with IDA, without tolerances.
/// @param matrix the verification matrix (references and tolerances)
/// @param method the scored method
/// @param data_root the folder holding verification/scenes
/// @param options the scene sets and the kind of IDA reference (validated here)
std::vector<ScoreItem> score_items(const VerificationMatrix& matrix, const std::string& method,
                                   const std::filesystem::path& data_root, const ScoreOptions& options = {});

/// @brief One quantity of a scored scene.
struct ScoreQuantity {
  std::string metric;
  std::optional<double> error, tol;
  std::string status;  ///< "pass" | "fail" | "not applicable" | "failed" | "skipped" | "no tolerance"
  std::string note;    ///< the tolerance's reason, or why there is no value
};

/// @brief A scored scene.
struct ScoreRow {
  const ScoreItem* item = nullptr;
  JobOutcome outcome;  ///< the method's run
  std::vector<ScoreQuantity> quantities;
};

/// @brief Compares each finished run with its reference (compare_runs, check_gate).
std::vector<ScoreRow> score_rows(const std::vector<ScoreItem>& items,
                                 const std::map<std::string, JobOutcome>& runs);

/// @brief What the scorecard says about how it was made.
struct ScoreContext {
  std::string method, origin, command, version, made;
  double wall_seconds = 0.0;
  ScoreOptions options;  ///< written into scorecard.json and the page
};

/// @brief Writes dir/scorecard.json and the self-contained dir/scorecard.html.
void write_scorecard(const std::filesystem::path& dir, const ScoreContext& ctx,
                     const std::vector<ScoreRow>& rows);

}  // namespace beamimpact::verification
