#include <api/accepts.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include <solver/model/Effects.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

/// Refuses with the method's name, what the scene should say instead and where the method's
/// capabilities were declared.
[[noreturn]] void refuse(const Method& m, const Scene& scene, const std::string& key, const std::string& what,
                         const std::string& expected, const std::string& flag) {
  throw InputError(
      scene.file, key,
      fmt::format("not applicable: method '{}' does not take {}; expected {} (accepts.{} = false, {})",
                  m.name, what, expected, flag, m.origin));
}

void check_tables(const Scene& scene) {
  for (const auto& [table, options] : scene.method_tables) {
    bool known = false;
    std::string tables;
    for (const Method& m : methods()) {
      known = known || m.options_table == table;
      if (!m.options_table.empty()) tables += (tables.empty() ? "" : ", ") + m.options_table;
    }
    if (!known)
      throw InputError(scene.file, table,
                       "unknown table [" + table + "]; expected a scene table or a method's options table (" +
                           tables + ")");
  }
}

/// True when the contact's striker node faces the target's side at a point inside an element
/// (between two nodes): the kind ContactKind::kNodeToSurface of the paper's contact and IDA's
/// (the same test: the foot of the node on the target's axis, 1e-9 of an element off a node).
bool meets_surface(const Scene& scene, const Contact& c) {
  const Body& target = scene.bodies[static_cast<std::size_t>(c.target)];
  const Vec2 x = scene.bodies[static_cast<std::size_t>(c.striker)].node_position(c.node);
  const Vec2 d = target.axis(), n = target.normal();
  const Vec2 rel{x[0] - target.start[0], x[1] - target.start[1]};
  const double L = target.length(), s = d[0] * rel[0] + d[1] * rel[1], h = n[0] * rel[0] + n[1] * rel[1];
  const double tol = 1e-9 * L;
  if (std::abs(h) <= tol && (s < -tol || s > L + tol)) return false;  // end to end
  const double r = std::clamp(s, 0.0, L) / (L / target.elements);
  return std::abs(r - std::round(r)) >= 1e-9;
}

/// The scene's physics against bending, node_to_surface and loads.
void check_physics(const Method& m, const Scene& scene) {
  const Method::Accepts& a = m.accepts;
  if (!a.bending && derive_effects(scene).bending)
    refuse(m, scene, "bodies", "bending (bodies not all on one line, or [effects] bending = true)",
           "bodies on one line moving along it (rods)", "bending");
  for (std::size_t i = 0; i < scene.contacts.size(); ++i)
    if (!a.node_to_surface && (scene.contacts[i].search || meets_surface(scene, scene.contacts[i])))
      refuse(m, scene, "contacts[" + std::to_string(i) + "]",
             "a node-to-surface contact (the striker node meets the target inside an element)",
             "a striker node facing the target's end or one of its nodes", "node_to_surface");
  if (!a.loads && scene.loads.any())
    refuse(m, scene, "loads", "loads (gravity or point forces)", "no [loads] (or all zero)", "loads");
}

}  // namespace

int mesh_factor(const std::string& mesh, const std::string& file, const std::string& method) {
  char* end = nullptr;
  const long f = std::strtol(mesh.c_str(), &end, 10);
  if (end == mesh.c_str() || *end != '\0' || f < 1 || f > 64)
    throw InputError(file, "mesh",
                     "expected an element multiplier 1..64 for method '" + method + "', got '" + mesh + "'");
  return static_cast<int>(f);
}

void check_accepts(const Method& m, const Scene& scene, const std::string& mesh) {
  check_tables(scene);
  const Method::Accepts& a = m.accepts;
  for (const char* key : {"time.dt", "time.fraction"})
    if (!a.dt && scene.overrides.count(key))
      refuse(m, scene, key, "a time step (it picks its own)", "no --dt or " + std::string(key) + " override",
             "dt");
  if (!mesh.empty()) {
    if (a.mesh_factor)
      (void)mesh_factor(mesh, scene.file, m.name);
    else if (m.in_process())
      refuse(m, scene, "mesh", "a mesh", "no --mesh", "mesh_factor");
    else if (!std::any_of(m.command.begin(), m.command.end(),
                          [](const std::string& x) { return x.find("{mesh}") != std::string::npos; }))
      refuse(m, scene, "mesh", "a mesh (its command has no {mesh})", "no --mesh", "mesh_factor");
  }
  for (std::size_t i = 0; i < scene.contacts.size(); ++i) {
    const Contact& c = scene.contacts[i];
    const std::string key = "contacts[" + std::to_string(i) + "]";
    if (!a.friction && c.friction > 0.0 && scene.effects.friction.value_or(true)) {
      const bool rigid_pair = scene.bodies[static_cast<std::size_t>(c.striker)].rigid &&
                              scene.bodies[static_cast<std::size_t>(c.target)].rigid;
      if (!a.rigid_friction)
        refuse(m, scene, key + ".friction", "friction (it does not model friction)", "friction = 0",
               "friction");
      if (!rigid_pair)
        refuse(m, scene, key + ".friction", "friction where a body deforms (only between rigid bodies)",
               "friction = 0, or both bodies rigid", "friction");
    }
    if (!a.search && c.search)
      refuse(m, scene, key + ".node", "a contact search (node = \"all\")",
             "one declared node: \"start\", \"end\" or a node index", "search");
    if (!a.hertz && c.law == ContactLaw::kHertz)
      refuse(m, scene, key + ".law", "the Hertz contact law (law = \"hertz\")", "\"hard\" (or no law)",
             "hertz");
  }
  check_physics(m, scene);
  if (!a.several_contacts && scene.contacts.size() > 1)
    refuse(m, scene, "contacts", fmt::format("{} contacts", scene.contacts.size()), "one [[contacts]] table",
           "several_contacts");
  if (!a.rotation && scene.model.kinematics == Kinematics::kCorotational)
    refuse(m, scene, "model.kinematics", "large rotation (corotational kinematics)", "\"linear\"",
           "rotation");
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const std::string key = "bodies[" + std::to_string(i) + "]";
    if (!a.rigid && scene.bodies[i].rigid)
      refuse(m, scene, key + ".rigid", "rigid bodies", "rigid = false", "rigid");
    if (!a.timoshenko && scene.bodies[i].theory == BeamTheory::kTimoshenko)
      refuse(m, scene, key + ".theory", "Timoshenko beams (theory = \"timoshenko\")",
             "\"euler-bernoulli\" (or no theory)", "timoshenko");
  }
}

}  // namespace beamimpact
