#pragma once
/// @file scorecard.hpp
/// @brief A method's scorecard on the benchmark set (docs/protocol.md, docs/benchmark-cards.md):
/// every scene of the chosen sets scored under its benchmark card (verification/cards.toml), the
/// same reference, quantities and tolerances for every method. On a scene with an exact answer
/// the method runs a resolution ladder (ladder.hpp) and each gated scalar's extrapolated limit is
/// judged against the exact value; elsewhere its one run is compared with IDA converged beyond
/// its defaults (time tolerances 100 times tighter, penalty 10 times stiffer, friction
/// regularised at 1e-5 m/s), whose spread against the same run at the card's penalty is the
/// reference's own uncertainty. A quantity with a settled value on its card (SettledValue: S4's
/// impulse) is judged against that value and its uncertainty instead.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <api/registry.hpp>
#include <verification/matrix/cards.hpp>
#include <verification/matrix/evaluate.hpp>
#include <verification/matrix/ladder.hpp>
#include <verification/matrix/quantity_status.hpp>

namespace beamimpact::verification {

/// @brief One benchmark scene as scored for one method.
struct ScoreItem {
  jobs::JobSpec run;  ///< the method at the scene's own settings
  LadderPlan ladder;  ///< rungs (rungs[0] == run) on a scene with an exact answer; none with --no-ladder
  jobs::JobSpec reference;
  /// The reference's uncertainty check: a converged IDA reference at the card's own penalty; none
  /// for an exact reference or with matrix references.
  std::optional<jobs::JobSpec> reference_check;
  std::string reference_kind;  ///< the reference's method, "exact" or "ida" (its settings in reference.set)
  std::vector<Gate> gates;     ///< the card's quantities (tol and why)
  /// The card's settled values: each of these quantities is judged against its settled value and
  /// uncertainty, not against the reference run's value and spread.
  std::vector<SettledValue> settled;
  std::string source;  ///< the matrix row the card's tolerances come from ("" derived)
  std::string set;     ///< the card's scene set
};

/// @brief What `beamimpact score` scores, and how: the options of the command, of
/// verification::score (score.hpp) and of the Python module's score().
struct ScoreOptions {
  /// The scored methods (`beamimpact methods`): one, or several run in one set of jobs, each
  /// scorecard in out/NAME.
  std::vector<std::string> methods;
  /// Output directory (runs/, scorecard.json, or NAME/ for each of several methods); "" is
  /// score-NAME (score-NAME1-NAME2 for several): out_dir().
  std::filesystem::path out;
  /// The benchmark cards (docs/benchmark-cards.md); "" is verification/cards.toml of the data root.
  std::filesystem::path cards;
  /// Folder of cached reference runs; "": cache_dir()'s default.
  std::filesystem::path cache;
  /// An earlier scorecard.json of the same method, sets and ladder setting ("" none): an error
  /// grown beyond its uncertainty since fails the verdict (the accuracy ratchet).
  std::filesystem::path baseline;
  int jobs = 1;            ///< runs in parallel (>= 1)
  double timeout = 900.0;  ///< s per run (> 0)
  /// @brief The beamimpact program each run is a process of (isolation); empty: every run goes
  /// in this process (jobs/execute_jobs.hpp).
  std::filesystem::path exe;
  /// Scene sets, in this order: "paper" (verification/scenes/paper), "hard"
  /// (verification/scenes/hard), "exact" (the other scenes with an exact answer).
  std::vector<std::string> sets = {"paper", "hard", "exact"};
  /// "converged": a converged reference (IDA) is converged beyond the card's settings by its
  /// registry entry's settings (Method::as_reference) and checked against itself at the card's
  /// stiffness; "matrix": the card's settings as written (quicker, less strict; refused for the
  /// scorecard of a converged reference, which would score itself).
  std::string references = "converged";
  bool ladder = true;  ///< false (--no-ladder): one run a scene, its error judged under the card
  int rungs = 3;       ///< runs of a ladder (>= 3)
  /// Scenes scored, by name (a card's scene file without .toml); empty: every scene of the sets.
  /// A name no card of the sets holds is bad input.
  std::vector<std::string> scenes;

