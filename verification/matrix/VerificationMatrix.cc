#include <verification/matrix/VerificationMatrix.hpp>

#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>
#include <toml++/toml.h>

#include <api/registry.hpp>
#include <solver/scene/TableReader.hpp>
#include <solver/util/InputError.hpp>
#include <verification/compare/compare_runs.hpp>
#include <verification/compare/run_checks.hpp>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;

std::vector<double> numbers(TableReader& r, const std::string& key) {
  std::vector<double> out;
  const toml::node* n = r.raw(key);
  const toml::array* a = n ? n->as_array() : nullptr;
  if (!a || a->size() < 2) r.fail(key, "expected an array of at least two positive numbers (coarse to fine)");
  for (const auto& e : *a) {
    const auto v = e.value<double>();
    if (!v || !(*v > 0.0)) r.fail(key, "expected an array of positive numbers");
    out.push_back(*v);
  }
  return out;
}

const toml::table& sub_table(TableReader& r, const std::string& key) {
  const toml::node* n = r.raw(key);
  if (!n || !n->as_table()) r.fail(key, "expected a table such as { method = \"exact\" }");
  return *n->as_table();
}

class Loader {
 public:
  explicit Loader(const fs::path& file) : file_(file.string()) {}

  VerificationMatrix load() {
    toml::table doc;
    try {
      doc = toml::parse_file(file_);
    } catch (const toml::parse_error& e) {
      throw InputError(file_, "", std::string("expected valid TOML: ") + std::string(e.description()));
    }
    VerificationMatrix m;
    m.file = fs::absolute(file_);
    TableReader top(doc, file_, "", nullptr);
    m.root = m.file.parent_path();
    if (const toml::node* s = top.raw("settings")) {
      if (!s->as_table()) top.fail("settings", "expected a table");
      TableReader st(*s->as_table(), file_, "settings", nullptr);
      if (st.has("root"))
        m.root = m.file.parent_path() / st.string("root", "a directory relative to the matrix file");
      m.timeout = st.number_or("timeout", m.timeout, "a positive number of seconds per run");
      if (!(m.timeout > 0.0)) st.fail("timeout", "expected a positive number of seconds per run");
      st.finish();
    }
    m.root = m.root.lexically_normal();
    root_ = m.root;
    if (const toml::node* s = top.raw("scenes")) {
      if (!s->as_table()) top.fail("scenes", "expected a table of name = \"path\"");
      TableReader sc(*s->as_table(), file_, "scenes", nullptr);
      for (const auto& [k, v] : *s->as_table()) {
        const std::string name(k.str());
        scenes_[name] = sc.string(name, "a scene path relative to the root");
      }
    }
    each(top, "case", [&](TableReader& r, const std::string& p) { m.cases.push_back(read_case(r, p)); });
    each(top, "convergence",
         [&](TableReader& r, const std::string& p) { m.convergence.push_back(read_ladder(r, p)); });
    each(top, "check", [&](TableReader& r, const std::string& p) { m.checks.push_back(read_check(r, p)); });
    top.finish();
    if (m.cases.empty() && m.convergence.empty() && m.checks.empty())
      throw InputError(file_, "case", "expected at least one [[case]], [[convergence]] or [[check]]");
    return m;
  }

