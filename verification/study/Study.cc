#include <verification/study/Study.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <toml++/toml.h>

#include <api/registry.hpp>
#include <solver/scene/TableReader.hpp>
#include <solver/scene/run_cost.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/InputError.hpp>
#include <verification/compare/compare_runs.hpp>
#include <verification/jobs/JobSpec.hpp>
#include <verification/matrix/sweep.hpp>

namespace beamimpact::study {
namespace {

namespace fs = std::filesystem;

Parameter parameter(const toml::table& t, const std::string& file, std::size_t i, Study::Design design) {
  TableReader r(t, file, fmt::format("parameter[{}]", i), nullptr);
  Parameter p;
  p.name = r.string("name", "the parameter's column name (e.g. \"mu\")");
  const int kinds = r.has("key") + r.has("mesh") + r.has("rake");
  if (kinds != 1) r.fail("key", "expected exactly one of key = \"SCENE.KEY\", mesh = true, rake = \"BODY\"");
  if (r.has("key")) {
    p.target = r.string("key", "a scene key as for --set (e.g. \"contacts[0].friction\")");
  } else if (r.has("rake")) {
    p.kind = Parameter::Kind::kRake;
    p.target = r.string("rake", "the striker body's name whose rake angle (deg) this sets");
  } else {
    if (!r.boolean_or("mesh", false)) r.fail("mesh", "expected true (element multiplier of every body)");
    p.kind = Parameter::Kind::kMesh;
  }
  if (const toml::node* v = r.raw("values")) {
    const toml::array* a = v->as_array();
    if (!a || a->empty()) r.fail("values", "expected a non-empty array of numbers");
    for (const auto& e : *a) {
      const auto x = e.value<double>();
      if (!x || !std::isfinite(*x)) r.fail("values", "expected an array of finite numbers");
      p.values.push_back(*x);
    }
  }
  if (r.has("from") || r.has("to")) {
    if (!p.values.empty()) r.fail("from", "expected either values = [...] or from/to (and count), not both");
    p.from = r.number("from", "the first value");
    p.to = r.number("to", "the last value");
    if (!(*p.to > *p.from)) r.fail("to", "expected to > from");
    const long count = design == Study::Design::kGrid
                           ? r.integer("count", "the number of grid levels (>= 2)")
                           : r.integer_or("count", 2, "the number of levels (>= 2)");
    if (count < 2 || count > 100000) r.fail("count", "expected 2 to 100000 levels");
    for (long k = 0; k < count; ++k)
      p.values.push_back(*p.from +
                         (*p.to - *p.from) * static_cast<double>(k) / static_cast<double>(count - 1));
  }
  if (p.values.empty()) r.fail("values", "expected values = [...] or from, to, count");
  if (p.kind == Parameter::Kind::kMesh)
    for (double m : p.values)
      if (!(m >= 1.0) || m != std::floor(m)) r.fail("values", "expected whole element multipliers >= 1");
  if (p.kind == Parameter::Kind::kRake)
    for (double a : p.values)
      if (!(a > 0.0 && a <= 180.0)) r.fail("values", "expected rake angles in (0, 180] degrees");
  r.finish();
  return p;
}

/// SplitMix64: a fixed, portable generator (the same points on every machine and library).
struct SplitMix {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
};

std::string number(double v) { return fmt::format("{:.17g}", v); }

/// The table `reference = { method = ..., set = [...] }`.
void read_reference(TableReader& r, const std::string& file, Study& s) {
  const toml::node* n = r.raw("reference");
  if (!n || !n->as_table()) r.fail("reference", "expected a table such as { method = \"ida\", set = [...] }");
  TableReader rr(*n->as_table(), file, "reference", nullptr);
  s.reference.method = rr.string("method", "a method name (" + method_names() + ")");
  (void)method(s.reference.method, file, "reference.method");
  s.reference.set = rr.strings("set");
  rr.finish();
}

/// The optional table `design = { kind = "grid" | "lhs", samples, seed }`.
void read_design(TableReader& r, const std::string& file, Study& s) {
  const toml::node* n = r.raw("design");
  if (!n) return;
  if (!n->as_table())
    r.fail("design", "expected a table { kind = \"grid\" } or { kind = \"lhs\", samples = N }");
  TableReader d(*n->as_table(), file, "design", nullptr);
  if (d.choice_or("kind", "grid", {"grid", "lhs"}) == "lhs") {
    s.design = Study::Design::kLatinHypercube;
    s.samples = d.integer("samples", "the number of Latin hypercube points (>= 1)");
    if (s.samples < 1 || s.samples > 10000000) d.fail("samples", "expected 1 to 10^7 points");
    s.seed = static_cast<std::uint64_t>(d.integer_or("seed", 1, "a non-negative seed"));
  }
  d.finish();
}

/// The optional array `breaks = [{ metric, above }]`, each metric one of the study's norms.
void read_breaks(TableReader& r, const std::string& file, Study& s) {
  const toml::node* n = r.raw("breaks");
  if (!n) return;
  const toml::array* a = n->as_array();
  if (!a || a->empty()) r.fail("breaks", "expected an array such as [{ metric = \"impulse\", above = 0.1 }]");
  s.breaks.clear();
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::table* t = a->get(i)->as_table();
    if (!t) r.fail("breaks", "expected tables { metric = \"impulse\", above = 0.1 }");
    TableReader b(*t, file, fmt::format("breaks[{}]", i), nullptr);
    BreakRule rule;
    rule.metric = b.string("metric", "a comparison norm");
    if (std::find(s.norms.begin(), s.norms.end(), rule.metric) == s.norms.end())
      b.fail("metric", "'" + rule.metric + "' is not one of the study's norms");
    rule.above = b.number("above", "the norm value above which a case is listed");
    b.finish();
    s.breaks.push_back(rule);
  }
}

/// The number of design points (a double: a grid's product may exceed any integer type).
double point_count(const Study& s) {
  if (s.design == Study::Design::kLatinHypercube) return static_cast<double>(s.samples);
  double n = 1.0;
  for (const auto& p : s.parameters) n *= static_cast<double>(p.values.size());
  return n;
}

/// Refuses, before any point is made, a design beyond memory (kMostStudyPoints points) and, unless
/// allow_long_run = true, a study whose runs add up to more than an ordinary run's work (run_cost.hpp):
/// each point runs once per method and once for its reference; a mesh parameter multiplies a run's
/// DOFs by its largest factor m and its steps by up to m (the wave or "auto" step), so m^2.
void check_cost(TableReader& r, const Study& s) {
  const double points = point_count(s);
  if (points > kMostStudyPoints)
    r.fail("parameter",
           fmt::format("the design has {:.3g} points: expected at most {:g} (the points are held "
                       "in memory); use fewer levels or design = {{ kind = \"lhs\", samples = N }}",
                       points, kMostStudyPoints));
  double mesh = 1.0;
  for (const auto& p : s.parameters)
    if (p.kind == Parameter::Kind::kMesh)
      mesh = std::max(mesh, *std::max_element(p.values.begin(), p.values.end()));
  Scene base;
  try {
    base = load_scene(s.scene, s.set);
  } catch (const InputError& e) {
    r.fail("set", std::string("the overrides do not apply to the scene: ") + e.what());
  }
  const double runs = points * static_cast<double>(s.methods.size() + 1);
  const double per_run = estimate_run_cost(base, planned_dt(base)).work * mesh * mesh;
  if (runs * per_run > kOrdinaryWork && !s.allow_long_run)
    r.fail("allow_long_run",
           fmt::format(
               "this study is far beyond an ordinary run: {:.3g} points x {} runs (the methods and the "
               "reference) x {:.3g} DOF-steps = {:.3g} DOF-steps (ordinary: at most {:g}, 8-18 min of one "
               "core); set allow_long_run = true in the study file to run it",
               points, s.methods.size() + 1, per_run, runs * per_run, kOrdinaryWork));
}

}  // namespace

