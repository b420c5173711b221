#include <verification/matrix/conform.hpp>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <api/accepts.hpp>
#include <api/child_process.hpp>
#include <api/external_method.hpp>
#include <solver/scene/SceneError.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/schema/output_schema.hpp>
#include <solver/util/sha256.hpp>
#include <solver/util/write_file_atomic.hpp>
#include <verification/compare/StoredRun.hpp>
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
std::vector<ConformScene> conformance_set(const Method& m, const fs::path& root, const fs::path& dir) {
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
  for (ConformScene& c : set) {
    try {
      check_accepts(m, load_scene(c.file), "");
    } catch (const SceneError& e) {
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
  } catch (const SceneError&) {  // the malformed scene: no end time to offer
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
    out_.push_back({rule, scene, file.string(), ok, ok ? "" : message});
    return ok;
  }

 private:
  std::vector<RuleResult>& out_;
};

std::string exit_text(const ProcessResult& p) {
  return p.error.empty() ? fmt::format("exit code {}", p.exit_code) : p.error;
}

/// The summary's required keys (docs/protocol.md) and their types; "" when all hold.
std::string summary_problem(const nlohmann::json& s, std::size_t contacts) {
  if (!s.is_object()) return "expected a JSON object";
  for (const char* k : {"method", "scene_sha256"})
    if (!s.contains(k) || !s[k].is_string()) return fmt::format("expected \"{}\" as a string", k);
  for (const char* k : {"dt", "steps", "wall_seconds", "end_time"})
    if (!s.contains(k) || !s[k].is_number()) return fmt::format("expected \"{}\" as a number", k);
  if (!s.contains("complete") || s["complete"] != true) return "expected \"complete\": true";
  if (!s.contains("contacts") || !s["contacts"].is_array() || s["contacts"].size() != contacts)
    return fmt::format("expected \"contacts\" as an array of {} object(s), one per scene contact", contacts);
  for (const auto& c : s["contacts"])
    if (!c.is_object() || !c.contains("impulse_normal") || !c["impulse_normal"].is_number() ||
        !c.contains("intervals") || !c["intervals"].is_array())
      return "expected each contact to give \"impulse_normal\" (N s) and \"intervals\" ([[start, end], ...] "
             "s)";
  return "";
}

/// Columns: the history reads (t, R, numbers, increasing times) and names only schema columns.
void check_columns(Checker& check, const std::string& scene, const fs::path& dir, std::size_t contacts) {
  const fs::path csv = dir / "history.csv";
  try {
    const StoredRun run = StoredRun::read(dir);
    const std::vector<std::string> known = history_columns(static_cast<int>(contacts));
    std::string unknown;
    for (const auto& [name, values] : run.columns())
      if (std::find(known.begin(), known.end(), name) == known.end() && name.rfind("impulse", 0) != 0)
        unknown += (unknown.empty() ? "" : ", ") + name;
    if (!check("columns", scene, csv, unknown.empty(),
               "unknown column(s) " + unknown + "; expected names of `beamimpact schema` (history_columns)"))
      return;
    check("columns", scene, csv, run.contacts() == static_cast<int>(contacts),
          fmt::format("expected R for each of the scene's {} contact(s) (R, R_2, ...), found {}", contacts,
                      run.contacts()));
  } catch (const SceneError& e) {
    check("columns", scene, csv, false, e.what());
  }
}

/// Every rule on the run of an accepted scene.
void check_accepted(Checker& check, const ConformScene& c, const Ran& r) {
  const fs::path summary = r.dir / "summary.json";
  if (!check("exit code", c.name, r.log, r.process.error.empty() && r.process.exit_code == 0,
             exit_text(r.process) + " on a scene it accepts; expected 0. Its last line: " + last_line(r.log)))
    return;
  std::error_code ec;
  if (!check("outputs", c.name, r.dir, fs::exists(summary, ec) && fs::exists(r.dir / "history.csv", ec),
             "expected history.csv and summary.json after exit 0"))
    return;
  check_columns(check, c.name, r.dir, load_scene(c.file).contacts.size());
  nlohmann::json s;
  try {
    s = nlohmann::json::parse(read_text(summary));
  } catch (const std::exception& e) {
    check("summary keys", c.name, summary, false, std::string("expected valid JSON: ") + e.what());
    return;
  }
  const std::string problem = summary_problem(s, load_scene(c.file).contacts.size());
  check("summary keys", c.name, summary, problem.empty(), problem);
  const bool units =
      s.contains("units") && s["units"].is_object() &&
      std::all_of(summary_units().items().begin(), summary_units().items().end(), [&](const auto& u) {
        return s["units"].contains(u.key()) && s["units"][u.key()] == u.value();
      });
  check("units", c.name, summary, units, "expected \"units\": " + summary_units().dump());
  const std::string sha = sha256_hex(read_text(c.file));
  check("scene sha256", c.name, summary, s.value("scene_sha256", "") == sha,
        "expected \"scene_sha256\": \"" + sha + "\" (the scene file's bytes), got \"" +
            s.value("scene_sha256", std::string("(none)")) + "\"");
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

const std::vector<std::pair<std::string, std::string>>& protocol_rules() {
  static const std::vector<std::pair<std::string, std::string>> r = {
      {"exit code", "0 done; 2 refused or bad input; 3 failed"},
      {"outputs", "exit 0 leaves history.csv and summary.json in {out}"},
      {"columns",
       "history.csv: t and R (R_k per contact) first, numbers only, times increasing, schema names"},
      {"summary keys",
       "summary.json: method, scene_sha256, dt, steps, wall_seconds, end_time, complete, contacts"},
      {"units", "summary.json units: the suite's units (t s, R N, u m, v m/s, energy J, impulse N s)"},
      {"scene sha256", "summary.json scene_sha256 is the sha256 of the scene file's bytes"},
      {"reason", "exit 2 prints one line saying why"},
      {"no summary after failure", "a run that exits non-zero leaves no summary.json"},
      {"same result twice", "the same scene run twice gives the same history.csv"},
  };
  return r;
}

std::vector<RuleResult> conform(const Method& m, const fs::path& data_root, const fs::path& out,
                                double timeout) {
  if (m.in_process())
    throw SceneError(m.origin, "conform", "'" + m.name + "' is built in; conform checks an external program");
  std::vector<RuleResult> results;
  Checker check(results);
  const std::vector<ConformScene> set = conformance_set(m, data_root, out / "scenes");
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
    check("same result twice", "-", out, false, "no accepted scene finished; nothing to repeat");
  }
  return results;
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
    if (!r.passed)
      x += fmt::format("\n      <failure message=\"{}: {}\">{}</failure>\n    ", xml_escape(r.rule),
                       xml_escape(r.file), xml_escape(r.message));
    x += "</testcase>\n";
  }
  x += "  </testsuite>\n</testsuites>\n";
  write_file_atomic(file, x);
}

}  // namespace beamimpact::verification
