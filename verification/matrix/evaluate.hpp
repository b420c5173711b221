#pragma once
/// @file evaluate.hpp
/// @brief Turns finished runs into gate results: compares each case with its reference, computes
/// the observed orders of convergence ladders, and decides pass / fail / skip per gate.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <verification/compare/Comparison.hpp>
#include <verification/jobs/execute_jobs.hpp>
#include <verification/matrix/VerificationMatrix.hpp>

namespace beamimpact::verification {

/// @brief Verdict of one gate. A skipped gate of a required item counts as a failure.
enum class GateStatus { kPass, kFail, kSkipped };

/// @brief "pass" | "fail" | "skipped" (norms.json, junit.xml, report.md).
const char* to_string(GateStatus s);

/// @brief Outcome of one gate.
struct GateResult {
  Gate gate;
  std::optional<double> value;  ///< the error (cases) or the observed order (ladders)
  GateStatus status = GateStatus::kFail;
  std::string message;  ///< why it failed / was skipped; "" on pass
  /// @brief "<= 0.01" or "order >= 0.9" (and "<= tol" too for ladders with both).
  std::string limit() const;
  /// @brief True for a passed gate (norms.json "passed").
  bool passed() const { return status == GateStatus::kPass; }
  /// @brief How much of its one limit the value uses, <= 1 when it holds: value / tol (an error),
  /// min_order / value (an observed order), value / richardson (Richardson distance); empty
  /// without a value or with more than one limit (norms.json "margin").
  std::optional<double> margin() const;
};

/// @brief Outcome of one case or ladder: its gates and what they were computed from.
struct ItemResult {
  std::string kind;       ///< "case" | "convergence" | "check"
  std::string scene;      ///< scene name (file stem)
  std::string name;       ///< Case::name() / Convergence::name()
  std::string settings;   ///< run settings label ("paper dt=0.01")
  std::string reference;  ///< reference settings label ("" for ladders)
  std::string tier;
  bool required = true;
  double wall_seconds = 0.0;    ///< s, process wall time of the run(s) under test
  double solver_seconds = 0.0;  ///< s, the methods' own wall time (summary.json)
  std::vector<GateResult> gates;
  std::vector<Comparison> comparisons;  ///< one per case; consecutive pairs for ladders
  /// @brief Ladders: norm name -> errors of consecutive pairs and the observed orders.
  std::map<std::string, std::pair<std::vector<std::optional<double>>, std::vector<std::optional<double>>>>
      orders;
  /// @brief Ladders with a reference, scalar norms: the Richardson limit of the last three rungs.
  struct Richardson {
    double order = 0.0;  ///< p = log(|Q1 - Q2| / |Q2 - Q3|) / log(r), from the rungs alone
    double limit = 0.0;  ///< Q3 + (Q3 - Q2) / (r^p - 1)
    double reference = 0.0;
    double error = 0.0;     ///< |limit - reference| / |reference|
    double estimate = 0.0;  ///< E_R / |reference|: |Q_n - Q_{n-1}| / (r^p - 1), relative
  };
  std::map<std::string, Richardson> richardson;
  std::string note;
  /// @brief True when no gate failed.
  bool passed() const;
};

/// @brief Gates of a verification run by verdict.
struct GateCounts {
  int gates = 0, pass = 0, fail = 0, skipped = 0;
};

/// @brief Counts the gates of every item by verdict.
GateCounts count_gates(const std::vector<ItemResult>& items);

/// @brief The one pass rule of a verification run: it is complete (no interruption: every run it
/// planned was started) and no gate failed (a required item's skipped gate is a failed one). The
/// exit status, norms.json's "verdict", report.md and report.html (which reads "verdict") follow it.
bool verification_passed(const std::vector<ItemResult>& items, bool complete);

/// @brief Decides one gate on a comparison (error <= tol). A missing or unavailable norm fails.
GateResult check_gate(const Gate& gate, const Comparison& cmp);

/// @brief Evaluates a case from the finished runs (keyed by JobSpec::key()).
ItemResult evaluate_case(const Case& c, const std::map<std::string, jobs::JobOutcome>& runs);

/// @brief Evaluates the health checks of one run (check_run()) from the finished runs.
ItemResult evaluate_check(const RunCheck& c, const std::map<std::string, jobs::JobOutcome>& runs);

/// @brief The Richardson limit of three rungs q1, q2, q3 (coarse to fine, refinement ratio r) with
/// their own observed order: {limit, order}; empty when the differences do not shrink monotonically (no
/// asymptotic range: 0 < (q2 - q3) / (q1 - q2) < 1).
std::optional<std::pair<double, double>> richardson_limit(double q1, double q2, double q3, double r);

/// @brief Evaluates a convergence ladder from the finished runs.
ItemResult evaluate_ladder(const Convergence& v, const std::map<std::string, jobs::JobOutcome>& runs);

/// @brief Observed order p = log(e_coarse / e_fine) / log(r); empty when an error is zero or missing.
std::optional<double> observed_order(std::optional<double> e_coarse, std::optional<double> e_fine, double r);

/// @brief JSON of an item: its gates and every norm of every comparison.
nlohmann::json to_json(const ItemResult& r);

}  // namespace beamimpact::verification