  /// @brief Throws InputError naming the option and the values allowed: every option, each method
  /// runnable here and named once, and each method with these settings (validate(method)).
  void validate() const;
  /// @brief Throws InputError naming the option and the values allowed (sets, references, rungs).
  /// @param method the scored method (a converged reference, ReferenceRank::kConverged, may not
  /// take matrix references: it would score its own runs)
  void validate(const Method& method) const;
  /// @brief `out`, or score-NAME1-NAME2 when it is empty.
  std::filesystem::path out_dir() const;
  /// @brief `cache` (made absolute), else $BEAMIMPACT_REFERENCE_CACHE, else
  /// $XDG_CACHE_HOME/beamimpact/references, else ~/.cache/beamimpact/references.
  std::filesystem::path cache_dir() const;
};

/// @brief The converged references of `o` (the registry's methods of ReferenceRank::kConverged),
/// in words (scorecard.json's ida_reference, which its page shows; the terminal says it too).
std::string ida_reference(const ScoreOptions& o);

/// @brief The benchmark set for `method`: one item per card of `options.sets`, in set order and
/// the cards' order within a set; the card's reference and quantities whatever the method's name.
/// @param cards the benchmark cards (load_cards)
/// @param method the scored method (its Accepts choose the ladder)
/// @param options the scene sets, the kind of IDA reference and the ladder (validated here)
std::vector<ScoreItem> score_items(const std::vector<BenchmarkCard>& cards, const Method& method,
                                   const ScoreOptions& options = {});

/// @brief One quantity of a scored scene.
struct ScoreQuantity {
  std::string metric;
  /// The error in the norm's unit: of the ladder's limit against the exact value (judged =
  /// "limit"), else of the run against the reference.
  std::optional<double> error, tol;
  /// The error's own uncertainty, same unit: the limit's (ladder.hpp) or the reference's spread
  /// (|reference - reference_check|); none when unknown, 0 against an exact reference.
  std::optional<double> uncertainty;
  QuantityStatus status = QuantityStatus::kFail;  ///< scorecard.json's word: to_string(status)
  std::string note;  ///< the tolerance's reason, or why the verdict is what it is
  /// "limit" (the ladder's extrapolation), "finest rung" (a quantity with no scalar value on a
  /// ladder: the finest run's error), "single run" (no ladder); "" when not judged.
  std::string judged;
  std::optional<LadderResult> ladder;  ///< the rungs' values, order, limit (judged == "limit")
  std::optional<double> exact;         ///< the reference's value of a scalar quantity (a settled value)
  std::optional<double> allowed;       ///< judged == "limit": 1.25 U + tol / 10, what the error may reach
};

/// @brief A scored scene.
struct ScoreRow {
  const ScoreItem* item = nullptr;
  jobs::JobOutcome outcome;             ///< the method's run at the scene's settings
  std::vector<jobs::JobOutcome> rungs;  ///< every rung's outcome (rungs[0] == outcome) on a ladder
  std::vector<ScoreQuantity> quantities;
};

/// @brief The relative slack of every tolerance comparison: 4 ulps (4 x 2^-52) of the largest
/// number compared (the tolerance, the error, or the compared values themselves: a contact_end
/// of 2.55 s carries round-off of 4.4e-16 s), so that round-off never decides a verdict.
double tolerance_slack(double tol, double error, double scale);

/// @brief The verdict on one quantity under a tolerance, given its uncertainty: pass if
/// error + spread <= tol and fail if error - spread > tol, each with tolerance_slack; else
/// reference uncertain (the reference cannot decide at this tolerance).
/// @param error the run's error against the reference
/// @param tol the tolerance (same norm)
/// @param spread the reference's uncertainty (same norm); none: the reference is taken as exact
/// @param scale the largest value the error was computed from (0: the error and tol only)
QuantityStatus verdict(double error, double tol, std::optional<double> spread, double scale = 0.0);

/// @brief Compares each finished run (and ladder) with its reference (compare_runs, run first).
/// `runs` holds the outcomes by JobSpec::key(); a reference absent from it was not run (the
/// method's run did not finish).
std::vector<ScoreRow> score_rows(const std::vector<ScoreItem>& items,
                                 const std::map<std::string, jobs::JobOutcome>& runs);

/// @brief The overall verdict of a scorecard: exit code 0 when every quantity passes (passes():
/// a scene the method refused counts as not applicable, said in the line), 1 when any does not
/// (fail, not converged, failed, or undecided: reference uncertain, skipped).
struct ScoreVerdict {
  int exit_code = 0;
  std::string
      line;  ///< "score NAME: PASSED ..." or "score NAME: FAILED ...", statuses as describe() says them
  std::map<QuantityStatus, int> counts;  ///< quantities by status
};

/// @brief The overall verdict of rows for method `name`.
ScoreVerdict score_verdict(const std::string& name, const std::vector<ScoreRow>& rows);

/// @brief The accuracy ratchet against an earlier scorecard.json of the same method, sets and
/// ladder setting: a quantity's error grew when it exceeds the baseline's by more than the
/// larger of the two uncertainties (plus tolerance_slack); improved when it fell by as much.
struct Ratchet {
  std::vector<std::string> grown, improved;  ///< "scene metric: 0.01 -> 0.02 (uncertainty 0)"
};

/// @brief Compares rows with a baseline scorecard. Throws InputError (file, key, expected) for a
/// baseline that is not a scorecard, or of another method, set list or ladder setting.
Ratchet ratchet(const std::filesystem::path& baseline_file, const std::string& method,
                const ScoreOptions& options, const std::vector<ScoreRow>& rows);

/// @brief What the scorecard says about how it was made.
struct ScoreContext {
  std::string method, origin, command, version, made;
  double wall_seconds = 0.0;
  ScoreOptions options;  ///< written into scorecard.json and the page
  std::string cache;     ///< the folder of cached references
};

/// @brief scorecard.json's document (every quantity with its verdict, ladder, order, limit,
/// uncertainty, tolerance and reason; the overall verdict; provenance).
nlohmann::json scorecard_json(const ScoreContext& ctx, const std::vector<ScoreRow>& rows,
                              const ScoreVerdict& verdict);

/// @brief Writes dir/scorecard.json (atomically). Its page, dir/scorecard.html, is rendered from it
/// by reports/render.py (the `score` command runs it: tools/beamimpact/page.hpp).
void write_scorecard(const std::filesystem::path& dir, const ScoreContext& ctx,
                     const std::vector<ScoreRow>& rows, const ScoreVerdict& verdict);

}  // namespace beamimpact::verification
