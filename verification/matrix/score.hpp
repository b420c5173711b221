#pragma once
/// @file score.hpp
/// @brief `score` as a library function (docs/protocol.md): one or several methods run on the
/// benchmark set (phase 1, ladders included), the references of the scenes they ran (phase 2, in a
/// cache shared between commands), each run judged under its benchmark card, an optional ratchet
/// against a baseline scorecard, and the one verdict. The command line (`beamimpact score`) and the
/// Python module (`beamimpact.score`) are thin calls of it.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <verification/matrix/scorecard.hpp>

namespace beamimpact::verification {

/// @brief One method's scorecard in a score result.
struct MethodScore {
  std::string method;         ///< its name
  std::string origin;         ///< "built-in" or the methods file that declared it
  std::filesystem::path dir;  ///< where its scorecard.json goes: out, or out/NAME for several methods
  std::shared_ptr<const std::vector<ScoreItem>> items;  ///< the scored scenes (the rows point into them)
  std::vector<ScoreRow> rows;                           ///< each scene judged
  ScoreVerdict verdict;                                 ///< the rows' verdict (score_verdict)
  std::optional<Ratchet> ratchet;                       ///< against ScoreOptions::baseline, when given
  /// @brief 1 when the verdict failed or an error grew since the baseline, else 0.
  int exit_code() const;
};

/// @brief A score: every method's scorecard, how it was made, and the one verdict.
struct ScoreResult {
  std::vector<MethodScore> methods;  ///< in the order of ScoreOptions::methods
  std::string command;               ///< the command line written into the scorecards
  std::filesystem::path cache;       ///< the reference cache used (ScoreOptions::cache_dir())
  std::string made;                  ///< UTC time it ended
  double wall_seconds = 0.0;         ///< s, from the options' check to the last judgement
  int interrupted = 0;               ///< the signal that interrupted it (interruption()); 0 none
  /// @brief 128 + the signal when interrupted, else 1 when a method's exit_code() is 1, else 0.
  int exit_code() const;
  /// @brief True when exit_code() is 0: every quantity of every method passes or is not
  /// applicable, no error grew since the baseline, and nothing interrupted it.
  bool passed() const { return exit_code() == 0; }
};

/// @brief Checks the options (ScoreOptions::validate, a --baseline that is not a scorecard of the one
/// method, sets and ladder setting), loads the cards, runs the methods' runs into out/runs and the
/// references of the scenes whose runs all finished into the reference cache (a reference recorded
/// there with the same input is taken, not run again), and judges every method's rows. Progress
/// goes to stderr. An interruption (interruption()) ends the runs: what finished is judged.
/// Under mpirun the runs are spread over the ranks (jobs::execute_jobs); nullopt on the ranks
/// other than 0.
std::optional<ScoreResult> score(const ScoreOptions& o);

/// @brief What a method's scorecard.json says of how it was made (its command, version, date,
/// options and cache).
ScoreContext score_context(const ScoreOptions& o, const ScoreResult& r, const MethodScore& m);

/// @brief Writes each method's scorecard.json (atomically) into its dir. Returns the files written,
/// in the order of r.methods. The pages (scorecard.html) are rendered from them by reports/render.py.
std::vector<std::filesystem::path> write_score_reports(const ScoreOptions& o, const ScoreResult& r);

}  // namespace beamimpact::verification
