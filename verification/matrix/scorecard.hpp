#pragma once
/// @file scorecard.hpp
/// @brief A method's scorecard on the benchmark set (docs/protocol.md): the paper's scenes, the
/// hard scenes and every scene with an exact answer, each run compared with the best reference
/// (exact where the matrix has one, else IDA converged beyond its defaults: time tolerances 100
/// times tighter, penalty 10 times stiffer, friction regularised at 1e-5 m/s) under the matrix's
/// own tolerances. Every method meets the same reference on a scene, and IDA is never scored
/// against its own run. A converged IDA reference comes with its own uncertainty: the spread
/// between it and the same run at the case's penalty, and a verdict the spread could reverse is
/// "reference uncertain", not pass or fail.

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
  /// The reference's uncertainty check: a converged IDA reference at the case's own penalty
  /// (kn_factor 1e3 unless the case sets kn or kn_factor); none for an exact reference or with
  /// matrix references.
  std::optional<JobSpec> reference_check;
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
  /// kn_factor 1e4, friction_velocity 1e-5 m/s, keeping the case's own settings) and checked
  /// against itself at the case's penalty; "matrix": the matrix case's IDA settings as
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
  /// The reference's own uncertainty in this quantity: |reference - reference_check| (same norm
  /// as error); none without a check or when the check did not finish.
  std::optional<double> reference_spread;
  std::string status;  ///< "pass" | "fail" | "reference uncertain" | "not applicable" | "failed" |
                       ///< "skipped" | "no tolerance"
  std::string note;    ///< the tolerance's reason, or why there is no value
};

/// @brief A scored scene.
struct ScoreRow {
  const ScoreItem* item = nullptr;
  JobOutcome outcome;  ///< the method's run
  std::vector<ScoreQuantity> quantities;
};

/// @brief The verdict on one quantity under a tolerance, given the reference's uncertainty: "pass"
/// if error + spread <= tol and "fail" if error - spread > tol (the same verdict whatever the
/// reference's own error within its spread); else "reference uncertain" (the reference cannot
/// decide at this tolerance).
/// @param error the run's error against the reference
/// @param tol the tolerance (same norm)
/// @param spread the reference's uncertainty (same norm); none: the reference is taken as exact
std::string verdict(double error, double tol, std::optional<double> spread);

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
