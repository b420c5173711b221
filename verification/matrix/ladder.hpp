#pragma once
/// @file ladder.hpp
/// @brief The resolution ladder of `beamimpact score` on a scene with an exact answer: the method
/// run at successively refined resolutions, and each gated scalar's observed order and
/// Richardson-extrapolated limit with its uncertainty, judged against the exact value. The
/// arithmetic is the verification matrix's (evaluate.hpp: richardson_limit, observed_order).

#include <optional>
#include <string>
#include <vector>

#include <api/registry.hpp>
#include <verification/jobs/JobSpec.hpp>

namespace beamimpact::verification {

/// @brief The refinement ratio between consecutive rungs (mesh x2 and/or dt / 2).
inline constexpr double kLadderRatio = 2.0;

/// @brief Roache's safety factor on the extrapolation's own error estimate (the matrix's
/// `richardson` gates use the same 1.25 for three rungs).
inline constexpr double kRichardsonFactor = 1.25;

/// @brief The least observed order a converging method shows; below it the quantity is "not
/// converged".
inline constexpr double kLeastOrder = 0.5;

/// @brief Rungs whose values differ by less than this, relative to the values, agree (a quantity
/// the scheme gets exact at every resolution, up to the round-off of a whole run): their limit is
/// the finest rung's value and no order is observed.
inline constexpr double kAgreement = 1e-10;

/// @brief The runs of a method's ladder on one scene.
struct LadderPlan {
  /// "mesh+dt" (elements x2 and dt / 2 a rung: the Courant number kept), "mesh" (elements x2,
  /// the step following from the scene), "dt" (dt / 2 a rung, the mesh kept: the limit is the
  /// method's semi-discrete answer) or "" (no ladder).
  std::string kind;
  std::string why;                   ///< in words: what is refined, or why there is no ladder
  std::vector<jobs::JobSpec> rungs;  ///< coarse to fine; rungs[0] is the scene as written
};

/// @brief Plans the ladder of `rungs` runs of `base` (a run at the scene's own settings): mesh and
/// dt together when the method accepts both (only a refined mesh converges to the continuum's
/// exact answer; dt follows it to keep the Courant number), the mesh alone when the scene's dt is
/// "auto" or the method takes no dt, dt alone when it takes no mesh factor; none otherwise.
/// @param base the run at the scene's settings (no dt, no mesh)
/// @param method the method's registry entry (Method::Accepts)
/// @param rungs how many runs, >= 3
LadderPlan plan_ladder(const jobs::JobSpec& base, const Method& method, int rungs);

/// @brief One gated scalar along a ladder.
struct LadderResult {
  std::vector<double> values;         ///< the method's value at each rung, coarse to fine
  std::optional<double> order;        ///< observed order of the last three rungs (none: rungs agree)
  std::optional<double> limit;        ///< the extrapolated limit (none: not converged)
  std::optional<double> uncertainty;  ///< of the limit, in the quantity's own unit
  std::string why_not;                ///< why there is no limit ("" when there is one)
};

/// @brief The limit of a quantity from its rungs (ratio r = kLadderRatio). Rungs that agree
/// within kAgreement of their values, or within `agree`: the finest value, uncertainty their
/// spread (refinement changes the quantity by less than it matters). Else the Richardson limit
/// Q_R = Q_n - (Q_{n-1} - Q_n) / (r^p - 1) of the last three rungs (richardson_limit) with their
/// own observed order p. Its uncertainty U is how far the limit moves when the order is the whole
/// order nearest p (at least 1), |Q_R(p) - Q_R(round(p))|: zero in a clean asymptotic range, a
/// large part of |Q_R - Q_n| when the rungs are not yet in one; with four or more rungs at least
/// |Q_R - Q_R'|, Q_R' the limit of the three rungs before (a limit that moves). No limit ("not
/// converged") when the differences do not shrink monotonically or p < kLeastOrder.
/// @param values the quantity at each rung, coarse to fine
/// @param agree a spread of the rungs below which they agree, in the quantity's unit (0: none)
LadderResult ladder_limit(const std::vector<double>& values, double agree = 0.0);

}  // namespace beamimpact::verification
