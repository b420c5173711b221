#include <solver/scene/scene_io.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include <solver/scene/Override.hpp>
#include <solver/scene/TableReader.hpp>
#include <solver/scene/beam_theory.hpp>
#include <solver/scene/collinear.hpp>
#include <solver/scene/contact_law.hpp>
#include <solver/scene/loads_io.hpp>
#include <solver/scene/support_axes.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/sha256.hpp>

namespace beamimpact {
namespace {

/// The scene's own tables; every other top-level table is a method's options (checked against
/// the registry when a method runs: api/accepts.hpp).
const std::vector<std::string> kSceneTables = {"time", "model", "loads", "effects", "output"};

// ---- geometry checks --------------------------------------------------------------------

double cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }
Vec2 sub(const Vec2& a, const Vec2& b) { return {a[0] - b[0], a[1] - b[1]}; }

/// True when segments p and q overlap: a crossing interior to both, or a collinear overlap of
/// positive length. Touching (an end on the other segment, zero gap) is allowed.
bool segments_overlap(const Body& p, const Body& q) {
  const Vec2 r = sub(p.end, p.start), s = sub(q.end, q.start), qp = sub(q.start, p.start);
  const double rxs = cross(r, s), scale = std::max(p.length(), q.length());
  const double eps = 1e-12;
  if (std::abs(rxs) < eps * scale * scale) {
    if (std::abs(cross(qp, r)) > eps * scale * scale) return false;  // parallel, apart
    const double rr = r[0] * r[0] + r[1] * r[1];
    const double t0 = (qp[0] * r[0] + qp[1] * r[1]) / rr;
    const double t1 = t0 + (s[0] * r[0] + s[1] * r[1]) / rr;
    const double lo = std::max(0.0, std::min(t0, t1)), hi = std::min(1.0, std::max(t0, t1));
    return (hi - lo) * std::sqrt(rr) > eps * scale;
  }
  const double t = cross(qp, s) / rxs, u = cross(qp, r) / rxs;
  return t > eps && t < 1 - eps && u > eps && u < 1 - eps;
}

// ---- readers -----------------------------------------------------------------------------

std::string fmt_range(const std::string& expected, double got) {
  std::ostringstream os;
  os << "expected " << expected << ", got " << got;
  return os.str();
}

const toml::table& sub_table(TableReader& r, const std::string& key, bool required,
                             const toml::table& empty) {
  const toml::node* n = r.raw(key);
  if (!n) {
    if (required) r.missing(key, "a table [" + key + "]");
    return empty;
  }
  if (!n->as_table()) r.fail(key, "expected a table [" + key + "]");
  return *n->as_table();
}

/// Magnitudes a scene may use: far outside any physical beam in SI units, and far enough from
/// the double range (1e-308 .. 1e308) that products of a few of them (masses, energies, step
/// counts) stay finite and nonzero. Outside it a run ends in a zero mass or an infinite energy.
constexpr double kSmallest = 1e-30, kLargest = 1e30;

double positive(TableReader& r, const std::string& key, const std::string& unit) {
  const double v = r.number(key, "a positive number (" + unit + ")");
  if (!(v > 0.0)) r.fail(key, "expected a positive number (" + unit + "), got " + std::to_string(v));
  if (v < kSmallest || v > kLargest)
    r.fail(key, fmt_range("a positive number between 1e-30 and 1e30 (" + unit + ")", v));
  return v;
}

/// Refuses a value of magnitude above 1e30 (a coordinate, velocity or damping coefficient).
double bounded(TableReader& r, const std::string& key, double v, const std::string& what) {
  if (!(std::abs(v) <= kLargest)) r.fail(key, fmt_range(what + " of magnitude at most 1e30", v));
  return v;
}

Vec2 bounded(TableReader& r, const std::string& key, const Vec2& v, const std::string& what) {
  for (double x : v) bounded(r, key, x, what);
  return v;
}

int node_ref(TableReader& r, const std::string& key, const Body& body) {
  const toml::node* n = r.raw(key);
  const std::string expected = "\"start\", \"end\", \"all\" (contact search) or a node index 0.." +
                               std::to_string(body.elements) + " of body '" + body.name + "'";
  if (!n) r.missing(key, expected);
  if (auto s = n->as_string()) {
    if (s->get() == "start") return 0;
    if (s->get() == "end") return body.elements;
    r.fail(key, "expected " + expected + ", got \"" + s->get() + "\"");
  }
  if (auto i = n->as_integer()) {
    if (i->get() < 0 || i->get() > body.elements)
      r.fail(key, "expected " + expected + ", got " + std::to_string(i->get()));
    return static_cast<int>(i->get());
  }
  r.fail(key, "expected " + expected);
}

/// Distance (m) from point x to the segment of body b.
double distance_to_body(const Vec2& x, const Body& b) {
  const Vec2 d{b.end[0] - b.start[0], b.end[1] - b.start[1]};
  const double L2 = d[0] * d[0] + d[1] * d[1];
  const double s = std::clamp(((x[0] - b.start[0]) * d[0] + (x[1] - b.start[1]) * d[1]) / L2, 0.0, 1.0);
  return std::hypot(x[0] - b.start[0] - s * d[0], x[1] - b.start[1] - s * d[1]);
}

/// The striker node nearest the target's segment at t = 0 (the first one on a tie).
int nearest_node(const Body& striker, const Body& target) {
  int best = 0;
  double best_distance = distance_to_body(striker.node_position(0), target);
  for (int i = 1; i < striker.nodes(); ++i)
    if (const double d = distance_to_body(striker.node_position(i), target); d < best_distance) {
      best = i;
      best_distance = d;
    }
  return best;
}

void read_time(TableReader& r, TimeSettings& t) {
  const toml::node* dt = r.raw("dt");
  if (!dt) r.missing("dt", "a positive number (s) or \"auto\"");
  if (auto s = dt->as_string()) {
    if (s->get() != "auto")
      r.fail("dt", "expected a positive number (s) or \"auto\", got \"" + s->get() + "\"");
    t.dt.reset();
    t.fraction = r.number_or("fraction", 0.5, "a fraction of the critical step in (0, 1]");
    if (!(t.fraction > 0.0 && t.fraction <= 1.0))
      r.fail("fraction",
             "expected a fraction of the critical step in (0, 1], got " + std::to_string(t.fraction));
  } else {
    t.dt = positive(r, "dt", "s");
    if (r.has("fraction"))
      r.fail("fraction", "is used only with dt = \"auto\"; remove it or set dt = \"auto\"");
  }
  t.end = positive(r, "end", "s");
  t.output_every = static_cast<int>(r.integer_or("output_every", 1, "a whole number of steps >= 1"));
  if (t.output_every < 1) r.fail("output_every", "expected a whole number of steps >= 1");
  t.allow_above_critical = r.boolean_or("allow_above_critical", false);
  t.allow_long_run = r.boolean_or("allow_long_run", false);
  if (t.dt && *t.dt > t.end) r.fail("dt", "expected a step no longer than time.end");
}

/// Reads a choice whose string forms are the enum's to_string() (the one owner of them).
template <typename Enum>
Enum read_choice(TableReader& r, const std::string& key, Enum fallback, std::initializer_list<Enum> all) {
  std::vector<std::string> names;
  for (Enum e : all) names.emplace_back(to_string(e));
  const std::string got = r.choice_or(key, to_string(fallback), names);
  for (Enum e : all)
    if (got == to_string(e)) return e;
  return fallback;
}

void read_model(TableReader& r, ModelSettings& m) {
  m.mass = read_choice(r, "mass", MassKind::kLumped, {MassKind::kLumped, MassKind::kConsistent});
  m.rotary_inertia =
      read_choice(r, "rotary_inertia", RotaryInertia::kHrz, {RotaryInertia::kHrz, RotaryInertia::kSection});
  m.kinematics =
      read_choice(r, "kinematics", Kinematics::kLinear, {Kinematics::kLinear, Kinematics::kCorotational});
  m.rayleigh_mass = r.number_or("rayleigh_mass", 0.0, "a number >= 0 (1/s)");
  m.rayleigh_stiffness = r.number_or("rayleigh_stiffness", 0.0, "a number >= 0 (s)");
  if (m.rayleigh_mass < 0) r.fail("rayleigh_mass", "expected a number >= 0 (1/s)");
  if (m.rayleigh_stiffness < 0) r.fail("rayleigh_stiffness", "expected a number >= 0 (s)");
  bounded(r, "rayleigh_mass", m.rayleigh_mass, "a number >= 0 (1/s)");
  bounded(r, "rayleigh_stiffness", m.rayleigh_stiffness, "a number >= 0 (s)");
}

/// The entries of a support's fix array, as a message lists them.
const std::string kFixNames = "\"x\", \"y\", \"theta\", \"axial\", \"normal\"";

void read_supports(TableReader& r, Body& b, std::map<std::string, std::string>* assumed) {
  const toml::node* n = r.raw("supports");
  if (!n) {
    if (assumed) (*assumed)[r.path("supports")] = "[] (free)";
    return;
  }
  const toml::array* arr = n->as_array();
  if (!arr)
    r.fail("supports", "expected an array of { at = \"start\"|\"end\"|index, fix = [" + kFixNames + "] }");
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const toml::table* st = arr->get(i)->as_table();
    const std::string key = "supports[" + std::to_string(i) + "]";
    if (!st) r.fail(key, "expected { at = ..., fix = [...] }");
    TableReader sr(*st, r.file(), r.path(key), nullptr);
    Support s;
    s.node = node_ref(sr, "at", b);
    const toml::node* fx = sr.raw("fix");
    if (!fx || !fx->as_array() || fx->as_array()->empty())
      sr.fail("fix", "expected a non-empty array of " + kFixNames);
    for (const toml::node& c : *fx->as_array()) {
      const std::string v = c.value<std::string>().value_or("?");
      bool* const flag = v == "x"        ? &s.fix_x
                         : v == "y"      ? &s.fix_y
                         : v == "theta"  ? &s.fix_theta
                         : v == "axial"  ? &s.fix_axial
                         : v == "normal" ? &s.fix_normal
                                         : nullptr;
      if (!flag)
        sr.fail("fix", "expected some of " + kFixNames +
                           " (global x, y, rotation; axial: along the body from start to end, normal: "
                           "across it, the axial direction turned +90 deg), got " +
                           v);
      *flag = true;
    }
    sr.finish();
    b.supports.push_back(s);
  }
}