Study Study::load(const fs::path& file_in) {
  const std::string file = file_in.string();
  toml::table doc;
  try {
    doc = toml::parse_file(file);
  } catch (const toml::parse_error& e) {
    throw InputError(file, "", std::string("expected valid TOML: ") + std::string(e.description()));
  }
  Study s;
  s.file = fs::absolute(file_in).lexically_normal();
  TableReader r(doc, file, "", nullptr);
  s.name = r.string("name", "the study's name");
  if (r.has("description")) s.description = r.string("description", "one line");
  s.scene = (s.file.parent_path() / r.string("scene", "a scene file relative to the study file"))
                .lexically_normal();
  std::error_code unreadable;  // e.g. a name too long for the file system: not found either
  if (!fs::exists(s.scene, unreadable))
    r.fail("scene", "scene file " + InputError::clip(s.scene.string(), 160) + " not found");
  s.methods = r.strings("methods", true);
  if (s.methods.empty()) r.fail("methods", "expected at least one method (" + method_names() + ")");
  for (const auto& m : s.methods) (void)method(m, file, "methods");
  s.set = r.strings("set");
  read_reference(r, file, s);
  read_design(r, file, s);
  s.energy_growth = r.number_or("energy_growth", s.energy_growth,
                                "the stability bound: energy created / initial energy (e.g. 0.01)");
  if (!(s.energy_growth > 0.0)) r.fail("energy_growth", "expected a positive fraction");
  s.norms = r.strings("norms");
  if (s.norms.empty()) s.norms = verification::sweep_norms();
  for (const auto& n : s.norms)
    if (!verification::known_norm(n)) r.fail("norms", "unknown norm '" + n + "' (see `beamimpact compare`)");
  read_breaks(r, file, s);
  s.keep_runs = r.boolean_or("keep_runs", false);
  s.allow_long_run = r.boolean_or("allow_long_run", false);
  const toml::node* ps = r.raw("parameter");
  const toml::array* pa = ps ? ps->as_array() : nullptr;
  if (!pa || pa->empty()) r.fail("parameter", "expected at least one [[parameter]] table");
  for (std::size_t i = 0; i < pa->size(); ++i) {
    const toml::table* t = pa->get(i)->as_table();
    if (!t) r.fail("parameter", "expected [[parameter]] tables");
    s.parameters.push_back(parameter(*t, file, i, s.design));
    for (std::size_t j = 0; j + 1 < s.parameters.size(); ++j)
      if (s.parameters[j].name == s.parameters.back().name)
        r.fail("parameter", "two parameters named '" + s.parameters.back().name + "'");
  }
  r.finish();
  check_cost(r, s);
  // Every override must apply to the scene: check the first point now, before any run.
  try {
    std::vector<std::string> first = overrides(s, design_points(s).front());
    (void)load_scene(s.scene, first);
    first.insert(first.end(), s.reference.set.begin(), s.reference.set.end());
    (void)load_scene(s.scene, first);
  } catch (const InputError& e) {
    r.fail("set", std::string("the overrides do not apply to the scene: ") + e.what());
  }
  return s;
}

