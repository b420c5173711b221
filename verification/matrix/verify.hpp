#pragma once
/// @file verify.hpp
/// @brief `verify` as a library function: runs a verification matrix's tier, evaluates every
/// case, ladder and check, and returns the result with its one pass rule; the command line
/// (`beamimpact verify`) and the Python module (`beamimpact.verify`) are thin calls of it.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <verification/jobs/execute_jobs.hpp>
#include <verification/matrix/baseline.hpp>
#include <verification/matrix/evaluate.hpp>
#include <verification/matrix/reports.hpp>

namespace beamimpact::verification {

/// @brief What to verify and where the runs go.
struct VerifyOptions {
  std::filesystem::path matrix = "verification/matrix.toml";  ///< the matrix file
  std::filesystem::path out;   ///< runs/ (one directory per run) and the reports
  std::string tier = "quick";  ///< VerificationMatrix::tier_names()
  std::string only;            ///< only items whose name contains this text ("" all)
  int jobs = 1;                ///< runs in parallel (>= 1)
  int threads = 0;             ///< --threads of every in-process run (0: each run's default)
  std::string command;         ///< the command line written into the reports ("" made from these options)
  /// @brief The beamimpact program each run is a process of (isolation); empty: every run goes
  /// in this process (jobs/execute_jobs.hpp).
  std::filesystem::path exe;
  bool quiet = false;  ///< no plan line (an MPI worker rank)
  /// @brief Run everything again; otherwise a run recorded as finished under out/runs with the
  /// same input (an interrupted verify's) is taken as it is (finished_runs.hpp).
  bool fresh = false;
  /// @brief A baseline (an earlier --update-baseline file, or a norms.json) this result is held to:
  /// a gated value worse than in it beyond its noise fails the verdict (baseline.hpp). "" none.
  std::filesystem::path baseline;
  /// @brief Write `baseline` from this result (when its gates pass) instead of holding it to it.
  bool update_baseline = false;
};

/// @brief A verification run: how it was made, every item's gates, and the verdict.
struct VerifyResult {
  ReportContext context;
  std::vector<ItemResult> items;
  /// @brief This result against VerifyOptions::baseline, when one was given and exists.
  std::optional<BaselineComparison> baseline;
  std::filesystem::path baseline_file;  ///< VerifyOptions::baseline
  bool update_baseline = false;         ///< VerifyOptions::update_baseline: written, not held
  /// @brief The gates' rule (verification_passed()): complete and no gate failed.
  bool gates_passed() const { return verification_passed(items, context.incomplete.empty()); }
  /// @brief The one verdict: the gates pass and, unless the baseline is being written, no gated
  /// value got worse than in the baseline.
  bool passed() const { return gates_passed() && (update_baseline || !baseline || baseline->passed()); }
};

/// @brief Checks the options (InputError naming the option; a --baseline that does not exist, unless it
/// is to be written), loads the matrix, runs the selected items' runs into out/runs/ (those finished
/// earlier taken, unless o.fresh), evaluates them and compares them with the baseline. Returns
/// nullopt on an MPI rank other than 0 (jobs::execute_jobs). An interruption (interruption()) leaves a result
/// marked incomplete.
std::optional<VerifyResult> verify(const VerifyOptions& o);

/// @brief Writes o.out/junit.xml, norms.json and report.md of a result, and with o.update_baseline the
/// baseline file when the gates passed. Returns the baseline file written ("" none).
std::filesystem::path write_verify_reports(const VerifyOptions& o, const VerifyResult& r);

}  // namespace beamimpact::verification
