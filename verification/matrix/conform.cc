#include <verification/matrix/conform.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <beamimpact/version.hpp>
#include <nlohmann/json.hpp>

#include <api/accepts.hpp>
#include <api/child_process.hpp>
#include <api/external_method.hpp>
#include <api/output_rules.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/schema/output_schema.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/write_file_atomic.hpp>
#include <verification/matrix/protocol_inputs.hpp>
#include <verification/matrix/reports.hpp>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;

/// One scene of the conformance set and what the method must do with it.
struct ConformScene {
  std::string name;
  fs::path file;
  int expect_exit = 0;  ///< 0: accepted; 2: refused (not accepted) or malformed
  std::string why;      ///< why exit 2 is expected
};

std::string read_text(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// The shipped scenes of each kind, a friction variant, and a malformed scene; the expected exit
/// code of each from what the method declares it accepts (the check api::run makes).
std::vector<ConformScene> conformance_set(const Method& m, const fs::path& root, const fs::path& dir,
                                          const std::vector<std::string>& only) {
  fs::create_directories(dir);
  const fs::path scenes = root / "verification/scenes";
  std::vector<ConformScene> set = {
      {"end_to_end", scenes / "paper/s1_central.toml", 0, ""},
      {"transverse", scenes / "paper/s2_transverse.toml", 0, ""},
      {"node_to_surface", scenes / "paper/s3_surface_10.toml", 0, ""},
      {"oblique_rotation", scenes / "paper/s4_oblique_45.toml", 0, ""},
      {"rigid_friction", scenes / "extra/rigid_rod_oblique.toml", 0, ""},
      {"two_contacts", scenes / "hard/two_contacts_pushed.toml", 0, ""},
  };
  const Scene s1 = load_scene(scenes / "paper/s1_central.toml", {"contacts[0].friction=0.3"});
  write_file_atomic(dir / "friction.toml", scene_toml(s1));
  set.push_back({"friction", dir / "friction.toml", 0, ""});
  if (!only.empty())
    set.erase(std::remove_if(set.begin(), set.end(),
                             [&](const ConformScene& c) {
                               return std::find(only.begin(), only.end(), c.name) == only.end();
                             }),
              set.end());
  for (ConformScene& c : set) {
    try {
      check_accepts(m, load_scene(c.file), "");
    } catch (const InputError& e) {
      c.expect_exit = 2;
      c.why = e.what();
    }
  }
  write_file_atomic(dir / "malformed.toml",
                    read_text(scenes / "paper/s1_central.toml") + "\n[time\nend = \n");
  set.push_back({"malformed", dir / "malformed.toml", 2, "a TOML syntax error"});
  return set;
}

/// What one run of the program did.
struct Ran {
  ProcessResult process;
  fs::path dir, log;
};

Ran run_program(const Method& m, const ConformScene& c, const fs::path& dir, double timeout) {
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  Ran r{{}, dir, dir / "run.log"};
  double end = 0.0;
  try {
    end = load_scene(c.file).time.end;
  } catch (const InputError&) {  // the malformed scene: no end time to offer
  }
  ExternalRun run{c.file, dir, "", "", end > 0.0 ? fmt::format("{:.17g}", end) : ""};
  r.process = spawn_and_wait(external_argv(m, run), r.log, timeout);
  return r;
}

class Checker {
 public:
  explicit Checker(std::vector<RuleResult>& out) : out_(out) {}
  /// Records the verdict of `rule` on `file` of scene `scene`.
  bool operator()(const std::string& rule, const std::string& scene, const fs::path& file, bool ok,
                  const std::string& message) {
    out_.push_back({rule, scene, file.string(), ok, ok ? "" : message, false});
    return ok;
  }
  /// Records a scene the program refused (exit 2 with its reason): not applicable, no verdict.
  void not_applicable(const std::string& scene, const fs::path& file, const std::string& reason) {
    out_.push_back({"not applicable", scene, file.string(), true, reason, true});
  }

 private:
  std::vector<RuleResult>& out_;
};

std::string exit_text(const ProcessResult& p) {
  return p.error.empty() ? fmt::format("exit code {}", p.exit_code) : p.error;
}

/// Columns: history.csv names only schema columns and one R per scene contact (its numbers are
/// the output rules' finite and times).
void check_columns(Checker& check, const std::string& scene, const fs::path& dir, std::size_t contacts) {
  const fs::path csv = dir / "history.csv";
  HistoryTable h;
  try {
    h = read_history_table(csv);
  } catch (const std::exception& e) {
    check("columns", scene, csv, false, e.what());
    return;
  }
  const std::vector<std::string> known = history_columns(static_cast<int>(contacts));
  std::string unknown;
  for (const std::string& name : h.names)
    if (std::find(known.begin(), known.end(), name) == known.end() && name.rfind("impulse", 0) != 0)
      unknown += (unknown.empty() ? "" : ", ") + name;
  if (!check("columns", scene, csv, unknown.empty(),
             "unknown column(s) " + unknown + "; expected names of `beamimpact schema` (history_columns)"))
    return;
  std::size_t found = 0;
  while (h.columns.count(contact_column("R", static_cast<int>(found) + 1))) ++found;
  check("columns", scene, csv, found == contacts,
        fmt::format("expected R for each of the scene's {} contact(s) (R, R_2, ...), found {}", contacts,
                    found));
}

/// The program refused a scene it declares it accepts: not applicable (the protocol lets a method
/// refuse what it does not model), provided it refused by the rules.
void check_refused_accepted(Checker& check, const ConformScene& c, const Ran& r) {
  std::error_code ec;
  const bool said = check("reason", c.name, r.log, !last_line(r.log).empty(),
                          "expected one line saying why on stderr or stdout, found none");
  const bool clean = check("no summary after failure", c.name, r.dir / "summary.json",
                           !fs::exists(r.dir / "summary.json", ec),
                           "summary.json written by a run that did not finish; expected none");
  if (said && clean) check.not_applicable(c.name, r.log, last_line(r.log));
}

/// Every rule on the run of an accepted scene (api/output_rules.hpp: the rules `beamimpact run`
/// applies too).
void check_accepted(Checker& check, const ConformScene& c, const Ran& r) {
  if (r.process.error.empty() && r.process.exit_code == 2) {
    check_refused_accepted(check, c, r);
    return;
  }
  if (!check("exit code", c.name, r.log, r.process.error.empty() && r.process.exit_code == 0,
             exit_text(r.process) +
                 " on a scene it accepts; expected 0 (or 2 with a reason when it does not "
                 "model the scene). Its last line: " +
                 last_line(r.log))) {
    std::error_code ec;
    check("no summary after failure", c.name, r.dir / "summary.json", !fs::exists(r.dir / "summary.json", ec),
          "summary.json written by a run that did not finish; expected none");
    return;
  }
  const Scene scene = load_scene(c.file);
  const std::vector<OutputVerdict> verdicts =
      check_outputs(r.dir, OutputExpectation{c.file, scene.contacts.size(), scene.time.end});
  for (const OutputVerdict& v : verdicts) check(v.rule, c.name, v.file, v.passed, v.message);
  if (!verdicts.empty() && verdicts.front().passed)
    check_columns(check, c.name, r.dir, scene.contacts.size());
}

/// The rules on a run that must end with exit 2.
void check_refused(Checker& check, const ConformScene& c, const Ran& r) {
  std::error_code ec;
  check("exit code", c.name, r.log, r.process.error.empty() && r.process.exit_code == 2,
        exit_text(r.process) + "; expected 2 (refused or bad input: " + c.why + ")");
  check("reason", c.name, r.log, !last_line(r.log).empty(),
        "expected one line saying why on stderr or stdout, found none");
  check("no summary after failure", c.name, r.dir / "summary.json", !fs::exists(r.dir / "summary.json", ec),
        "summary.json written by a run that did not finish; expected none");
}

}  // namespace