// ---- the steps of load_scene --------------------------------------------------------------

/// @brief The scene file's bytes; records its SHA-256 in sc.
std::string read_scene_file(const std::filesystem::path& path, Scene& sc) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;  // the reason, as the system gives it (No such file or directory, ...)
    std::error_code ec;
    const bool dir = std::filesystem::is_directory(path, ec);
    throw InputError(
        sc.file, "",
        std::string("cannot open the scene file: ") + (dir ? "it is a directory" : std::strerror(err)));
  }
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  sc.sha256 = sha256_hex(text);
  return text;
}

/// @brief Parses the TOML text of the file named in sc; a syntax error names line and column.
toml::table parse_scene_text(const std::string& text, const Scene& sc) {
  try {
    return toml::parse(text, sc.file);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << "TOML syntax error at line " << e.source().begin.line << ", column " << e.source().begin.column
        << ": " << e.description();
    throw InputError(sc.file, "", msg.str());
  }
}

/// A step in seconds given by --set replaces the file's dt = "auto" and with it the fraction that
/// belongs to "auto" (no --set can remove a key): the fraction goes unless --set gave it too.
void drop_auto_fraction(toml::table& root, const Scene& sc) {
  const auto dt = sc.overrides.find("time.dt");
  if (dt == sc.overrides.end() || sc.overrides.count("time.fraction")) return;
  toml::table* time = root["time"].as_table();
  if (!time || !(*time)["dt"].is_number()) return;
  time->erase("fraction");
}

