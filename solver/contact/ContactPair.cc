#include <solver/contact/ContactPair.hpp>

#include <algorithm>
#include <cmath>

#include <solver/util/InputError.hpp>

namespace beamimpact::paper {
namespace {

double dot(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }
Vec2 sub(const Vec2& a, const Vec2& b) { return {a[0] - b[0], a[1] - b[1]}; }

/// Weights closer than this to a node snap to it (node-to-node): 1e-9 of an element.
constexpr double kSnap = 1e-9;

}  // namespace

ContactPair::ContactPair(const Model& model, const Scene& scene, int index, SurfaceInterpolation surface)
    : model_(model), surface_(surface) {
  const Contact& c = scene.contacts[index];
  locate(scene, index, c.striker, c.node, c.target);
}

ContactPair::ContactPair(const Model& model, const Scene& scene, int index, int striker, int node, int target,
                         SurfaceInterpolation surface)
    : model_(model), surface_(surface), searched_(true) {
  locate(scene, index, striker, node, target);
}

void ContactPair::locate(const Scene& scene, int index, int striker_body, int node, int target) {
  const Model& model = model_;
  const Body& tb = scene.bodies[target];
  const std::string key = "contacts[" + std::to_string(index) + "]";
  striker_ = model.node_id(striker_body, node);
  target_body_ = target;
  target_first_ = model.node_id(target, 0);
  target_elements_ = tb.elements;
  const Vec2 xs = model.node_position(striker_);
  const double L = tb.length();
  const Vec2 axis{(tb.end[0] - tb.start[0]) / L, (tb.end[1] - tb.start[1]) / L};
  const Vec2 rel = sub(xs, tb.start);
  const double along = dot(rel, axis);                        // m, along the target from its start
  const double across = rel[0] * axis[1] - rel[1] * axis[0];  // m, signed distance from its axis
  const double tol = 1e-9 * L;
  if (std::abs(across) <= tol && (along < -tol || along > L + tol)) {
    // Collinear: the striker node faces the target's nearer end.
    kind_ = ContactKind::kEndToEnd;
    const bool at_start = along < 0;
    element_ = at_start ? 0 : tb.elements - 1;
    xi1_ = at_start ? 1.0 : 0.0;
    xi2_ = 1.0 - xi1_;
    n_ = at_start ? Vec2{-axis[0], -axis[1]} : axis;
    t_ = {n_[1], -n_[0]};
  } else if ((searched_ || (along >= -tol && along <= L + tol)) && std::abs(across) > tol) {
    // The striker node faces the target's surface: normal across the axis, toward the striker.
    const double sgn = across > 0 ? 1.0 : -1.0;  // across > 0: striker on the right of the axis
    n_ = {sgn * axis[1], -sgn * axis[0]};
    t_ = axis;
    const double le = L / tb.elements;
    const double s = std::clamp(along / le, 0.0, static_cast<double>(tb.elements));
    element_ = std::min(static_cast<int>(s), tb.elements - 1);
    xi2_ = s - element_;
    if (xi2_ < kSnap) xi2_ = 0.0;
    if (xi2_ > 1.0 - kSnap) xi2_ = 1.0;
    xi1_ = 1.0 - xi2_;
    kind_ = (xi2_ == 0.0 || xi2_ == 1.0) ? ContactKind::kNodeToNode : ContactKind::kNodeToSurface;
    on_surface_ = along >= -tol && along <= L + tol;  // a searched node beyond an end joins later
  } else {
    throw InputError(scene.file, key + ".node",
                     "the striker node of body '" + scene.bodies[striker_body].name +
                         "' faces neither the surface nor an end of target '" + tb.name +
                         "'; expected a node above the target's span or on its axis beyond an end");
  }
  const Vec2 x1 = model.node_position(target_first_ + element_);
  const Vec2 x2 = model.node_position(target_first_ + element_ + 1);
  const Vec2 xt{xi1_ * x1[0] + xi2_ * x2[0], xi1_ * x1[1] + xi2_ * x2[1]};
  g0_ = dot(n_, sub(xs, xt));
  if (g0_ < -tol)
    throw InputError(scene.file, key,
                     "the striker node penetrates the target at t = 0 (gap " + std::to_string(g0_) +
                         " m); expected a gap >= 0");
  // Room for the largest row: no growth while sliding.
  gn_.reserve(kMaxRowTerms);
  gt_.reserve(kMaxRowTerms);
  build_rows();
}

void ContactPair::build_rows() {
  const int n1 = target_first_ + element_;
  // Rows are rebuilt in place (clear keeps the capacity): a sliding point allocates nothing.
  auto linear = [&](const Vec2& d, std::vector<DofTerm>& out) {
    out.clear();
    model_.append_projection(striker_, d, 1.0, out);
    if (xi1_ != 0.0) model_.append_projection(n1, d, -xi1_, out);
    if (xi2_ != 0.0) model_.append_projection(n1 + 1, d, -xi2_, out);
  };
  linear(t_, gt_);
  if (surface_ == SurfaceInterpolation::kLinear || kind_ == ContactKind::kEndToEnd ||
      model_.dofs_per_node() != 3) {
    linear(n_, gn_);
    wn_ = {xi1_, xi2_};
    return;
  }
  // Hermite: w(s) = H1 w_j + H2 theta'_j + H3 w_j+1 + H4 theta'_j+1 along the element, s = xi2,
  // with the slope dw/dx = +-theta (sign: n is the axis turned +90 deg or -90 deg).
  const double s = xi2_;
  const Vec2 p1 = model_.node_position(n1), p2 = model_.node_position(n1 + 1);
  const double L = std::hypot(p2[0] - p1[0], p2[1] - p1[1]);
  const double turn = t_[0] * n_[1] - t_[1] * n_[0];  // +1: n = t turned +90 deg
  const double H[4] = {1 - 3 * s * s + 2 * s * s * s, L * (s - 2 * s * s + s * s * s),
                       3 * s * s - 2 * s * s * s, L * (-s * s + s * s * s)};
  wn_ = {H[0], H[2]};
  gn_.clear();
  model_.append_projection(striker_, n_, 1.0, gn_);
  for (int k = 0; k < 2; ++k) {
    const int node = n1 + k;
    if (H[2 * k] != 0.0) model_.append_projection(node, n_, -H[2 * k], gn_);
    if (const int eq = model_.equation(node, 2); eq >= 0 && H[2 * k + 1] != 0.0)
      gn_.push_back({eq, -H[2 * k + 1] * turn});
  }
}

double ContactPair::eval(const std::vector<DofTerm>& row, const Eigen::VectorXd& U) {
  double s = 0.0;
  for (const DofTerm& t : row) s += t.coeff * U(t.eq);
  return s;
}

bool ContactPair::relocate(const Eigen::VectorXd& U) {
  if (!can_slide()) return false;
  const Vec2 us = model_.node_vector(U, striker_);
  const Vec2 X = model_.node_position(striker_);
  const Vec2 xs{X[0] + us[0], X[1] + us[1]};
  // Walk from the current element toward the striker's point on the deformed target chord.
  int e = element_;
  int walked = 0;  // direction of the walk so far: -1, 0 or +1
  for (int guard = 0; guard <= target_elements_; ++guard) {
    const int n1 = target_first_ + e;
    const Vec2 p1 = model_.node_position(n1), p2 = model_.node_position(n1 + 1);
    const Vec2 u1 = model_.node_vector(U, n1), u2 = model_.node_vector(U, n1 + 1);
    const Vec2 a{p1[0] + u1[0], p1[1] + u1[1]}, b{p2[0] + u2[0], p2[1] + u2[1]};
    // The struck point is where the striker's line along the normal n crosses the deformed
    // chord: the rows close the gap along n, so any other point (the foot of the chord's own
    // perpendicular) leaves a striker corrected along n off the chord, below it by the predicted
    // penetration times sin^2 of the chord's turn. Coordinates along t, the reference axis.
    const double span = dot(sub(b, a), t_);
    if (!(span > 0.0)) return false;  // an element turned by 90 deg or more: keep the point
    const double x = dot(sub(xs, a), t_) / span;
    // A walk that turns back has found the node between two elements, which roundoff puts just
    // outside both (x < 0 in one, x > 1 in the other): it would go back and forth until the
    // guard runs out and keep the pair where it is. Keep it there at once (O(1), not O(elements)).
    if (x < 0.0 && e > 0) {
      if (walked > 0) return false;
      --e;
      walked = -1;
      continue;
    }
    if (x > 1.0 && e < target_elements_ - 1) {
      if (walked < 0) return false;
      ++e;
      walked = 1;
      continue;
    }
    on_surface_ = x >= -kSnap && x <= 1.0 + kSnap;
    if (!on_surface_) return false;  // beyond the target's end: keep the end point, carry no force
    const double xi2 = std::clamp(x, 0.0, 1.0);
    if (e == element_ && xi2 == xi2_) return false;
    element_ = e;
    xi2_ = xi2;
    xi1_ = 1.0 - xi2;
    build_rows();
    return true;
  }
  return false;
}

Vec2 ContactPair::target_vector(const Eigen::VectorXd& U) const {
  // Tangential part from the tangent row (linear), normal part from the normal row: both rows
  // are "striker minus target", so the target's part is the striker's minus the row value.
  const Vec2 us = model_.node_vector(U, striker_);
  const double un = us[0] * n_[0] + us[1] * n_[1] - eval(gn_, U);
  const double ut = us[0] * t_[0] + us[1] * t_[1] - eval(gt_, U);
  return {un * n_[0] + ut * t_[0], un * n_[1] + ut * t_[1]};
}

std::array<std::pair<int, Vec2>, 3> ContactPair::nodal_forces(double R, double tau) const {
  auto force = [&](double wn, double wt) {
    return Vec2{wn * R * n_[0] + wt * tau * t_[0], wn * R * n_[1] + wt * tau * t_[1]};
  };
  const int n1 = target_first_ + element_;
  return {{{striker_, force(1.0, 1.0)}, {n1, force(-wn_[0], -xi1_)}, {n1 + 1, force(-wn_[1], -xi2_)}}};
}

}  // namespace beamimpact::paper
