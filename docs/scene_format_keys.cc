/// @file scene_format_keys.cc
/// @brief Lists, from the code itself, what docs/scene-format.md must document; prints one JSON
/// object that docs/check_scene_format.py compares with the page (ctest scene_format_doc).
///
/// - "scene_keys": every key that the scene reader and the in-process methods' option readers
///   ask about (TableReader's KeyLog) while the scenes below are read and run with paper, exact
///   and ida: the keys they accept, since a reader refuses every key it did not ask about. Array
///   indices are dropped ("bodies[0].supports[1].fix" -> "bodies.supports.fix"). The scenes give
///   every table that has keys of its own ([[bodies]] supports, [[loads.point]], each method's
///   table) and leave out the keys that switch a reader to another branch ([exact] modes, [ida]
///   kn, cn): a reader asks about every key of its table on the branch taken then. One more
///   scene is only read, with the other branches of the scene reader (dt = "auto", a rigid body,
///   a Timoshenko body, the Hertz law, a contact search).
/// - "history_columns": the time column, the contact and model columns, the optional columns
///   (solver/schema/output_schema.hpp), and "state_values" (the codes of column `state`).
/// - "summary": the keys of the summary.json of each run (summary_json(), what `beamimpact run`
///   writes): "" for the top level, and for each object or array of objects at the top level
///   its keys under its name ("contacts", "critical_step", ...).

#include <cstdio>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <references/exact/solve.hpp>
#include <references/ida/solve.hpp>
#include <solver/paper/solve.hpp>
#include <solver/record/output_files.hpp>
#include <solver/scene/TableReader.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/schema/output_schema.hpp>
#include <solver/util/Progress.hpp>

namespace {

using nlohmann::json;

/// The paper's S2 (a vertical rod onto the midspan of a simply supported beam, first touch at
/// 0.1 s), shortened to its first impact: a scene every in-process method runs in well under a
/// second, the exact one as a rod on a beam.
const std::string kBase = R"(
name = "keys"
description = "docs/scene_format_keys.cc"
[time]
dt = 0.01
end = 0.3
[[bodies]]
name = "A"
start = [5.0, 5.1]
end = [5.0, 0.1]
elements = 5
E = 100.0
rho = 1.0
area = 0.4
inertia = 0.0053333333333333
velocity = [0.0, -1.0]
[[bodies]]
name = "B"
start = [0.0, 0.0]
end = [10.0, 0.0]
elements = 10
E = 100.0
rho = 1.0
area = 0.4
inertia = 0.0053333333333333
supports = [{ at = "start", fix = ["x", "y"] }, { at = "end", fix = ["y"] }]
[[contacts]]
striker = "A"
node = "end"
target = "B"
)";

/// The tables the base scene leaves out, for the paper's run.
const std::string kPaperTables = R"(
[model]
mass = "lumped"
[loads]
gravity = [0.0, -0.01]
[[loads.point]]
body = "B"
node = 5
force = [0.0, 0.01]
[effects]
bending = true
[output]
history = true
[paper]
merge_steps = 3
)";

/// The base scene's other branches, as --set overrides.
const std::vector<std::string> kOtherBranches = {
    "time.dt=\"auto\"",          "bodies[0].rigid=true",      "bodies[1].theory=\"timoshenko\"",
    "contacts[0].law=\"hertz\"", "contacts[0].stiffness=1e3", "contacts[0].node=\"all\""};

/// "bodies[0].supports[1].fix" -> "bodies.supports.fix".
std::string without_indices(const std::string& key) {
  static const std::regex index(R"(\[[0-9]+\])");
  return std::regex_replace(key, index, "");
}

/// The keys of each object (or array of objects) at the top level of a summary.json document,
/// added to `out` under its name; the top level's own keys under "".
void add_summary_keys(const json& summary, std::map<std::string, std::set<std::string>>& out) {
  for (const auto& [key, value] : summary.items()) {
    out[""].insert(key);
    if (value.is_object())
      for (const auto& [sub, unused] : value.items()) out[key].insert(sub);
    if (value.is_array())
      for (const json& entry : value)
        if (entry.is_object())
          for (const auto& [sub, unused] : entry.items()) out[key].insert(sub);
  }
}

json history_columns_json() {
  using namespace beamimpact;
  json cols = json::array({"t"});
  for (const std::string& c : contact_columns()) cols.push_back(c);
  for (const std::string& c : model_columns()) cols.push_back(c);
  const json schema = schema_json();
  for (const auto& [name, meaning] : schema.at("optional_columns").items()) cols.push_back(name);
  return {{"columns", cols}, {"state_values", schema.at("state_values")}};
}

}  // namespace

int main() {
  using namespace beamimpact;
  Progress::set_enabled(false);
  std::map<std::string, std::set<std::string>> summary;
  std::set<std::string> scene_keys;
  try {
    const KeyLog log;
    const Scene paper_scene = load_scene_text(kBase + kPaperTables, "paper scene");
    add_summary_keys(summary_json(paper_scene, paper::solve(paper_scene)), summary);
    // A rod on a beam: the exact method's mode study, whose keys it asks about when [exact]
    // gives no fixed mode count (a small study keeps the run short).
    const Scene exact_scene =
        load_scene_text(kBase + "[exact]\nmodes_min = 4\nmodes_max = 8\n", "exact scene");
    add_summary_keys(summary_json(exact_scene, exact::solve(exact_scene)), summary);
    const Scene ida_scene = load_scene_text(kBase + "[ida]\nrtol = 1e-6\n", "ida scene");
    add_summary_keys(summary_json(ida_scene, ida::solve(ida_scene)), summary);
    (void)load_scene_text(kBase, "other branches", kOtherBranches);
    for (const std::string& key : log.keys()) scene_keys.insert(without_indices(key));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "scene_format_keys: %s\n", e.what());
    return 1;
  }
  json out = {{"scene_keys", scene_keys}, {"history", history_columns_json()}, {"summary", json::object()}};
  for (const auto& [name, keys] : summary) out["summary"][name] = keys;
  std::printf("%s\n", out.dump(1).c_str());
  return 0;
}