/// @brief Applies the overrides to root in order and records them in sc (the one place every
/// override passes, --set text and typed edits alike).
void apply_overrides(toml::table& root, const std::vector<Override>& overrides, Scene& sc) {
  for (const Override& o : overrides) {
    apply_override(root, sc.file, o);
    sc.overrides[o.key] = o.text;
  }
  drop_auto_fraction(root, sc);
}

/// @brief Reads the optional [output] table.
void read_output(TableReader& top, Scene& sc) {
  const toml::table empty;
  TableReader r(sub_table(top, "output", false, empty), sc.file, "output", &sc.assumed);
  sc.output.history = r.boolean_or("history", true);
  sc.output.fields = r.boolean_or("fields", false);
  sc.output.field_format = r.choice_or("field_format", "binary", {"binary", "ascii"}) == "binary"
                               ? FieldFormat::kBinary
                               : FieldFormat::kAscii;
  sc.output.field_precision = r.choice_or("field_precision", "single", {"single", "double"}) == "single"
                                  ? FieldPrecision::kSingle
                                  : FieldPrecision::kDouble;
  r.finish();
}

/// @brief Reads the required [time] and the optional [model] table.
void read_time_and_model(TableReader& top, Scene& sc) {
  const toml::table empty;
  {
    TableReader r(sub_table(top, "time", true, empty), sc.file, "time", &sc.assumed);
    read_time(r, sc.time);
    r.finish();
  }
  {
    TableReader r(sub_table(top, "model", false, empty), sc.file, "model", &sc.assumed);
    read_model(r, sc.model);
    r.finish();
  }
}

