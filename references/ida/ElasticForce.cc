#include <references/ida/ElasticForce.hpp>

#include <cmath>
#include <stdexcept>

#include <solver/model/frame_element.hpp>
#include <solver/model/timoshenko_element.hpp>

namespace beamimpact::ida {
namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

}  // namespace

ElasticForce::ElasticForce(const Model& model, const std::vector<bool>& rotating) : K_linear_(&model.K()) {
  if (static_cast<int>(rotating.size()) != model.num_bodies())
    throw std::invalid_argument("ElasticForce: one rotating flag per body");
  const auto& list = model.elements();
  for (int e = 0; e < static_cast<int>(list.size()); ++e) {
    const Model::Element& m = list[e];
    if (m.rigid || !rotating[m.body]) continue;
    if (model.dofs_per_node() != 3)
      throw std::invalid_argument("ElasticForce: corotation needs the frame layout");
    Element el;
    el.eq = model.element_equations(e);
    const Vec2 p1 = model.node_position(m.n1), p2 = model.node_position(m.n2);
    el.x1 = p1[0];
    el.y1 = p1[1];
    el.x2 = p2[0];
    el.y2 = p2[1];
    el.beta0 = std::atan2(p2[1] - p1[1], p2[0] - p1[0]);
    el.length = std::hypot(p2[0] - p1[0], p2[1] - p1[1]);
    el.k_local = m.timoshenko ? timoshenko_stiffness_local(m.E, m.area, m.inertia, el.length, m.phi)
                              : frame_stiffness_local(m.E, m.area, m.inertia, el.length);
    // The linear part keeps every other element: take this one's reference stiffness out of K
    // (the pattern stays: the entries become explicit zeros where nothing else adds).
    const Eigen::MatrixXd k0 = model.element_stiffness(e, m.c, m.s);
    std::vector<Eigen::Triplet<double>> minus;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if (el.eq(i) >= 0 && el.eq(j) >= 0) minus.emplace_back(el.eq(i), el.eq(j), -k0(i, j));
    if (elements_.empty()) {
      K_own_ = model.K();
      K_linear_ = &K_own_;
    }
    SparseMatrix D(K_own_.rows(), K_own_.cols());
    D.setFromTriplets(minus.begin(), minus.end());
    K_own_ += D;
    elements_.push_back(el);
  }
}

ElasticForce::Frame ElasticForce::frame(const Element& el, const Eigen::Ref<const Eigen::VectorXd>& U) const {
  Vec6 x;
  for (int i = 0; i < 6; ++i) x(i) = el.eq(i) >= 0 ? U(el.eq(i)) : 0.0;
  const double dx = el.x2 + x(3) - el.x1 - x(0), dy = el.y2 + x(4) - el.y1 - x(1);
  const double l = std::hypot(dx, dy);
  Frame f;
  // The rigid rotation in (-pi, pi], then the branch nearest the nodes' mean rotation.
  const double turn = std::atan2(dy, dx) - el.beta0;
  f.alpha = std::atan2(std::sin(turn), std::cos(turn));
  f.alpha += 2.0 * M_PI * std::round((0.5 * (x(2) + x(5)) - f.alpha) / (2.0 * M_PI));
  f.beta = el.beta0 + f.alpha;
  f.d << 0.0, 0.0, x(2) - f.alpha, l - el.length, 0.0, x(5) - f.alpha;
  f.length = l;
  f.T = frame_rotation(std::cos(f.beta), std::sin(f.beta));  // the element matrices' own rotation
  return f;
}

double ElasticForce::rigid_rotation(int k, const Eigen::Ref<const Eigen::VectorXd>& U) const {
  return frame(elements_.at(k), U).alpha;
}

void ElasticForce::apply(const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::VectorXd& f) const {
  f = *K_linear_ * U;
  for (const Element& el : elements_) {
    const Frame fr = frame(el, U);
    Vec6 fl = el.k_local * fr.d;
    // The transverse end forces from the moments' equilibrium on the current chord (length l):
    // K_local's own, (M1 + M2) / L, is the same to first order, but only (M1 + M2) / l makes the
    // force the gradient of the energy d^T K_local d / 2 (the chord angle moves by dv / l).
    fl(1) = (fl(2) + fl(5)) / fr.length;
    fl(4) = -fl(1);
    const Vec6 fe = fr.T.transpose() * fl;
    for (int i = 0; i < 6; ++i)
      if (el.eq(i) >= 0) f(el.eq(i)) += fe(i);
  }
}

void ElasticForce::add_tangent(const Eigen::Ref<const Eigen::VectorXd>& U, double scale, int row0, int col0,
                               std::vector<Eigen::Triplet<double>>& out) const {
  for (int k = 0; k < K_linear_->outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(*K_linear_, k); it; ++it)
      out.emplace_back(row0 + it.row(), col0 + it.col(), scale * it.value());
  for (const Element& el : elements_) {
    const Frame fr = frame(el, U);
    const Mat6 kt = fr.T.transpose() * el.k_local * fr.T;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if (el.eq(i) >= 0 && el.eq(j) >= 0)
          out.emplace_back(row0 + el.eq(i), col0 + el.eq(j), scale * kt(i, j));
  }
}

double ElasticForce::energy(const Eigen::Ref<const Eigen::VectorXd>& U) const {
  double w = 0.5 * U.dot(*K_linear_ * U);
  for (const Element& el : elements_) {
    const Frame fr = frame(el, U);
    w += 0.5 * fr.d.dot(el.k_local * fr.d);
  }
  return w;
}

}  // namespace beamimpact::ida
