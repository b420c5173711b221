#include <solver/contact/contact_search.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace beamimpact::paper {
namespace {

/// Nodes on the other body's axis (within 1e-9 of its length) have no side: no surface pair.
bool off_axis(const Vec2& x, const Body& b) {
  const Vec2 d{b.end[0] - b.start[0], b.end[1] - b.start[1]};
  const double across = ((x[0] - b.start[0]) * d[1] - (x[1] - b.start[1]) * d[0]) / b.length();
  return std::abs(across) > 1e-9 * b.length();
}

}  // namespace

ContactPairs make_contact_pairs(const Model& model, const Scene& scene, SurfaceInterpolation surface) {
  ContactPairs out;
  for (int c = 0; c < static_cast<int>(scene.contacts.size()); ++c) {
    const Contact& k = scene.contacts[c];
    auto& group = out.group.emplace_back();
    auto add = [&](auto&&... args) {
      group.push_back(static_cast<int>(out.pairs.size()));
      out.pairs.emplace_back(model, scene, c, args..., surface);
      out.contact.push_back(c);
    };
    add();
    if (!k.search) continue;
    const Body& A = scene.bodies[k.striker];
    const Body& B = scene.bodies[k.target];
    for (int i = 0; i < A.nodes(); ++i)
      if (i != k.node && off_axis(A.node_position(i), B)) add(k.striker, i, k.target);
    for (int e : {0, B.elements})
      if (off_axis(B.node_position(e), A)) add(k.target, e, k.striker);
  }
  return out;
}

SearchBoxes::SearchBoxes(const Model& model, std::vector<char> bodies, std::vector<double> margin)
    : model_(model), boxed_(std::move(bodies)), margin_(std::move(margin)), box_(boxed_.size()) {}

void SearchBoxes::update(const Eigen::VectorXd& U) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (auto& b : box_) b = {inf, inf, -inf, -inf};
  for (int n = 0; n < model_.num_nodes(); ++n) {
    const int b = model_.body_of_node(n);
    if (!boxed_[b]) continue;
    const Vec2& X = model_.node_position(n);
    const Vec2 u = model_.node_vector(U, n);
    auto& box = box_[b];
    box[0] = std::min(box[0], X[0] + u[0]);
    box[1] = std::min(box[1], X[1] + u[1]);
    box[2] = std::max(box[2], X[0] + u[0]);
    box[3] = std::max(box[3], X[1] + u[1]);
  }
}

bool SearchBoxes::near(const Eigen::VectorXd& U, int node, int body) const {
  if (!boxed_[body]) return true;
  const Vec2& X = model_.node_position(node);
  const Vec2 u = model_.node_vector(U, node);
  const double x = X[0] + u[0], y = X[1] + u[1], m = margin_[body];
  const auto& b = box_[body];
  return x >= b[0] - m && x <= b[2] + m && y >= b[1] - m && y <= b[3] + m;
}

}  // namespace beamimpact::paper
