#pragma once
/// @file VerificationMatrix.hpp
/// @brief The verification matrix (verification/matrix.toml): cases of scene x method x dt/mesh
/// compared with a reference run under gated norms, and self-convergence ladders.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <verification/jobs/JobSpec.hpp>

namespace beamimpact::verification {

/// @brief One gate: a norm with its limit and the reason for that limit.
struct Gate {
  std::string metric;               ///< a compare_runs norm name ("impulse", "R.rel_l2", ...)
  std::optional<double> tol;        ///< passes when the error <= tol
  std::optional<double> min_order;  ///< convergence only: passes when the observed order >= this
  std::string why;                  ///< justification (theory, mesh error, measured spread)
  /// Ladders with a reference, scalar norms only: a safety factor F (Roache's grid convergence
  /// index uses 1.25 for three rungs). Passes when the Richardson limit Q_R of the last three
  /// rungs (their own observed order p, no reference used) is within F E_R of the reference,
  /// E_R = |Q_n - Q_{n-1}| / (r^p - 1) the extrapolation's own error estimate of the finest rung.
  std::optional<double> richardson;
};

/// @brief A run compared with a reference run.
struct Case {
  jobs::JobSpec run, reference;
  std::string tier = "quick";  ///< "quick" (CI) or "full"
  bool required = true;        ///< a skipped run fails the gate when required
  std::vector<Gate> gates;
  std::string note;  ///< free text shown in the report
  /// @brief "s1_central paper dt=0.01 vs exact".
  std::string name() const;
};

/// @brief A convergence ladder: the same method at successively refined steps (dt or fraction)
/// or meshes (element multiplier; the step follows from the scene). Without a reference,
/// consecutive pairs are compared (self-convergence); with one, every rung is compared with it.
/// The observed order of each norm is p = log(e_i / e_{i+1}) / log(r), r the refinement ratio.
struct Convergence {
  std::vector<jobs::JobSpec> runs;  ///< coarse to fine
  std::vector<double>
      steps;  ///< the refined quantity of each run: dt, fraction, 1 / mesh multiplier, or a rung's step
  std::string refined = "dt";  ///< what is refined: "dt", "fraction", "mesh", or the rungs' `refined` name
  std::optional<jobs::JobSpec> reference;  ///< when set, errors are against it (e.g. the exact solution)
  std::string tier = "quick";
  bool required = true;
  std::vector<Gate> gates;  ///< min_order (and optionally tol on the finest pair)
  std::string note;
  /// @brief "s1_central paper dt=0.01/0.005/0.0025".
  std::string name() const;
};

/// @brief Health checks of one run, no reference (the stability tier): gates on the metrics of
/// check_run() (energy band, tension, friction cone, real penetration, momentum drift).
struct RunCheck {
  jobs::JobSpec run;
  std::string tier = "stability";
  bool required = true;
  std::vector<Gate> gates;
  std::string note;
  /// @brief "two_contacts_pushed paper checks".
  std::string name() const;
};

/// @brief The whole matrix file.
struct VerificationMatrix {
  std::filesystem::path file;
  std::filesystem::path root;  ///< repository root: scene paths are relative to it
  double timeout = 900.0;      ///< s, per run
  std::vector<Case> cases;
  std::vector<Convergence> convergence;
  std::vector<RunCheck> checks;

  /// @brief Reads and checks a matrix file. Throws InputError (file, key, what was expected) for
  /// unknown keys, unknown metrics, gates without a tolerance or reason, and missing scenes.
  static VerificationMatrix load(const std::filesystem::path& file);
  /// @brief Every distinct run needed by the cases, ladders and checks of a tier.
  std::vector<jobs::JobSpec> runs(const std::string& tier) const;
  /// @brief The tiers: "quick" (CI), "stability" (hard cases' health checks), "full" (all items,
  /// plus fine meshes and small steps).
  static const std::vector<std::string>& tier_names();
  /// @brief True when an item of tier `item` belongs to a run of tier `tier` ("full" runs all).
  static bool in_tier(const std::string& item, const std::string& tier) {
    return tier == "full" || item == tier;
  }
};

}  // namespace beamimpact::verification
