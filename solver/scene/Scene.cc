#include <solver/scene/Scene.hpp>

#include <cmath>

#include <solver/scene/SceneError.hpp>

namespace beamimpact {

double Body::length() const { return std::hypot(end[0] - start[0], end[1] - start[1]); }

Vec2 Body::axis() const {
  const double L = length();
  return {(end[0] - start[0]) / L, (end[1] - start[1]) / L};
}

Vec2 Body::normal() const {
  const Vec2 a = axis();
  return {-a[1], a[0]};
}

Vec2 Body::node_position(int i) const {
  const double s = static_cast<double>(i) / elements;
  return {start[0] + s * (end[0] - start[0]), start[1] + s * (end[1] - start[1])};
}

const char* to_string(MassKind m) { return m == MassKind::kLumped ? "lumped" : "consistent"; }
const char* to_string(RotaryInertia r) { return r == RotaryInertia::kHrz ? "hrz" : "section"; }
const char* to_string(Kinematics k) { return k == Kinematics::kLinear ? "linear" : "corotational"; }
const char* to_string(FieldFormat f) { return f == FieldFormat::kBinary ? "binary" : "ascii"; }
const char* to_string(ContactLaw l) { return l == ContactLaw::kHard ? "hard" : "hertz"; }
const char* to_string(BeamTheory t) {
  return t == BeamTheory::kEulerBernoulli ? "euler-bernoulli" : "timoshenko";
}

int Scene::body_index(const std::string& n) const {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == n) return static_cast<int>(i);
  return -1;
}

void refuse_loads(const Scene& scene, const std::string& method) {
  if (scene.loads.any())
    throw SceneError(scene.file, "loads",
                     "method '" + method +
                         "' does not apply external loads (gravity, point forces); expected "
                         "no [loads] table, or run a method that applies them (paper, ida)");
}

void refuse_contact_search(const Scene& scene, const std::string& method) {
  for (std::size_t i = 0; i < scene.contacts.size(); ++i)
    if (scene.contacts[i].search)
      throw SceneError(scene.file, "contacts[" + std::to_string(i) + "].node",
                       "node = \"all\" (contact search) is run by the paper method only; method '" + method +
                           "' checks one declared node: expected \"start\", \"end\" or a node index");
}

}  // namespace beamimpact