 private:
  template <class F>
  void each(TableReader& top, const std::string& key, F f) {
    const toml::node* n = top.raw(key);
    if (!n) return;
    const toml::array* a = n->as_array();
    if (!a) top.fail(key, "expected an array of tables ([[" + key + "]])");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::table* t = (*a)[i].as_table();
      const std::string p = fmt::format("{}[{}]", key, i);
      if (!t) throw InputError(file_, p, "expected a table");
      TableReader r(*t, file_, p, nullptr);
      f(r, p);
      r.finish();
    }
  }

  fs::path scene_path(TableReader& r) {
    std::string s = r.string("scene", "a scene name from [scenes] or a path relative to the root");
    if (scenes_.count(s)) s = scenes_.at(s);
    const fs::path p = (root_ / s).lexically_normal();
    std::error_code unreadable;  // e.g. a name too long for the file system: not found either
    if (!fs::exists(p, unreadable))
      r.fail("scene", "expected an existing scene file, " + p.string() + " does not exist");
    return p;
  }

  /// Fields shared by runs and references; `dt` is read by the caller (a number or a list).
  /// mesh_ladder: `mesh` is a ladder's list of multipliers (read by read_ladder), not the run's.
  jobs::JobSpec read_spec(TableReader& r, const fs::path& scene, bool with_dt, bool mesh_ladder = false) {
    jobs::JobSpec s;
    s.scene = scene;
    s.method = r.string("method", "a method name: " + method_names());
    if (!find_method(s.method))
      r.fail("method", "expected a method name (" + method_names() + "), got '" + s.method + "'");
    if (with_dt && r.has("dt")) {
      s.dt = r.number("dt", "a positive time step (s)");
      if (!(*s.dt > 0.0)) r.fail("dt", "expected a positive time step (s)");
    }
    if (const toml::node* n = mesh_ladder ? nullptr : r.raw("mesh")) {
      if (auto i = n->value<long>()) {
        if (*i < 1) r.fail("mesh", "expected a whole element multiplier >= 1");
        s.mesh = std::to_string(*i);
      } else if (auto str = n->value<std::string>()) {
        s.mesh = *str;
      } else
        r.fail("mesh", "expected an element multiplier or a method's mesh preset name");
    }
    s.set = r.strings("set");
    return s;
  }

  enum class GateKind { kCase, kLadder, kCheck };

  std::vector<Gate> read_gates(TableReader& r, const std::string& prefix, GateKind kind) {
    const bool ladder = kind == GateKind::kLadder;
    std::vector<Gate> gates;
    const toml::node* n = r.raw("gates");
    const toml::array* a = n ? n->as_array() : nullptr;
    if (!a || a->empty()) r.fail("gates", "expected a non-empty array of { metric, tol, why }");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string p = fmt::format("{}.gates[{}]", prefix, i);
      const toml::table* t = (*a)[i].as_table();
      if (!t) throw InputError(file_, p, "expected { metric = ..., tol = ..., why = ... }");
      TableReader g(*t, file_, p, nullptr);
      Gate gate;
      gate.metric =
          g.string("metric", "a norm name of `beamimpact compare` (e.g. \"impulse\", \"R.rel_l2\")");
      if (kind == GateKind::kCheck && !known_check(gate.metric))
        g.fail("metric", "unknown check '" + gate.metric +
                             "'; expected one of: " + fmt::format("{}", fmt::join(check_names(), ", ")));
      if (kind != GateKind::kCheck && !known_norm(gate.metric))
        g.fail("metric", "unknown norm '" + gate.metric + "' (see `beamimpact compare` output)");
      if (g.has("tol")) gate.tol = g.number("tol", "a non-negative tolerance in the norm's unit");
      if (ladder && g.has("min_order"))
        gate.min_order = g.number("min_order", "the least acceptable observed order");
      if (ladder && g.has("richardson"))
        gate.richardson = g.number("richardson", "a safety factor >= 1 on the Richardson error estimate");
      if (gate.richardson && !(*gate.richardson >= 1.0))
        g.fail("richardson", "expected a safety factor >= 1 on the Richardson error estimate (1.25: Roache)");
      if (!gate.tol && !gate.min_order && !gate.richardson)
        g.fail("tol", ladder ? "expected tol, min_order and/or richardson" : "expected a tolerance");
      if (gate.tol && !(*gate.tol >= 0.0)) g.fail("tol", "expected a non-negative tolerance");
      gate.why = g.string("why", "the justification of the tolerance (theory, mesh error, measured spread)");
      if (gate.why.size() < 10) g.fail("why", "expected a real justification");
      g.finish();
      gates.push_back(gate);
    }
    return gates;
  }

  void common(TableReader& r, std::string& tier, bool& required, std::string& note,
              const char* default_tier = "quick") {
    tier = r.choice_or("tier", default_tier, VerificationMatrix::tier_names());
    required = r.boolean_or("required", true);
    if (r.has("note")) note = r.string("note", "text");
  }

  Case read_case(TableReader& r, const std::string& prefix) {
    Case c;
    const fs::path scene = scene_path(r);
    c.run = read_spec(r, scene, true);
    const toml::table& ref = sub_table(r, "reference");
    TableReader rr(ref, file_, prefix + ".reference", nullptr);
    const fs::path ref_scene = rr.has("scene") ? scene_path(rr) : scene;
    c.reference = read_spec(rr, ref_scene, true);
    rr.finish();
    common(r, c.tier, c.required, c.note);
    c.gates = read_gates(r, prefix, GateKind::kCase);
    if (c.run.key() == c.reference.key())
      r.fail("reference", "expected a run different from the case's own run");
    return c;
  }

  Convergence read_ladder(TableReader& r, const std::string& prefix) {
    Convergence v;
    const fs::path scene = scene_path(r);
    const jobs::JobSpec base = read_spec(r, scene, false, r.raw("mesh") && r.raw("mesh")->as_array());
    const int given = r.has("dt") + r.has("fraction") + r.has("mesh") + r.has("rungs");
    if (given != 1)
      r.fail("dt", "expected exactly one of dt = [...], fraction = [...], mesh = [...] or rungs = [...]");
    const std::string key = r.has("dt")         ? "dt"
                            : r.has("fraction") ? "fraction"
                            : r.has("mesh")     ? "mesh"
                                                : "rungs";
    v.refined = key;
    if (key == "rungs")
      read_rungs(r, prefix, base, v);
    else
      v.steps = numbers(r, key);
    if (key == "mesh")
      for (double& s : v.steps) {
        if (!(s >= 1.0) || s != std::floor(s)) r.fail("mesh", "expected whole element multipliers >= 1");
        s = 1.0 / s;  // the refined quantity is the element size, relative to the scene's
      }
    for (std::size_t i = 0; i + 1 < v.steps.size(); ++i)
      if (!(v.steps[i + 1] < v.steps[i]))
        r.fail(key, key == "mesh" ? "expected increasing multipliers (coarse to fine)"
                                  : "expected decreasing values (coarse to fine)");
    for (double s : v.steps) {
      if (key == "rungs") break;  // read_rungs made the runs
      jobs::JobSpec spec = base;
      if (key == "dt")
        spec.dt = s;
      else if (key == "fraction")
        spec.set.push_back(fmt::format("time.fraction={:g}", s));
      else
        spec.mesh = fmt::format("{:g}", 1.0 / s);
      v.runs.push_back(spec);
    }
    if (r.has("reference")) {
      TableReader rr(sub_table(r, "reference"), file_, prefix + ".reference", nullptr);
      v.reference = read_spec(rr, rr.has("scene") ? scene_path(rr) : scene, true);
      rr.finish();
    }
    common(r, v.tier, v.required, v.note);
    v.gates = read_gates(r, prefix, GateKind::kLadder);
    for (const Gate& g : v.gates)
      if (g.richardson && (!v.reference || v.runs.size() < 3))
        r.fail("gates", "a richardson gate needs a reference and at least three rungs");
    return v;
  }

  /// rungs = [{ step, dt, set }, ...] with refined = "name": a ladder of anything, each rung with
  /// its own step (s) and overrides after the ladder's `set`, and `step`, the value of the refined
  /// quantity that tends to zero (e.g. a contact spring's compliance 1 / k), whose ratios the
  /// observed orders use.
  void read_rungs(TableReader& r, const std::string& prefix, const jobs::JobSpec& base, Convergence& v) {
    v.refined = r.string("refined", "the name of the refined quantity the rungs' step gives (e.g. \"1/k\")");
    const toml::node* n = r.raw("rungs");
    const toml::array* a = n ? n->as_array() : nullptr;
    if (!a || a->size() < 2) r.fail("rungs", "expected an array of at least two { step, dt, set } tables");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string p = fmt::format("{}.rungs[{}]", prefix, i);
      const toml::table* t = (*a)[i].as_table();
      if (!t) throw InputError(file_, p, "expected { step = ..., dt = ..., set = [...] }");
      TableReader q(*t, file_, p, nullptr);
      const double step = q.number("step", "the refined quantity's value at this rung, > 0");
      if (!(step > 0.0)) q.fail("step", "expected the refined quantity's value at this rung, > 0");
      jobs::JobSpec spec = base;
      if (q.has("dt")) {
        spec.dt = q.number("dt", "a positive time step (s)");
        if (!(*spec.dt > 0.0)) q.fail("dt", "expected a positive time step (s)");
      }
      for (const std::string& o : q.strings("set")) spec.set.push_back(o);
      q.finish();
      v.steps.push_back(step);
      v.runs.push_back(spec);
    }
  }

  RunCheck read_check(TableReader& r, const std::string& prefix) {
    RunCheck c;
    c.run = read_spec(r, scene_path(r), true);
    common(r, c.tier, c.required, c.note, "stability");
    c.gates = read_gates(r, prefix, GateKind::kCheck);
    return c;
  }

  std::string file_;
  fs::path root_;
  std::map<std::string, std::string> scenes_;
};

}  // namespace

