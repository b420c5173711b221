#include <solver/scene/collinear.hpp>

#include <algorithm>
#include <cmath>

namespace beamimpact {
namespace {

double cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }
double norm(const Vec2& a) { return std::hypot(a[0], a[1]); }

}  // namespace

bool scene_is_collinear(const Scene& scene, Vec2* axis_out) {
  if (scene.bodies.empty()) return false;
  const Vec2 axis = scene.bodies[0].axis();
  const Vec2 origin = scene.bodies[0].start;
  double scale = 0.0, vscale = 0.0;
  for (const Body& b : scene.bodies) {
    scale = std::max(scale, b.length());
    vscale = std::max(vscale, norm(b.velocity));
  }
  const double tol = 1e-9 * scale;
  for (const Body& b : scene.bodies) {
    const Vec2 d = b.axis();
    if (std::abs(cross(d, axis)) > 1e-9) return false;
    const Vec2 off{b.start[0] - origin[0], b.start[1] - origin[1]};
    if (std::abs(cross(off, axis)) > tol) return false;
    if (std::abs(cross(b.velocity, axis)) > 1e-12 * std::max(vscale, 1.0)) return false;
  }
  if (axis_out) *axis_out = axis;
  return true;
}

}  // namespace beamimpact
