#include <solver/scene/support_axes.hpp>

#include <cmath>

#include <fmt/format.h>

namespace beamimpact {
namespace {

double cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

/// One held direction and the entry that names it.
enum class Entry { kGlobal, kAxial, kNormal };
struct Held {
  Vec2 d;
  Entry entry;
};

std::vector<Held> held(const Body& body, const Support& s) {
  std::vector<Held> h;
  if (s.fix_x) h.push_back({{1.0, 0.0}, Entry::kGlobal});
  if (s.fix_y) h.push_back({{0.0, 1.0}, Entry::kGlobal});
  if (s.fix_axial) h.push_back({body.axis(), Entry::kAxial});
  if (s.fix_normal) h.push_back({body.normal(), Entry::kNormal});
  return h;
}

}  // namespace

NodeHold node_hold(const Body& body, int node) {
  NodeHold n;
  for (const Support& s : body.supports) {
    if (s.node != node) continue;
    n.theta |= s.fix_theta;
    for (const Held& h : held(body, s)) {
      const bool body_entry = h.entry != Entry::kGlobal;
      if (n.held == 0) {
        n.held = 1;
      } else if (n.held == 2 || std::abs(cross(n.direction, h.d)) > kParallelTolerance) {
        n.held = 2;
        continue;
      } else if (!body_entry || n.body_axes) {
        continue;  // parallel to the direction kept
      }
      n.direction = h.d;
      n.body_axes = body_entry;
      n.normal = h.entry == Entry::kNormal;
    }
  }
  return n;
}

bool axis_aligned(const Body& body) {
  const Vec2 a = body.axis();
  return std::abs(a[0]) <= kParallelTolerance || std::abs(a[1]) <= kParallelTolerance;
}

std::string global_roller_warning(const Body& body, const Support& s, const std::string& file,
                                  const std::string& key) {
  if (s.fix_axial || s.fix_normal || s.fix_x == s.fix_y || axis_aligned(body)) return "";
  if (node_hold(body, s.node).held != 1) return "";  // another support there makes it a pin
  const Vec2 a = body.axis();
  const double deg = std::atan2(a[1], a[0]) * 180.0 / M_PI;
  return fmt::format(
      "{}: key '{}.fix': [\"{}\"] holds the global {} displacement of a body inclined at {:.6g} deg to x: "
      "a roller in global axes, not the roller across the body (a rotated copy of the scene is another "
      "problem); fix = [\"normal\"] is the body-axis roller (\"axial\" holds along the body)",
      file, key, s.fix_x ? "x" : "y", s.fix_x ? "x" : "y", deg);
}

}  // namespace beamimpact