std::string Case::name() const {
  return run.label() + " vs " +
         (reference.scene == run.scene ? reference.settings_label() : reference.label());
}

std::string Convergence::name() const {
  const jobs::JobSpec& first = runs.front();
  const bool by_mesh = refined == "mesh";
  std::string s = first.scene_name() + " " + first.method + " " + refined + "=";
  for (std::size_t i = 0; i < steps.size(); ++i)
    s += fmt::format("{}{:g}", i ? "/" : "", by_mesh ? 1.0 / steps[i] : steps[i]);
  if (!by_mesh && !first.mesh.empty()) s += " mesh=" + first.mesh;
  if (reference) s += " vs " + reference->settings_label();
  return s;
}

VerificationMatrix VerificationMatrix::load(const std::filesystem::path& file) { return Loader(file).load(); }

std::string RunCheck::name() const { return run.label() + " checks"; }

const std::vector<std::string>& VerificationMatrix::tier_names() {
  static const std::vector<std::string> t = {"quick", "stability", "full"};
  return t;
}

std::vector<jobs::JobSpec> VerificationMatrix::runs(const std::string& tier) const {
  std::vector<jobs::JobSpec> out;
  std::set<std::string> seen;
  auto add = [&](const jobs::JobSpec& s) {
    if (seen.insert(s.key()).second) out.push_back(s);
  };
  for (const auto& c : cases)
    if (in_tier(c.tier, tier)) {
      add(c.run);
      add(c.reference);
    }
  for (const auto& v : convergence)
    if (in_tier(v.tier, tier)) {
      for (const auto& s : v.runs) add(s);
      if (v.reference) add(*v.reference);
    }
  for (const auto& c : checks)
    if (in_tier(c.tier, tier)) add(c.run);
  return out;
}

}  // namespace beamimpact::verification