const std::vector<std::string>& conform_scene_names() {
  static const std::vector<std::string> n = {"end_to_end",       "transverse",     "node_to_surface",
                                             "oblique_rotation", "rigid_friction", "two_contacts",
                                             "friction"};
  return n;
}

const std::vector<std::pair<std::string, std::string>>& protocol_rules() {
  static const std::vector<std::pair<std::string, std::string>> r = [] {
    std::vector<std::pair<std::string, std::string>> rules = {
        {"exit code", "0 done; 2 refused or bad input; 3 failed; a scene it does not declare is refused"}};
    for (const auto& rule : output_rules()) rules.push_back(rule);
    rules.insert(rules.end(),
                 {{"columns", "history.csv: t and R (R_k per contact), schema names only"},
                  {"reason", "exit 2 prints one line saying why"},
                  {"no summary after failure", "a run that exits non-zero leaves no summary.json"},
                  {"same result twice", "the same scene run twice gives the same history.csv"}});
    return rules;
  }();
  return r;
}

namespace {

/// Every rule on the runs of the external method `m` on the conformance set (out/runs, out/scenes).
std::vector<RuleResult> check_rules(const Method& m, const fs::path& data_root, const fs::path& out,
                                    double timeout, const std::vector<std::string>& scenes) {
  std::vector<RuleResult> results;
  Checker check(results);
  const std::vector<ConformScene> set = conformance_set(m, data_root, out / "scenes", scenes);
  const ConformScene* first_accepted = nullptr;
  for (const ConformScene& c : set) {
    const Ran r = run_program(m, c, out / "runs" / c.name, timeout);
    const bool known = r.process.error.empty() && r.process.exit_code >= 0 && r.process.exit_code <= 3 &&
                       r.process.exit_code != 1;
    if (!known) check("exit code", c.name, r.log, false, exit_text(r.process) + "; expected 0, 2 or 3");
    if (!known) {
      if (c.expect_exit != 0) check_refused(check, c, r);
      continue;
    }
    if (c.expect_exit == 0) {
      check_accepted(check, c, r);
      if (!first_accepted && r.process.exit_code == 0) first_accepted = &c;
    } else {
      check_refused(check, c, r);
    }
  }
  if (first_accepted) {  // the same scene again: the same history
    const Ran again =
        run_program(m, *first_accepted, out / "runs" / (first_accepted->name + "_again"), timeout);
    const fs::path a = out / "runs" / first_accepted->name / "history.csv", b = again.dir / "history.csv";
    check("same result twice", first_accepted->name, b,
          again.process.exit_code == 0 && read_text(a) == read_text(b),
          "the second run's history.csv differs from " + a.string() + " (or it did not finish)");
  } else {
    check("same result twice", "-", out, false,
          "no scene it accepts finished with exit 0 (every one refused or failed): no output to check; "
          "conform needs at least one scene the method models");
  }
  return results;
}

}  // namespace

