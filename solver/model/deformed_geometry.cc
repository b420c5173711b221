#include <solver/model/deformed_geometry.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beamimpact {
namespace {

Vec2 sub(const Vec2& a, const Vec2& b) { return {a[0] - b[0], a[1] - b[1]}; }
double dot(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }
double cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

/// Orders elements and body indices by body (std::equal_range over model.elements()).
struct ByBody {
  bool operator()(const Model::Element& e, int b) const { return e.body < b; }
  bool operator()(int b, const Model::Element& e) const { return b < e.body; }
};

}  // namespace

DeformedSurface::DeformedSurface(const Model& model, int body, int striker_node, Centreline line)
    : model_(model), striker_(striker_node), line_(line) {
  // The model lists the elements body by body: the body's are one range, found by bisection.
  const auto& els = model.elements();
  const auto [lo, hi] = std::equal_range(els.begin(), els.end(), body, ByBody{});
  if (lo == hi) throw std::logic_error("DeformedSurface: the body has no elements");
  first_ = static_cast<int>(lo - els.begin());
  count_ = static_cast<int>(hi - lo);
  const auto& first = *lo;
  const auto& last = *(hi - 1);
  const Vec2 p0 = model.node_position(first.n1), p1 = model.node_position(last.n2);
  const Vec2 axis = sub(p1, p0);
  const double L = std::sqrt(dot(axis, axis));
  const Vec2 rel = sub(model.node_position(striker_node), p0);
  const double across = cross(axis, rel) / L, along = dot(axis, rel) / L;
  side_ = across >= 0.0 ? 1.0 : -1.0;
  if (std::abs(across) <= 1e-9 * L && (along < 0.0 || along > L)) end_on_ = along < 0.0 ? -1 : 1;
}

DeformedSurface::Shape DeformedSurface::shape(const Eigen::VectorXd& U, int k) const {
  const Model::Element& el = model_.elements()[first_ + k];
  const Vec2 X1 = model_.node_position(el.n1), X2 = model_.node_position(el.n2);
  const Vec2 u1 = model_.node_vector(U, el.n1), u2 = model_.node_vector(U, el.n2);
  Shape s;
  s.a = {X1[0] + u1[0], X1[1] + u1[1]};
  s.c = sub({X2[0] + u2[0], X2[1] + u2[1]}, s.a);
  s.L = std::sqrt(dot(s.c, s.c));
  s.n = {-s.c[1] / s.L, s.c[0] / s.L};  // the chord's left normal
  s.phi1 = s.phi2 = 0.0;
  if (model_.dofs_per_node() == 3 && line_ == Centreline::kBeam) {
    // Nodal rotations relative to the chord's rigid rotation: the beam's own cubic about it.
    const double turn = std::atan2(cross({el.c, el.s}, s.c), dot({el.c, el.s}, s.c));
    const int e1 = model_.equation(el.n1, 2), e2 = model_.equation(el.n2, 2);
    s.phi1 = (e1 >= 0 ? U(e1) : 0.0) - turn;
    s.phi2 = (e2 >= 0 ? U(e2) : 0.0) - turn;
  }
  return s;
}

Vec2 DeformedSurface::point(const Eigen::VectorXd& U, int k, double xi) const {
  const Shape s = shape(U, k);
  const double w = s.L * ((xi - 2 * xi * xi + xi * xi * xi) * s.phi1 + (-xi * xi + xi * xi * xi) * s.phi2);
  return {s.a[0] + xi * s.c[0] + w * s.n[0], s.a[1] + xi * s.c[1] + w * s.n[1]};
}

double DeformedSurface::turn(const Eigen::VectorXd& U, int k, double xi) const {
  const Shape s = shape(U, k);
  // d point / d xi = c + w'(xi) n, w' the derivative of the cubic in point().
  const double dw = s.L * ((1 - 4 * xi + 3 * xi * xi) * s.phi1 + (-2 * xi + 3 * xi * xi) * s.phi2);
  const Vec2 tangent{s.c[0] + dw * s.n[0], s.c[1] + dw * s.n[1]};
  const Model::Element& el = model_.elements()[first_ + k];
  return std::atan2(cross({el.c, el.s}, tangent), dot({el.c, el.s}, tangent));
}

