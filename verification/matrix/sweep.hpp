#pragma once
/// @file sweep.hpp
/// @brief `beamimpact sweep`: one scene at several dt (and meshes), each compared with one
/// reference, with wall time: the table behind "what accuracy costs in time".

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <verification/compare/Comparison.hpp>
#include <verification/jobs/execute_jobs.hpp>

namespace beamimpact::verification {

/// @brief What to sweep.
struct SweepOptions {
  std::filesystem::path scene;
  std::string method = "paper";
  std::vector<double> dts;          ///< s (scenes with a numeric dt)
  std::vector<double> fractions;    ///< of the critical step (scenes with dt = "auto"); instead of dts
  std::vector<std::string> meshes;  ///< element multipliers (beam methods) or presets; empty = scene's
  std::string reference = "self";   ///< "self" | a method name | a run directory
  std::filesystem::path out;
  int jobs = 1;
  double timeout = 3600.0;  ///< s per run
  int threads = 0;          ///< --threads of each run of the paper integrator (0: each run's default)
  /// @brief The beamimpact program each run is a process of (isolation); empty: every run goes
  /// in this process (jobs/execute_jobs.hpp).
  std::filesystem::path exe;
};

/// @brief One point of the sweep.
struct SweepPoint {
  jobs::JobOutcome outcome;
  std::optional<Comparison> comparison;  ///< empty when the run failed
};

/// @brief The whole sweep.
struct SweepResult {
  std::string reference_label;  ///< what the errors are measured against
  std::filesystem::path reference_dir;
  std::vector<SweepPoint> points;  ///< in the order dts x meshes
  std::string command;             ///< the command line that makes this sweep
  std::string made;                ///< UTC, when it started
  double wall_seconds = 0.0;       ///< s, the whole sweep
  std::string incomplete;          ///< why the sweep is not complete (an interruption); "" complete
};

/// @brief The runs a sweep is made of, before any runs.
struct SweepPlan {
  std::vector<jobs::JobSpec> points;       ///< in the order dts x meshes
  std::optional<jobs::JobSpec> reference;  ///< the reference run; none when it is a run directory
  SweepResult head;                        ///< reference_label, reference_dir, command, made
};

/// @brief Checks the options and plans the runs (InputError for bad options).
SweepPlan plan_sweep(const SweepOptions& o);

/// @brief Compares each point's outcome with the reference's: the sweep without its runs.
/// Throws InputError when the reference run was refused, std::runtime_error when it failed.
/// @param o the options; @param plan plan_sweep(o); @param outcomes the runs by JobSpec::key()
SweepResult judge_sweep(const SweepOptions& o, const SweepPlan& plan,
                        const std::map<std::string, jobs::JobOutcome>& outcomes);

/// @brief Runs the sweep (runs in parallel) and compares each point with the reference.
/// Throws InputError for bad options or when every run was refused, and std::runtime_error when
/// the reference run fails. Returns nullopt on an MPI rank other than 0 (jobs::execute_jobs).
std::optional<SweepResult> sweep(const SweepOptions& o);

/// @brief Writes o.out/sweep.md (headed by how it was made: command, version, time), sweep.csv
/// and sweep.json.
void write_sweep(const SweepOptions& o, const SweepResult& r);

/// @brief The norms tabulated by sweep (and printed by verify for a case).
const std::vector<std::string>& sweep_norms();

}  // namespace beamimpact::verification