void ConformOptions::validate() const {
  const Method& m = runnable_method(method, "conform");
  if (m.in_process())
    throw InputError(m.origin, "conform", "'" + m.name + "' is built in; conform checks an external program");
  if (!(timeout > 0.0) || !std::isfinite(timeout))
    throw InputError("command line", "--timeout", fmt::format("expected seconds > 0, got {}", timeout));
  for (const std::string& name : scenes)
    if (std::find(conform_scene_names().begin(), conform_scene_names().end(), name) ==
        conform_scene_names().end())
      throw InputError("command line", "--scenes",
                       fmt::format("expected names of conformance scenes ({}), got '{}'",
                                   fmt::join(conform_scene_names(), ", "), name));
}

fs::path ConformOptions::out_dir() const { return out.empty() ? fs::path("conform-" + method) : out; }

ConformResult conform(const ConformOptions& o) {
  o.validate();
  const Method& m = runnable_method(o.method, "conform");
  const fs::path root = shipped_data("conform");
  const std::string command =
      fmt::format("beamimpact conform {} --out {} --timeout {}{}", m.name, o.out_dir().string(), o.timeout,
                  o.scenes.empty() ? "" : fmt::format(" --scenes {}", fmt::join(o.scenes, ",")));
  return ConformResult{m.name, m.origin, command, check_rules(m, root, o.out_dir(), o.timeout, o.scenes)};
}

void write_conform_junit(const fs::path& file, const std::string& method,
                         const std::vector<RuleResult>& results) {
  const auto failures =
      std::count_if(results.begin(), results.end(), [](const RuleResult& r) { return !r.passed; });
  std::string x = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n  <testsuite name=\"conform {}\" "
      "tests=\"{}\" "
      "failures=\"{}\">\n",
      xml_escape(method), results.size(), failures);
  for (const RuleResult& r : results) {
    x += fmt::format("    <testcase classname=\"conform.{}\" name=\"{}: {}\">", xml_escape(method),
                     xml_escape(r.rule), xml_escape(r.scene));
    if (r.skipped)
      x += fmt::format("\n      <skipped message=\"not applicable: {}\"/>\n    ", xml_escape(r.message));
    else if (!r.passed)
      x += fmt::format("\n      <failure message=\"{}: {}\">{}</failure>\n    ", xml_escape(r.rule),
                       xml_escape(r.file), xml_escape(r.message));
    x += "</testcase>\n";
  }
  x += "  </testsuite>\n</testsuites>\n";
  write_file_atomic(file, x);
}

int ConformResult::broken() const {
  return static_cast<int>(std::count_if(results.begin(), results.end(),
                                        [](const RuleResult& r) { return !r.skipped && !r.passed; }));
}

int ConformResult::not_applicable() const {
  return static_cast<int>(
      std::count_if(results.begin(), results.end(), [](const RuleResult& r) { return r.skipped; }));
}

int ConformResult::checks() const { return static_cast<int>(results.size()) - not_applicable(); }

nlohmann::json conform_json(const ConformOptions& o, const ConformResult& r) {
  nlohmann::json rules = nlohmann::json::array(), results = nlohmann::json::array();
  for (const auto& [rule, says] : protocol_rules()) rules.push_back({{"rule", rule}, {"definition", says}});
  for (const RuleResult& x : r.results)
    results.push_back({{"rule", x.rule},
                       {"scene", x.scene},
                       {"file", x.file},
                       {"passed", x.passed},
                       {"not_applicable", x.skipped},
                       {"message", x.message}});
  return {
      {"method", r.method},
      {"origin", r.origin},
      {"command", r.command},
      {"version", kVersion},
      {"made", utc_now()},
      {"timeout_seconds", o.timeout},
      {"verdict", r.passed() ? "passed" : "failed"},
      {"rules", rules},
      {"results", results},
      {"counts", {{"checks", r.checks()}, {"broken", r.broken()}, {"not_applicable", r.not_applicable()}}}};
}

std::vector<fs::path> write_conform_reports(const ConformOptions& o, const ConformResult& r) {
  const fs::path dir = o.out_dir();
  write_conform_junit(dir / "junit.xml", r.method, r.results);
  write_file_atomic(dir / "conform.json", conform_json(o, r).dump(1) + "\n");
  return {dir / "junit.xml", dir / "conform.json"};
}

}  // namespace beamimpact::verification