RealGap DeformedSurface::gap(const Eigen::VectorXd& U) {
  const Vec2 X = model_.node_position(striker_), us = model_.node_vector(U, striker_);
  const Vec2 x{X[0] + us[0], X[1] + us[1]};
  RealGap r;
  const int last = count_ - 1;
  if (end_on_ != 0) {
    // End-on: the distance beyond the target's end along the end element's deformed direction.
    const int k = end_on_ < 0 ? 0 : last;
    const Shape s = shape(U, k);
    const Vec2 tip = end_on_ < 0 ? s.a : Vec2{s.a[0] + s.c[0], s.a[1] + s.c[1]};
    const double out = end_on_ < 0 ? -1.0 : 1.0;
    // Outward tangent at the end: the chord turned by the end's relative rotation.
    const double phi = end_on_ < 0 ? s.phi1 : s.phi2;
    const Vec2 t{(std::cos(phi) * s.c[0] - std::sin(phi) * s.c[1]) / s.L,
                 (std::sin(phi) * s.c[0] + std::cos(phi) * s.c[1]) / s.L};
    r.element = k;
    r.xi = end_on_ < 0 ? 0.0 : 1.0;
    r.gap = out * dot(sub(x, tip), t);
    return r;
  }
  int k = std::clamp(hint_, 0, last);
  // The walk moves one element at a time towards the closest point and stops where it would turn
  // back: at a node shared by two elements the roundoff of each one's xi can point to the other
  // (xi just below 0 on the right one, just above 1 on the left), and the node is the closest point.
  int came_from = -1;
  for (int guard = 0; guard <= last + 1; ++guard) {
    const Shape s = shape(U, k);
    // Closest point on the element's cubic: Newton on (p(xi) - x) . p'(xi) = 0 from the chord's foot.
    double xi = dot(sub(x, s.a), s.c) / (s.L * s.L);
    for (int it = 0; it < 8; ++it) {
      const double q = std::clamp(xi, -0.5, 1.5);
      const double w = s.L * ((q - 2 * q * q + q * q * q) * s.phi1 + (-q * q + q * q * q) * s.phi2);
      const double dw = s.L * ((1 - 4 * q + 3 * q * q) * s.phi1 + (-2 * q + 3 * q * q) * s.phi2);
      const double ddw = s.L * ((-4 + 6 * q) * s.phi1 + (-2 + 6 * q) * s.phi2);
      const Vec2 p{s.a[0] + q * s.c[0] + w * s.n[0], s.a[1] + q * s.c[1] + w * s.n[1]};
      const Vec2 dp{s.c[0] + dw * s.n[0], s.c[1] + dw * s.n[1]};
      const Vec2 d = sub(p, x);
      const double f = dot(d, dp), df = dot(dp, dp) + dot(d, {ddw * s.n[0], ddw * s.n[1]});
      const double step = df > 0.0 ? f / df : 0.0;
      xi = q - step;
      if (std::abs(step) < 1e-14) break;
    }
    if (xi < 0.0 && k > 0 && k - 1 != came_from) {
      came_from = k--;
      continue;
    }
    if (xi > 1.0 && k < last && k + 1 != came_from) {
      came_from = k++;
      continue;
    }
    hint_ = k;
    r.element = k;
    r.beyond_end = xi < -1e-9 || xi > 1.0 + 1e-9;
    r.xi = std::clamp(xi, 0.0, 1.0);
    const Vec2 p = point(U, k, r.xi);
    const double q = r.xi;
    const double dw = s.L * ((1 - 4 * q + 3 * q * q) * s.phi1 + (-2 * q + 3 * q * q) * s.phi2);
    const Vec2 dp{s.c[0] + dw * s.n[0], s.c[1] + dw * s.n[1]};
    const Vec2 d = sub(x, p);
    r.gap = r.beyond_end ? std::sqrt(dot(d, d)) : side_ * cross(dp, d) / std::sqrt(dot(dp, dp));
    return r;
  }
  return r;
}

}  // namespace beamimpact
