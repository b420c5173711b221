#include <beamimpact/integrator/InternalForce.hpp>

#include <cmath>

namespace beamimpact::paper {

InternalForce::InternalForce(const Model& model, const std::vector<bool>& corotational)
    : model_(model), K_(&model.K()) {
  if (model.dofs_per_node() != 3) {  // rods never rotate
    build_blocks();
    return;
  }
  for (int e = 0; e < static_cast<int>(model.elements().size()); ++e)
    if (corotational[model.elements()[e].body]) corot_elements_.push_back(e);
  if (corot_elements_.empty()) {
    build_blocks();
    return;
  }
  // Linear part: K minus the corotational elements' reference stiffness.
  std::vector<Eigen::Triplet<double>> t;
  for (int e : corot_elements_) {
    const Model::Element& el = model.elements()[e];
    const Eigen::MatrixXd Ke = model.element_stiffness(e, el.c, el.s);
    const Eigen::Matrix<int, 6, 1> eq = model.element_equations(e);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if (eq(i) >= 0 && eq(j) >= 0 && Ke(i, j) != 0.0) t.emplace_back(eq(i), eq(j), -Ke(i, j));
  }
  SparseMatrix Kc(model.size(), model.size());
  Kc.setFromTriplets(t.begin(), t.end());
  K_linear_ = model.K() + Kc;
  K_linear_.prune(0.0);
  K_ = &K_linear_;
}

void InternalForce::build_blocks() {
  const int w = 2 * model_.dofs_per_node();
  for (int e = 0; e < static_cast<int>(model_.elements().size()); ++e) {
    const Model::Element& el = model_.elements()[e];
    if (el.rigid) continue;  // no element stiffness
    const Eigen::MatrixXd Ke = model_.element_stiffness(e, el.c, el.s);
    const Eigen::Matrix<int, 6, 1> eq = model_.element_equations(e);
    BlockElement be{};
    for (int i = 0; i < 6; ++i) be.eq[i] = i < w ? eq(i) : -1;
    const std::size_t nb = blocks_.size() / (w * w);
    bool same = nb > 0;
    for (int i = 0; same && i < w; ++i)
      for (int j = 0; same && j < w; ++j) same = blocks_[(nb - 1) * w * w + i * w + j] == Ke(i, j);
    if (!same)
      for (int i = 0; i < w; ++i)
        for (int j = 0; j < w; ++j) blocks_.push_back(Ke(i, j));
    be.block = static_cast<int>(blocks_.size() / (w * w)) - 1;
    block_elements_.push_back(be);
  }
  // Kept only when the blocks are the whole of K (no other stiffness assembled into it): the
  // two products agree on a vector with no special structure, to the roundoff of the sums
  // (1e-12 of sum |K_ij| |x_j| per row; a missing or extra term of K shows at O(1)).
  const int n = model_.size();
  Eigen::VectorXd x(n), kx(n), bx(n), scale(n);
  for (int i = 0; i < n; ++i) x(i) = std::sin(1.3 * i + 0.7) + 1.5;
  kx.noalias() = model_.K() * x;
  scale.noalias() = model_.K().cwiseAbs() * x.cwiseAbs();
  use_blocks_ = n > 0;
  if (use_blocks_) {
    if (w == 6)
      apply_blocks<6>(x, bx);
    else
      apply_blocks<2>(x, bx);
    use_blocks_ = ((kx - bx).cwiseAbs().array() <= 1e-12 * scale.array()).all();
  }
  if (!use_blocks_) {
    blocks_.clear();
    block_elements_.clear();
  }
}

template <int W>
void InternalForce::apply_blocks(const Eigen::VectorXd& U, Eigen::VectorXd& f) const {
  f.setZero();
  const double* u = U.data();
  double* out = f.data();
  const double* blocks = blocks_.data();
  for (const BlockElement& be : block_elements_) {
    double x[W];
    for (int i = 0; i < W; ++i) x[i] = be.eq[i] >= 0 ? u[be.eq[i]] : 0.0;
    const double* k = blocks + be.block * W * W;
    for (int i = 0; i < W; ++i) {
      if (be.eq[i] < 0) continue;
      double y = 0.0;
      for (int j = 0; j < W; ++j) y += k[i * W + j] * x[j];
      out[be.eq[i]] += y;
    }
  }
}

InternalForce::Local InternalForce::local(int e, const Eigen::VectorXd& U, Eigen::Matrix<int, 6, 1>& eq,
                                          double x[6]) const {
  const Model::Element& el = model_.elements()[e];
  eq = model_.element_equations(e);
  for (int i = 0; i < 6; ++i) x[i] = eq(i) >= 0 ? U(eq(i)) : 0.0;
  const Vec2 p1 = model_.node_position(el.n1), p2 = model_.node_position(el.n2);
  const double dx = p2[0] + x[3] - p1[0] - x[0], dy = p2[1] + x[4] - p1[1] - x[1];
  Local l;
  l.ln = std::hypot(dx, dy);
  l.c = dx / l.ln;
  l.s = dy / l.ln;
  // Rigid rotation of the chord from the reference direction: atan2 gives it in (-pi, pi], but the
  // nodal rotations accumulate past pi on a spinning body, so take the branch nearest to them.
  double alpha = std::atan2(el.c * l.s - el.s * l.c, el.c * l.c + el.s * l.s);
  alpha += 2 * M_PI * std::round((0.5 * (x[2] + x[5]) - alpha) / (2 * M_PI));
  l.u = l.ln - el.length;
  l.th1 = x[2] - alpha;
  l.th2 = x[5] - alpha;
  return l;
}

Vec2 InternalForce::chord_direction(int e, const Eigen::VectorXd& U) const {
  Eigen::Matrix<int, 6, 1> eq;
  double x[6];
  const Local l = local(e, U, eq, x);
  return {l.c, l.s};
}

void InternalForce::apply(const Eigen::VectorXd& U, Eigen::VectorXd& f) const {
  if (use_blocks_) {
    if (model_.dofs_per_node() == 3)
      apply_blocks<6>(U, f);
    else
      apply_blocks<2>(U, f);
    return;
  }
  f.noalias() = (*K_) * U;
  Eigen::Matrix<int, 6, 1> eq;
  double x[6];
  for (int e : corot_elements_) {
    const Model::Element& el = model_.elements()[e];
    const Local l = local(e, U, eq, x);
    const double N = el.E * el.area / el.length * l.u;
    const double k = el.E * el.inertia / el.length;
    const double M1 = k * (4 * l.th1 + 2 * l.th2), M2 = k * (2 * l.th1 + 4 * l.th2);
    // f = B^T [N, M1, M2] with B = [r; e3 - z/ln; e6 - z/ln] (theta_local = theta - chord rotation,
    // d(chord angle) = z . dp / ln), r = [-c,-s,0,c,s,0], z = [s,-c,0,-s,c,0]:
    // f = r N - z (M1 + M2)/ln + e3 M1 + e6 M2.
    const double q = -(M1 + M2) / l.ln;
    const double fe[6] = {-l.c * N + l.s * q, -l.s * N - l.c * q, M1,
                          l.c * N - l.s * q,  l.s * N + l.c * q,  M2};
    for (int i = 0; i < 6; ++i)
      if (eq(i) >= 0) f(eq(i)) += fe[i];
  }
}

double InternalForce::strain_energy(const Eigen::VectorXd& U) const {
  double e = 0.5 * U.dot((*K_) * U);
  Eigen::Matrix<int, 6, 1> eq;
  double x[6];
  for (int i : corot_elements_) {
    const Model::Element& el = model_.elements()[i];
    const Local l = local(i, U, eq, x);
    const double k = el.E * el.inertia / el.length;
    e += 0.5 * el.E * el.area / el.length * l.u * l.u +
         0.5 * k * (4 * l.th1 * l.th1 + 4 * l.th1 * l.th2 + 4 * l.th2 * l.th2);
  }
  return e;
}

}  // namespace beamimpact::paper
