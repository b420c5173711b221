#pragma once
/// @file solve.hpp
/// @brief The method "paper": the Pu & Chi (2011) explicit dynamic-contact integrator run on a
/// scene, start to end.

#include <filesystem>
#include <string>

#include <solver/contact/ContactPair.hpp>
#include <solver/contact/ContactSolver.hpp>
#include <solver/record/ContactIntervals.hpp>
#include <solver/record/SimulationResult.hpp>

namespace beamimpact::paper {

/// @brief The scene's [paper] table, read and validated in one place.
struct Options {
  long merge_steps =
      kMergeSteps;         ///< contact phases separated by fewer open steps than this are one interval
  double merge_gap = 0.0;  ///< s; when > 0, phases closer than this are merged instead (dt-independent)
  SurfaceInterpolation surface = SurfaceInterpolation::kLinear;  ///< "linear" (paper) or "hermite"
  ClosureSlip closure_slip = ClosureSlip::kWholeStep;            ///< "step" (paper) or "from_closure"
  int threads = 0;  ///< threads of the step's element sweep; 0 = default_threads() of the model

  /// @brief Reads [paper] of `scene`; defaults not given are recorded in `assumed`. Throws
  /// InputError naming the file and key for a bad value or an unknown key.
  static Options read(const Scene& scene, std::map<std::string, std::string>* assumed);
};

/// @brief Runs the scene with the paper's integrator. Throws InputError for bad settings
/// (dt above the critical step) and std::runtime_error if the run diverges.
/// @param scene the scene
/// @param fields_dir when not empty, the run directory that receives the VTK fields of every
/// output row (record/FieldWriter.hpp; the API passes it when [output] fields = true)
/// @param threads the run's thread count (RunOptions::threads, `--threads`; valid_thread_count()),
/// taken over [paper] threads; 0: the scene's, else default_threads() of the model
SimulationResult solve(const Scene& scene, const std::filesystem::path& fields_dir = {}, int threads = 0);

}  // namespace beamimpact::paper
