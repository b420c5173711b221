#pragma once
/// @file conform.hpp
/// @brief The conformance check of an external method (docs/protocol.md): its program run on a
/// small set of scenes (valid scenes of each kind, scenes it should refuse, a malformed scene),
/// every rule of the protocol checked on what it wrote and how it exited.

#include <filesystem>
#include <string>
#include <vector>

#include <api/registry.hpp>

namespace beamimpact::verification {

/// @brief One rule checked on one run.
struct RuleResult {
  std::string rule;     ///< the protocol's rule ("columns", "exit code", ...)
  std::string scene;    ///< the conformance scene's name
  std::string file;     ///< the file the verdict is about (history.csv, summary.json, run.log, ...)
  bool passed = false;  ///< true when the rule holds
  std::string message;  ///< what was found when it does not (and what was expected)
};

/// @brief The protocol's rules, in checklist order, with one line each (docs/protocol.md).
const std::vector<std::pair<std::string, std::string>>& protocol_rules();

/// @brief Runs the external method `m` on the conformance set and checks every rule.
/// @param m an external method; @param data_root the folder holding verification/scenes/
/// @param out the output directory (runs/, scenes/); @param timeout_seconds per run
std::vector<RuleResult> conform(const Method& m, const std::filesystem::path& data_root,
                                const std::filesystem::path& out, double timeout_seconds);

/// @brief JUnit XML of a conformance check: one test case per rule and run, a failure naming the
/// rule and the file.
void write_conform_junit(const std::filesystem::path& file, const std::string& method,
                         const std::vector<RuleResult>& results);

}  // namespace beamimpact::verification
