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
  std::string message;  ///< what was found when it does not (and what was expected); a refusal's reason
  /// True for a scene the program refused with exit 2 and a reason (rule "not applicable"): no
  /// verdict, whatever the method declares.
  bool skipped = false;
};

/// @brief The conformance scenes' names, for `conform --scenes` (end_to_end, transverse,
/// node_to_surface, oblique_rotation, rigid_friction, two_contacts, friction).
const std::vector<std::string>& conform_scene_names();

/// @brief The protocol's rules, in checklist order, with one line each (docs/protocol.md): exit
/// code, the output rules of api/output_rules.hpp, columns, reason, no summary after failure, same
/// result twice.
const std::vector<std::pair<std::string, std::string>>& protocol_rules();

/// @brief Runs the external method `m` on the conformance set and checks every rule.
/// @param m an external method; @param data_root the folder holding verification/scenes/
/// A scene the program refuses with exit 2 and one line of reason is not applicable (a
/// RuleResult with skipped = true), whatever the method declares; only a broken rule fails.
/// @param out the output directory (runs/, scenes/); @param timeout_seconds per run
/// @param scenes the conformance scenes to run (conform_scene_names(); empty: all); the malformed
/// scene is always run. Throws InputError for an unknown name.
std::vector<RuleResult> conform(const Method& m, const std::filesystem::path& data_root,
                                const std::filesystem::path& out, double timeout_seconds,
                                const std::vector<std::string>& scenes = {});

/// @brief JUnit XML of a conformance check: one test case per rule and run, a failure naming the
/// rule and the file.
void write_conform_junit(const std::filesystem::path& file, const std::string& method,
                         const std::vector<RuleResult>& results);

/// @brief What a conformance check found, and its one verdict: passed when no rule is broken (a
/// scene refused with exit 2 and a reason is not applicable, not a check).
struct ConformResult {
  std::string method;  ///< the method checked
  std::string origin;  ///< the methods file that declared it
  std::vector<RuleResult> results;
  /// @brief Checks that broke a rule.
  int broken() const;
  /// @brief Scenes the program refused with exit 2 and a reason.
  int not_applicable() const;
  /// @brief Checks made (results less the not-applicable scenes).
  int checks() const;
  /// @brief True when no rule is broken.
  bool passed() const { return broken() == 0; }
};

/// @brief Writes dir/junit.xml and dir/conform.json (the rules, every result, the counts and how
/// it was made: the data of the page `reports/render.py conform DIR` renders).
/// @param dir the conform output folder; @param r the result; @param command the command line
/// @param timeout_seconds the time limit per run it was made with
void write_conform_reports(const std::filesystem::path& dir, const ConformResult& r,
                           const std::string& command, double timeout_seconds);

}  // namespace beamimpact::verification
