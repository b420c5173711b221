#pragma once
/// @file RodOnBeam.hpp
/// @brief Semi-analytic solution of an elastic rod striking a simply supported Euler-Bernoulli
/// or Timoshenko beam end-on (references.md section 2): exact rod waves with reflection memory, a
/// truncated modal sum for the beam (BeamModes.hpp), integrated by GSL's rk8pd between breakpoints, with
/// contact onset, separation and re-contact located by Brent root finding on the event functions.

#include <array>
#include <vector>

#include <references/exact/BeamModes.hpp>
#include <references/exact/CoaxialRods.hpp>
#include <references/exact/DelayMemory.hpp>
#include <references/exact/Rod.hpp>
#include <references/exact/SimpleBeam.hpp>

namespace beamimpact::exact {

/// @brief Problem data and numerical settings.
struct RodOnBeamSetup {
  Rod rod;           ///< striker, moving along its axis towards the beam
  SimpleBeam beam;   ///< target, pinned at both ends for transverse motion
  BeamShear shear;   ///< the target's shear data when it is a Timoshenko beam (default: Euler-Bernoulli)
  double x_c = 0.0;  ///< m, struck point measured from the beam's first end, 0 < x_c < L
  double v0 = 0.0;   ///< m/s, rod speed towards the beam
  double gap = 0.0;  ///< m, initial gap between rod end and beam axis
  int modes = 32;  ///< number of beam modes kept, the lowest by frequency (both Timoshenko branches counted)
  double t_end = 0.0;      ///< s
  double dt_out = 0.0;     ///< s, output rows at k dt_out, k = 0, 1, ... while <= t_end
  double rtol = 1e-10;     ///< rk8pd relative tolerance (absolute: rtol x natural scales)
  bool rod_fields = true;  ///< integrate the rod's kinetic/strain split for each row
};

/// @brief One output row (rod quantities positive along the rod's velocity; w positive
/// in the same direction, i.e. the beam pushed away from the rod).
struct RodOnBeamRow {
  double t = 0.0;                                ///< s
  double P = 0.0;                                ///< N, contact force
  double gap = 0.0;                              ///< m
  double u = 0.0, du = 0.0;                      ///< m, m/s: rod end displacement and velocity
  double w = 0.0, dw = 0.0;                      ///< m, m/s: beam deflection and velocity at the struck point
  double impulse = 0.0;                          ///< N s, integral of P so far
  double rod_work = 0.0;                         ///< J, work of P on the rod end (the rod's energy loss)
  double beam_kinetic = 0.0, beam_strain = 0.0;  ///< J, modal sums
  double beam_momentum = 0.0;                    ///< N s, along the rod velocity
  RodField rod;         ///< rod kinetic/strain/momentum from its wave field (if asked)
  bool closed = false;  ///< in contact
};

/// @brief Everything the run produced.
struct RodOnBeamSolution {
  std::vector<RodOnBeamRow> rows;
  std::vector<std::array<double, 2>> intervals;  ///< s, contact intervals from the located events
  double impulse = 0.0;                          ///< N s, integral of P over [0, t_end]
  double peak_P = 0.0;                           ///< N
  double first_P = 0.0;                          ///< N, just after first touch (= Z_A v0)
  double w_max = 0.0, t_w_max = 0.0;             ///< m, s: largest deflection under the struck point
  double w_min = 0.0;                            ///< m, most negative deflection (rebound side)
  double energy_error = 0.0;  ///< J, max |beam modal energy - work of P on the beam| (should be ~rtol)
  long steps = 0;             ///< accepted + rejected rk8pd steps
  long pieces = 0;            ///< smooth pieces integrated (breakpoints and events)
  long events = 0;            ///< located onsets/separations after the first touch
  int modes = 0;
  double sample_dt = 0.0;  ///< s, spacing of the stored reflection-memory samples
};

/// @brief Runs the semi-analytic solution for a fixed number of modes.
class RodOnBeam {
 public:
  /// @brief Solves the problem (the work is done here).
  explicit RodOnBeam(const RodOnBeamSetup& setup);
  /// @brief The result.
  const RodOnBeamSolution& solution() const { return sol_; }
  /// @brief The rod's reflection memory R(s) = P(s) + R(s - T_A) (N).
  const DelayMemory& memory() const { return mem_; }
  /// @brief Kinetic, strain energy and momentum of the rod from its wave field at t.
  RodField rod_field(double t) const;
  /// @brief Fills RodOnBeamRow::rod of every row (done by the constructor when
  /// RodOnBeamSetup::rod_fields is set).
  void compute_rod_fields();

 private:
  void run();
  RodOnBeamSetup s_;
  RodOnBeamSolution sol_;
  DelayMemory mem_;
};

/// @brief One entry of a mode-convergence study.
struct ModeStudyEntry {
  int modes = 0;
  double impulse = 0.0;                          ///< N s
  std::vector<std::array<double, 2>> intervals;  ///< s
  double w_max = 0.0;                            ///< m
};

/// @brief Result of choosing the number of modes.
struct ModeStudy {
  RodOnBeamSolution solution;         ///< of the finest run
  std::vector<ModeStudyEntry> table;  ///< every run, coarse to fine
  bool converged = false;             ///< criterion met before modes_max
  double impulse_change = 0.0;        ///< relative change of the impulse in the last doubling
  double time_change = 0.0;           ///< s, largest change of an interval end in the last doubling
};

/// @brief Doubles the mode count from modes_min until impulse and contact times change by
/// less than tol (relative to the impulse, and to the first contact's duration) between two
/// runs with the same number of intervals, or modes_max is reached. The rod's field split is
/// computed only for the final run.
ModeStudy converge_modes(RodOnBeamSetup setup, int modes_min, int modes_max, double tol);

}  // namespace beamimpact::exact