/// @brief Reads one [[bodies]] table (its name must be new in sc; defaults go to sc.assumed).
Body read_body(TableReader& r, Scene& sc) {
  auto* assumed = &sc.assumed;
  Body b;
  b.name = r.string("name", "a string naming the body");
  if (sc.body_index(b.name) >= 0) r.fail("name", "body name '" + b.name + "' is used twice");
  b.start = bounded(r, "start", r.vec2("start", "[x, y] of the first node (m)"), "coordinates (m)");
  b.end = bounded(r, "end", r.vec2("end", "[x, y] of the last node (m)"), "coordinates (m)");
  if (!(b.length() > 0.0))
    r.fail("end", "expected a point different from start: the length must be positive (m)");
  const long ne = r.integer("elements", "a whole number of elements >= 1");
  if (ne < 1 || ne > 10'000'000) r.fail("elements", "expected a whole number of elements >= 1");
  b.elements = static_cast<int>(ne);
  b.E = positive(r, "E", "N/m^2");
  b.rho = positive(r, "rho", "kg/m^3");
  b.area = positive(r, "area", "m^2");
  if (r.has("inertia")) b.inertia = positive(r, "inertia", "m^4");
  if (r.has("velocity"))
    b.velocity = bounded(r, "velocity", r.vec2("velocity", "[vx, vy] (m/s)"), "velocities (m/s)");
  else
    (*assumed)[r.path("velocity")] = "[0, 0]";
  read_supports(r, b, assumed);
  b.rigid = r.boolean_or("rigid", false);
  read_beam_theory(r, b);
  for (std::size_t j = 0; j < b.supports.size(); ++j)
    if (std::string w =
            global_roller_warning(b, b.supports[j], sc.file, r.path("supports[" + std::to_string(j) + "]"));
        !w.empty())
      sc.warnings.push_back(std::move(w));
  const auto immovable = [&] {
    const NodeHold h = node_hold(b, b.supports[0].node);
    return b.supports.size() == 1 && h.held == 2 && h.theta;
  };
  if (b.rigid && !b.supports.empty() && !immovable())
    r.fail("supports",
           "a rigid body is free (supports = []) or immovable (one support fixing \"x\", \"y\" and "
           "\"theta\"); expected one of those");
  r.finish();
  return b;
}

/// @brief Reads the [[bodies]] tables (at least two).
void read_bodies(TableReader& top, Scene& sc) {
  const toml::node* bn = top.raw("bodies");
  if (!bn || !bn->as_array() || bn->as_array()->size() < 2)
    top.fail("bodies", "expected at least two [[bodies]] tables");
  const toml::array& barr = *bn->as_array();
  for (std::size_t i = 0; i < barr.size(); ++i) {
    const std::string key = "bodies[" + std::to_string(i) + "]";
    if (!barr.get(i)->as_table()) top.fail(key, "expected a table");
    TableReader r(*barr.get(i)->as_table(), sc.file, key, &sc.assumed);
    sc.bodies.push_back(read_body(r, sc));
  }
}

