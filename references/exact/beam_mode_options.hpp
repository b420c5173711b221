#pragma once
/// @file beam_mode_options.hpp
/// @brief The [exact] options of the solutions with a modal beam (rod on beam, ball on beam).

namespace beamimpact::exact {

/// @brief How many modes, and how the mode study and the integrator are run.
struct BeamModeOptions {
  long modes = 0;                        ///< fixed number of modes; 0: a convergence study
  long modes_min = 16, modes_max = 512;  ///< the study's first and largest mode counts
  double tol = 1e-3;                     ///< the study's relative change per doubling
  double rtol = 1e-10;                   ///< rk8pd relative tolerance
};

}  // namespace beamimpact::exact