std::vector<Point> design_points(const Study& s) {
  std::vector<Point> out;
  const std::size_t np = s.parameters.size();
  if (s.design == Study::Design::kGrid) {
    std::size_t total = 1;
    for (const auto& p : s.parameters) total *= p.values.size();
    for (std::size_t i = 0; i < total; ++i) {
      Point pt;
      pt.values.resize(np);
      std::size_t rest = i;
      for (std::size_t k = np; k-- > 0;) {  // last parameter fastest
        const auto& v = s.parameters[k].values;
        pt.values[k] = v[rest % v.size()];
        rest /= v.size();
      }
      out.push_back(pt);
    }
    return out;
  }
  // Latin hypercube: each parameter's range cut into `samples` strata, one point per stratum,
  // strata paired by independent shuffles. Discrete parameters (values = [...]) take the level
  // of the stratum's position.
  const auto n = static_cast<std::size_t>(s.samples);
  SplitMix rng{s.seed};
  out.assign(n, Point{std::vector<double>(np)});
  for (std::size_t k = 0; k < np; ++k) {
    std::vector<std::size_t> perm(n);
    for (std::size_t i = 0; i < n; ++i) perm[i] = i;
    for (std::size_t i = n; i-- > 1;) std::swap(perm[i], perm[rng.next() % (i + 1)]);
    const Parameter& p = s.parameters[k];
    for (std::size_t i = 0; i < n; ++i) {
      const double u = (static_cast<double>(perm[i]) + rng.uniform()) / static_cast<double>(n);
      if (p.from)
        out[i].values[k] = *p.from + (*p.to - *p.from) * u;
      else
        out[i].values[k] = p.values[std::min(
            p.values.size() - 1, static_cast<std::size_t>(u * static_cast<double>(p.values.size())))];
    }
  }
  return out;
}

std::vector<std::string> overrides(const Study& s, const Point& pt) {
  std::vector<std::string> out = s.set;
  for (std::size_t k = 0; k < s.parameters.size(); ++k) {
    const Parameter& p = s.parameters[k];
    const double v = pt.values[k];
    try {
      switch (p.kind) {
        case Parameter::Kind::kKey: out.push_back(p.target + "=" + number(v)); break;
        case Parameter::Kind::kMesh: {
          const auto m = jobs::mesh_overrides(s.scene, static_cast<int>(v));
          out.insert(out.end(), m.begin(), m.end());
          break;
        }
        case Parameter::Kind::kRake: {
          const Scene sc = load_scene(s.scene, out);
          const int b = sc.body_index(p.target);
          if (b < 0)
            throw InputError(s.file.string(), "parameter." + p.name + ".rake",
                             "no body '" + p.target + "' in the scene");
          const Body& body = sc.bodies[static_cast<std::size_t>(b)];
          const double a = v * std::numbers::pi / 180.0, len = body.length();
          const double speed = std::hypot(body.velocity[0], body.velocity[1]);
          const double c = std::cos(a), sn = std::sin(a);
          out.push_back(fmt::format("bodies.{}.start=[{}, {}]", p.target, number(body.end[0] + len * c),
                                    number(body.end[1] + len * sn)));
          out.push_back(
              fmt::format("bodies.{}.velocity=[{}, {}]", p.target, number(-speed * c), number(-speed * sn)));
          break;
        }
      }
    } catch (const InputError& e) {
      throw InputError(s.file.string(), "parameter." + p.name, std::string("cannot apply: ") + e.what());
    }
  }
  return out;
}

}  // namespace beamimpact::study
