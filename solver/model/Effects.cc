#include <solver/model/Effects.hpp>

#include <set>

#include <solver/scene/collinear.hpp>

namespace beamimpact {

bool body_can_rotate(const Body& body) {
  std::set<int> held;
  for (const Support& s : body.supports)
    if (s.fix_x || s.fix_y) held.insert(s.node);
  bool clamped = false;
  for (const Support& s : body.supports) clamped |= s.fix_theta && (s.fix_x && s.fix_y);
  return held.size() < 2 && !clamped;
}

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
      e.corotational |= e.rotating[b] = body_can_rotate(scene.bodies[b]) && !scene.bodies[b].rigid;
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