/// @brief Reads one [[contacts]] table, resolving striker and target names to body indices.
Contact read_contact(TableReader& r, const Scene& sc) {
  Contact c;
  const std::string s = r.string("striker", "the name of a body");
  c.striker = sc.body_index(s);
  if (c.striker < 0) r.fail("striker", "expected the name of a body, got '" + s + "'");
  const toml::node* nn = r.raw("node");
  c.search = nn && nn->as_string() && nn->as_string()->get() == "all";
  if (!c.search) c.node = node_ref(r, "node", sc.bodies[c.striker]);
  const std::string t = r.string("target", "the name of a body");
  c.target = sc.body_index(t);
  if (c.target < 0) r.fail("target", "expected the name of a body, got '" + t + "'");
  if (c.target == c.striker) r.fail("target", "expected a body other than the striker");
  if (c.search) c.node = nearest_node(sc.bodies[c.striker], sc.bodies[c.target]);
  c.friction = r.number_or("friction", 0.0, "a Coulomb coefficient >= 0");
  if (c.friction < 0) r.fail("friction", "expected a Coulomb coefficient >= 0");
  bounded(r, "friction", c.friction, "a Coulomb coefficient >= 0");
  read_contact_law(r, c);
  r.finish();
  return c;
}

/// @brief Reads the [[contacts]] tables (at least one), after the bodies.
void read_contacts(TableReader& top, Scene& sc) {
  const toml::node* cn = top.raw("contacts");
  if (!cn || !cn->as_array() || cn->as_array()->empty())
    top.fail("contacts", "expected at least one [[contacts]] table");
  const toml::array& carr = *cn->as_array();
  for (std::size_t i = 0; i < carr.size(); ++i) {
    const std::string key = "contacts[" + std::to_string(i) + "]";
    if (!carr.get(i)->as_table()) top.fail(key, "expected a table");
    TableReader r(*carr.get(i)->as_table(), sc.file, key, &sc.assumed);
    sc.contacts.push_back(read_contact(r, sc));
  }
}

/// @brief Reads the optional [effects] table (unset switches stay unset: derived later).
void read_effects(TableReader& top, Scene& sc) {
  const toml::table empty;
  TableReader r(sub_table(top, "effects", false, empty), sc.file, "effects", nullptr);
  sc.effects.bending = r.boolean_opt("bending");
  sc.effects.friction = r.boolean_opt("friction");
  sc.effects.damping = r.boolean_opt("damping");
  r.finish();
}

/// @brief Keeps the method option tables ([paper], [ida], an external method's [name]) as parsed
/// tables for their methods.
void keep_method_tables(const toml::table& root, TableReader& top, Scene& sc) {
  for (auto&& [k, node] : root) {
    const std::string key(k.str());
    if (!node.is_table() || std::count(kSceneTables.begin(), kSceneTables.end(), key)) continue;
    (void)top.raw(key);
    sc.method_tables[key] = *node.as_table();
  }
}

/// @brief Cross-checks that need the whole scene: a bending scene gives every body an inertia,
/// and no two bodies overlap at t = 0.
/// A striker node that touches its target at t = 0 has no gap to close: refused for every method.
void check_initial_gaps(const Scene& sc) {
  double scale = 0.0;
  for (const Body& b : sc.bodies) scale = std::max(scale, b.length());
  for (std::size_t i = 0; i < sc.contacts.size(); ++i) {
    const Contact& c = sc.contacts[i];
    const Body& striker = sc.bodies[c.striker];
    const Body& target = sc.bodies[c.target];
    for (int node = c.search ? 0 : c.node; node <= (c.search ? striker.elements : c.node); ++node) {
      const Vec2 x = striker.node_position(node);
      if (distance_to_body(x, target) <= 1e-9 * scale)
        throw InputError(
            sc.file, "contacts[" + std::to_string(i) + "].node",
            fmt::format("the striker node of '{}' at ({:.6g}, {:.6g}) m touches target '{}' at t = 0 "
                        "(zero initial gap); expected a positive gap: move '{}' away from '{}' "
                        "(a contact must close during the run)",
                        striker.name, x[0], x[1], target.name, striker.name, target.name));
    }
    // A search also checks the target's end nodes against the striker.
    for (int end : {0, target.elements})
      if (c.search && distance_to_body(target.node_position(end), striker) <= 1e-9 * scale)
        throw InputError(
            sc.file, "contacts[" + std::to_string(i) + "].node",
            fmt::format("node = \"all\": an end node of target '{}' touches striker '{}' at t = 0 "
                        "(zero initial gap); expected a positive gap",
                        target.name, striker.name));
  }
}

