#pragma once
/// @file BallOnBeam.hpp
/// @brief Semi-analytic solution of Timoshenko's ball on a beam: a rigid striker of mass m hits
/// a simply supported Euler-Bernoulli beam through a Hertz spring R = k delta^(3/2) (delta > 0,
/// the indentation: the striker's advance past the beam point under it). The beam is a truncated
/// modal sum; the N modes, the striker and the impulse are integrated by GSL's rk8pd to
/// tolerance; the ends of each contact (delta through 0) and each contact's peak force (the
/// indentation rate through 0) are located by Brent's method, and the integration restarts at
/// every contact end. The contact may open and close again (sub-impacts).

#include <array>
#include <vector>

#include <references/exact/SimpleBeam.hpp>

namespace beamimpact::exact {

/// @brief Problem data and numerical settings.
struct BallOnBeamSetup {
  double mass = 0.0;       ///< kg, rigid striker
  double stiffness = 0.0;  ///< N/m^1.5, k of the Hertz spring
  SimpleBeam beam;         ///< target, pinned at both ends for transverse motion
  double x_c = 0.0;        ///< m, struck point from the beam's first end, 0 < x_c < L
  double v0 = 0.0;         ///< m/s, striker speed towards the beam
  double gap = 0.0;        ///< m, initial gap between the striker's contact point and the beam axis
  int modes = 32;          ///< number of beam modes kept
  double t_end = 0.0;      ///< s
  double dt_out = 0.0;     ///< s, output rows at k dt_out, k = 0, 1, ... while <= t_end
  double rtol = 1e-10;     ///< rk8pd relative tolerance (absolute: rtol x natural scales)
};

/// @brief One output row (displacements positive along the striker's velocity: w > 0 pushes the
/// beam away from the striker).
struct BallOnBeamRow {
  double t = 0.0;                                ///< s
  double R = 0.0;                                ///< N, contact force
  double gap = 0.0;                              ///< m, -delta (negative while the spring is compressed)
  double z = 0.0, dz = 0.0;                      ///< m, m/s: striker displacement and velocity
  double w = 0.0, dw = 0.0;                      ///< m, m/s: beam deflection and velocity at the struck point
  double impulse = 0.0;                          ///< N s, integral of R so far
  double beam_kinetic = 0.0, beam_strain = 0.0;  ///< J, modal sums
  double spring = 0.0;                           ///< J, 2/5 k delta^(5/2)
  double beam_momentum = 0.0;                    ///< N s, along the striker's velocity
};

/// @brief Everything the run produced.
struct BallOnBeamSolution {
  std::vector<BallOnBeamRow> rows;
  std::vector<std::array<double, 2>> intervals;  ///< s, contact intervals (delta > 0) from located events
  std::vector<double> interval_impulses;         ///< N s, impulse of each interval
  std::vector<double> interval_peaks;            ///< N, peak force of each interval
  double impulse = 0.0;                          ///< N s, integral of R over [0, t_end]
  double peak_R = 0.0, t_peak = 0.0;             ///< N, s: largest contact force and its time
  double delta_max = 0.0;                        ///< m, largest indentation
  double w_max = 0.0, t_w_max = 0.0;             ///< m, s: largest deflection under the struck point
  double final_velocity = 0.0;                   ///< m/s, striker at t_end (v0 - impulse / m)
  double energy_error = 0.0;  ///< J, max |energy - m v0^2 / 2| over the rows (should be ~rtol)
  long steps = 0;             ///< rk8pd steps (accepted + rejected)
  int modes = 0;
  double stop_dt = 0.0;  ///< s, spacing of the stops at which contact changes are looked for
};

/// @brief Contact time of the striker on a rigid half-space through the same spring (s):
/// 2.9432 delta_max / v0 with delta_max = (5 m v0^2 / (4 k))^(2/5) (Johnson 1985, section 11.4).
double half_space_contact_time(double mass, double stiffness, double v0);

/// @brief Spacing of the integrator's stops (s): a quarter radian of the top mode, and at most
/// 1/400 of the half-space contact time, so that no contact change of the striker is missed.
double ball_stop_spacing(const BallOnBeamSetup& setup, int modes);

/// @brief Runs the semi-analytic solution for setup.modes modes.
BallOnBeamSolution solve_ball_on_beam(const BallOnBeamSetup& setup);

/// @brief One entry of a mode-convergence study.
struct BallModeEntry {
  int modes = 0;
  double impulse = 0.0;                          ///< N s
  double peak_R = 0.0;                           ///< N
  std::vector<std::array<double, 2>> intervals;  ///< s
};

/// @brief Result of choosing the number of modes.
struct BallModeStudy {
  BallOnBeamSolution solution;       ///< of the finest run
  std::vector<BallModeEntry> table;  ///< every run, coarse to fine
  bool converged = false;            ///< criterion met before modes_max
  double change =
      0.0;  ///< largest relative change of impulse, peak force and contact times in the last doubling
};

/// @brief Doubles the mode count from modes_min until the impulse, the peak force and the
/// contact times (relative to the first contact's duration) change by less than tol between two
/// runs with the same number of contacts, or modes_max is reached.
BallModeStudy converge_ball_modes(BallOnBeamSetup setup, int modes_min, int modes_max, double tol);

}  // namespace beamimpact::exact
