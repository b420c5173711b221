#pragma once
/// @file solve_ball_on_beam.hpp
/// @brief `--method exact` on a ball-on-beam scene (a free rigid striker onto a simply supported
/// Euler-Bernoulli beam through a Hertz spring): BallOnBeam's converged modal solution as the
/// run's history and summary.

#include <references/exact/BallOnBeam.hpp>
#include <references/exact/beam_mode_options.hpp>
#include <references/exact/recognise_scene.hpp>
#include <solver/record/ResultRecorder.hpp>

namespace beamimpact::exact {

/// @brief The physical data of the recognised problem p (kind kBallOnBeam): striker, spring,
/// beam, struck point, approach speed and gap; the caller sets modes, span and tolerance.
BallOnBeamSetup ball_on_beam_setup(const ExactProblem& p);

/// @brief Solves the recognised problem p (kind kBallOnBeam) with the [exact] options o; the
/// mode study (or the fixed count) and the cost estimate are written into the summary.
/// Throws InputError (exit 2) when the solution is far beyond an ordinary run.
SimulationResult solve_ball_on_beam_scene(const Scene& scene, const ExactProblem& p, const BeamModeOptions& o,
                                          ResultRecorder& rec);

}  // namespace beamimpact::exact
