#pragma once
/// @file conform.hpp
/// @brief The conformance check of an external method (docs/protocol.md): its program run on a
/// small set of scenes (valid scenes of each kind, scenes it should refuse, a malformed scene),
/// every rule of the protocol checked on what it wrote and how it exited.

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

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

/// @brief What `beamimpact conform` checks, and where: the options of the command and of the
/// Python module's conform().
struct ConformOptions {
  std::string method;         ///< the external method checked (`beamimpact methods`)
  std::filesystem::path out;  ///< runs/, scenes/, junit.xml, conform.json; "": conform-NAME (out_dir())
  double timeout = 600.0;     ///< s, per run (> 0)
  /// The conformance scenes to run (conform_scene_names(); empty: all); the malformed scene is
  /// always run.
  std::vector<std::string> scenes;

  /// @brief Throws InputError naming the option and what was expected: a method that is unknown,
  /// built in or cannot run here, a timeout that is no number of seconds > 0, a scene name that is
  /// not a conformance scene's.
  void validate() const;
  /// @brief `out`, or conform-NAME when it is empty.
  std::filesystem::path out_dir() const;
};

/// @brief JUnit XML of a conformance check: one test case per rule and run, a failure naming the
/// rule and the file.
void write_conform_junit(const std::filesystem::path& file, const std::string& method,
                         const std::vector<RuleResult>& results);

/// @brief What a conformance check found, and its one verdict: passed when no rule is broken (a
/// scene refused with exit 2 and a reason is not applicable, not a check).
struct ConformResult {
  std::string method;   ///< the method checked
  std::string origin;   ///< the methods file that declared it
  std::string command;  ///< the command line that makes this check again
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

/// @brief Runs the external method o.method on the conformance set into o.out_dir() (runs/,
/// scenes/) and checks every rule on what it wrote and how it exited. A scene the program refuses
/// with exit 2 and one line of reason is not applicable (a RuleResult with skipped = true),
/// whatever the method declares; only a broken rule fails. Throws InputError for bad options
/// (validate()), an unknown or built-in method, or one whose program cannot run here.
ConformResult conform(const ConformOptions& o);

/// @brief conform.json's document: the rules, every result, the counts, the verdict and how it was
/// made (the data of the page `reports/render.py conform DIR` renders).
nlohmann::json conform_json(const ConformOptions& o, const ConformResult& r);

/// @brief Writes o.out_dir()/junit.xml and conform.json (conform_json). Returns the two files.
std::vector<std::filesystem::path> write_conform_reports(const ConformOptions& o, const ConformResult& r);

}  // namespace beamimpact::verification
