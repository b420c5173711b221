#include <solver/model/Effects.hpp>

#include <set>

#include <solver/scene/collinear.hpp>
#include <solver/scene/support_axes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {

bool body_can_rotate(const Body& body) {
  std::set<int> held;
  bool clamped = false;
  for (const Support& s : body.supports) {
    const NodeHold h = node_hold(body, s.node);
    if (h.held > 0) held.insert(s.node);
    clamped |= h.theta && h.held == 2;
  }
  return held.size() < 2 && !clamped;
}

namespace {

/// Refuses a body-axis roller on an inclined body that the corotational kinematics rebuilds:
/// its element forces are formed in global axes and have no node axes.
void refuse_rotating_body_axes(const Scene& scene, int b) {
  const Body& body = scene.bodies[b];
  for (std::size_t j = 0; j < body.supports.size(); ++j) {
    const Support& s = body.supports[j];
    if (!(s.fix_axial || s.fix_normal)) continue;
    // As Model: a held direction not exactly along x or y puts the node in the body's axes.
    if (const NodeHold h = node_hold(body, s.node);
        h.held == 1 && h.direction[0] != 0.0 && h.direction[1] != 0.0)
      throw InputError(scene.file,
                       "bodies[" + std::to_string(b) + "].supports[" + std::to_string(j) + "].fix",
                       "a roller in the axes of an inclined body is modelled with linear kinematics only; "
                       "expected model.kinematics = \"linear\" (or a pin, or supports in global x, y)");
  }
}

}  // namespace

Effects derive_effects(const Scene& scene) {
  Effects e;
  e.bending = scene.effects.bending.value_or(!scene_is_collinear(scene));
  const bool has_damping = scene.model.rayleigh_mass != 0.0 || scene.model.rayleigh_stiffness != 0.0;
  e.damping = scene.effects.damping.value_or(has_damping) && has_damping;
  bool has_friction = false;
  for (const Contact& c : scene.contacts) has_friction |= c.friction > 0.0;
  e.friction = scene.effects.friction.value_or(has_friction) && has_friction && e.bending;
  e.loads = scene.loads.any();
  e.rotating.assign(scene.bodies.size(), false);
  if (e.bending && scene.model.kinematics == Kinematics::kCorotational)
    for (std::size_t b = 0; b < scene.bodies.size(); ++b)
      if ((e.rotating[b] = body_can_rotate(scene.bodies[b]) && !scene.bodies[b].rigid)) {
        e.corotational = true;
        refuse_rotating_body_axes(scene, static_cast<int>(b));
      }
  return e;
}

Scene effective_scene(const Scene& scene, const Effects& effects) {
  Scene s = scene;
  if (!effects.damping) s.model.rayleigh_mass = s.model.rayleigh_stiffness = 0.0;
  if (!effects.friction)
    for (Contact& c : s.contacts) c.friction = 0.0;
  return s;
}

std::vector<std::string> Effects::names() const {
  std::vector<std::string> n = {"axial"};
  if (bending) n.push_back("bending");
  if (damping) n.push_back("damping");
  if (friction) n.push_back("friction");
  if (corotational) n.push_back("corotational");
  if (loads) n.push_back("loads");
  return n;
}

}  // namespace beamimpact