void check_whole_scene(const Scene& sc) {
  const bool bending = sc.effects.bending.value_or(!scene_is_collinear(sc));
  for (std::size_t i = 0; i < sc.bodies.size(); ++i)
    if (bending && sc.bodies[i].inertia <= 0.0 && !sc.bodies[i].rigid)
      throw InputError(sc.file, "bodies[" + std::to_string(i) + "].inertia",
                       "missing; expected a positive second moment of area (m^4): this scene bends");
  for (std::size_t i = 0; i < sc.bodies.size(); ++i)
    for (std::size_t j = i + 1; j < sc.bodies.size(); ++j)
      if (segments_overlap(sc.bodies[i], sc.bodies[j]))
        throw InputError(sc.file, "bodies[" + std::to_string(j) + "].start",
                         "bodies '" + sc.bodies[i].name + "' and '" + sc.bodies[j].name +
                             "' overlap at t = 0; expected a positive gap between them");
  check_initial_gaps(sc);
  check_beam_theory(sc);
}

/// @brief Reads and validates the scene whose file and sha256 are given, from its parsed root.
Scene read_scene(Scene sc, toml::table root, const std::vector<Override>& overrides) {
  apply_overrides(root, overrides, sc);

  TableReader top(root, sc.file, "", &sc.assumed);
  sc.name = top.string("name", "a string naming the scene");
  sc.description = top.has("description") ? top.string("description", "a string") : "";
  read_time_and_model(top, sc);
  read_bodies(top, sc);
  read_contacts(top, sc);
  read_loads(top, sc);
  read_effects(top, sc);
  read_output(top, sc);
  keep_method_tables(root, top, sc);
  top.finish();
  check_whole_scene(sc);
  return sc;
}

/// @brief The file's parsed root; records its name and SHA-256 in sc.
toml::table read_scene_root(const std::filesystem::path& path, Scene& sc) {
  sc.file = path.string();
  return parse_scene_text(read_scene_file(path, sc), sc);
}

}  // namespace

Scene load_scene(const std::filesystem::path& path, const std::vector<std::string>& overrides) {
  Scene sc;
  toml::table root = read_scene_root(path, sc);
  std::vector<Override> parsed = parse_overrides(overrides, sc.file);
  return read_scene(std::move(sc), std::move(root), parsed);
}

Scene load_scene_with(const std::filesystem::path& path, const std::vector<Override>& overrides) {
  Scene sc;
  toml::table root = read_scene_root(path, sc);
  return read_scene(std::move(sc), std::move(root), overrides);
}

Scene load_scene_text(const std::string& text, const std::string& label,
                      const std::vector<std::string>& overrides) {
  Scene sc;
  sc.file = label;
  sc.sha256 = sha256_hex(text);
  toml::table root = parse_scene_text(text, sc);
  std::vector<Override> parsed = parse_overrides(overrides, sc.file);
  return read_scene(std::move(sc), std::move(root), parsed);
}

Scene load_scene_table(toml::table root, const std::string& label, const std::vector<Override>& overrides) {
  Scene sc;
  sc.file = label;
  std::ostringstream text;  // the bytes the scene has as a TOML file, for its scene_sha256
  text << root << "\n";
  sc.sha256 = sha256_hex(text.str());
  return read_scene(std::move(sc), std::move(root), overrides);
}

std::string scene_toml(const Scene& scene) {
  Scene sc;
  toml::table root = read_scene_root(scene.file, sc);
  for (const auto& [key, value] : scene.overrides)
    apply_override(root, sc.file, parse_override(key + "=" + value, sc.file));
  std::ostringstream os;
  os << root << "\n";
  return os.str();
}

}  // namespace beamimpact
