#include <solver/scene/Scene.hpp>

#include <cmath>

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
const char* to_string(FieldPrecision p) { return p == FieldPrecision::kSingle ? "single" : "double"; }
const char* to_string(ContactLaw l) { return l == ContactLaw::kHard ? "hard" : "hertz"; }
const char* to_string(BeamTheory t) {
  return t == BeamTheory::kEulerBernoulli ? "euler-bernoulli" : "timoshenko";
}

int Scene::body_index(const std::string& n) const {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == n) return static_cast<int>(i);
  return -1;
}

}  // namespace beamimpact
