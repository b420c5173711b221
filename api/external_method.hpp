#pragma once
/// @file external_method.hpp
/// @brief Runs an external method of the registry (docs/protocol.md): the scene file in, its
/// command with the placeholders filled, history.csv and summary.json out.

#include <filesystem>
#include <string>
#include <vector>

#include <api/registry.hpp>

namespace beamimpact {

/// @brief The values of one run's placeholders (an empty value: not asked for).
struct ExternalRun {
  std::filesystem::path scene;  ///< {scene}: the scene file the program reads
  std::filesystem::path out;    ///< {out}: the run directory
  std::string dt;               ///< {dt}: s, the step asked for
  std::string mesh;             ///< {mesh}: element multiplier or the method's preset
  std::string end;              ///< {end}: s, the end time
};

/// @brief The method's command for this run. An argument whose placeholder has no value is left
/// out, together with the option just before it (an argument starting with '-').
std::vector<std::string> external_argv(const Method& m, const ExternalRun& run);

/// @brief Where run_external() moves the summary.json of a run whose outputs break a rule
/// (api/output_rules.hpp): kept for the user to read, never taken for a finished run.
inline constexpr const char* kRejectedSummary = "summary.rejected.json";

/// @brief Runs the external method on the scene into `out` (the scene's overrides are written
/// to out/scene.toml, which the program then reads). Its output goes to out/method.log, echoed
/// on stderr after a failure or when progress is shown (Progress::enabled). Exit 0: the outputs are
/// checked by every output rule (check_outputs()); one broken is std::runtime_error naming the rule,
/// and summary.json is moved to kRejectedSummary. Otherwise the result's summary keys are read back
/// (the run directory holds the rest). Exit 2: InputError "not
/// applicable: ..." with the program's last line. Otherwise std::runtime_error; a summary.json left by a
/// failed run is removed.
/// @param m the method; @param scene the scene; @param out the run directory
/// @param mesh the mesh asked for ("" none)
SimulationResult run_external(const Method& m, const Scene& scene, const std::filesystem::path& out,
                              const std::string& mesh);

/// @brief The last non-blank line of a text file ("" when none): an exit-2 program's reason.
std::string last_line(const std::filesystem::path& file);

}  // namespace beamimpact
