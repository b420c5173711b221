#include <beamimpact/model/Model.hpp>

#include <cmath>

#include <beamimpact/model/frame_element.hpp>
#include <beamimpact/scene/SceneError.hpp>
#include <beamimpact/scene/collinear.hpp>

namespace beamimpact {
namespace {

double dot(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }

Vec2 unit_axis(const Body& b) {
  const double L = b.length();
  return {(b.end[0] - b.start[0]) / L, (b.end[1] - b.start[1]) / L};
}

}  // namespace

Model::Model(const Scene& scene, bool bending)
    : dofs_per_node_(bending ? 3 : 1),
      lumped_(scene.model.mass == MassKind::kLumped),
      rotary_(scene.model.rotary_inertia),
      a0_(scene.model.rayleigh_mass),
      a1_(scene.model.rayleigh_stiffness) {
  if (!bending && !scene_is_collinear(scene, &axis_))
    throw SceneError(scene.file, "effects.bending",
                     "false requires all bodies and velocities on one line; this scene is not collinear");
  const int dpn = dofs_per_node_;

  // Nodes and fixed DOFs.
  std::vector<char> fixed;
  for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b) {
    const Body& body = scene.bodies[b];
    body_first_node_.push_back(static_cast<int>(node_pos_.size()));
    body_velocity_.push_back(body.velocity);
    body_mass_.push_back(body.rho * body.area * body.length());
    for (int i = 0; i < body.nodes(); ++i) {
      node_pos_.push_back(body.node_position(i));
      node_body_.push_back(b);
    }
    fixed.resize(node_pos_.size() * dpn, 0);
    for (const Support& s : body.supports) {
      const int n = body_first_node_[b] + s.node;
      if (dpn == 3) {
        fixed[3 * n] |= s.fix_x;
        fixed[3 * n + 1] |= s.fix_y;
        fixed[3 * n + 2] |= s.fix_theta;
      } else {
        // A rod only moves along its axis: a support fixing a component with an axial part fixes it.
        fixed[n] |= (s.fix_x && std::abs(axis_[0]) > 1e-12) || (s.fix_y && std::abs(axis_[1]) > 1e-12);
      }
    }
    const Vec2 d = unit_axis(body);
    for (int i = 0; i < body.elements; ++i)
      elements_.push_back({b, body_first_node_[b] + i, body_first_node_[b] + i + 1, body.E, body.area,
                           body.inertia, body.rho, body.length() / body.elements, d[0], d[1]});
  }
  dof_to_eq_.assign(fixed.size(), -1);
  for (std::size_t d = 0; d < fixed.size(); ++d)
    if (!fixed[d]) {
      dof_to_eq_[d] = static_cast<int>(free_.size());
      free_.push_back(static_cast<int>(d));
    }
  const int n = size();

  // Element matrices in global axes, scattered to the free equations.
  std::vector<Eigen::Triplet<double>> kt, mt;
  Eigen::VectorXd mdiag = Eigen::VectorXd::Zero(n);
  momentum_.assign(num_bodies(), {Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)});
  for (int e = 0; e < static_cast<int>(elements_.size()); ++e) {
    const Element& el = elements_[e];
    const Eigen::Matrix<int, 6, 1> eq = element_equations(e);
    const int ne = 2 * dpn;
    const Eigen::MatrixXd Ke = element_stiffness(e, el.c, el.s), Me = element_mass(e, el.c, el.s);
    for (int c = 0; c < 2; ++c) {  // rigid translation along global axis c, in element DOFs
      Eigen::VectorXd r = Eigen::VectorXd::Zero(ne);
      for (int k = 0; k < 2; ++k) {
        if (dpn == 3)
          r(3 * k + c) = 1.0;
        else
          r(k) = axis_[c];
      }
      const Eigen::VectorXd mr = Me * r;
      for (int i = 0; i < ne; ++i)
        if (eq(i) >= 0) momentum_[el.body][c](eq(i)) += mr(i);
    }
    for (int i = 0; i < ne; ++i) {
      if (eq(i) < 0) continue;
      for (int j = 0; j < ne; ++j) {
        if (eq(j) < 0) continue;
        if (Ke(i, j) != 0.0) kt.emplace_back(eq(i), eq(j), Ke(i, j));
        if (Me(i, j) != 0.0) {
          if (lumped_)
            mdiag(eq(i)) += Me(i, j);
          else
            mt.emplace_back(eq(i), eq(j), Me(i, j));
        }
      }
    }
  }
  K_.resize(n, n);
  K_.setFromTriplets(kt.begin(), kt.end());
  M_.resize(n, n);
  if (lumped_) {
    m_diag_ = mdiag;
    for (int i = 0; i < n; ++i) mt.emplace_back(i, i, mdiag(i));
  }
  M_.setFromTriplets(mt.begin(), mt.end());
  K_.makeCompressed();
  M_.makeCompressed();
}

Eigen::MatrixXd Model::element_stiffness(int e, double c, double s) const {
  const Element& el = elements_[e];
  if (dofs_per_node_ == 1) return bar_stiffness(el.E, el.area, el.length);
  return to_global(frame_stiffness_local(el.E, el.area, el.inertia, el.length), c, s);
}

Eigen::MatrixXd Model::element_mass(int e, double c, double s) const {
  const Element& el = elements_[e];
  if (dofs_per_node_ == 1)
    return lumped_ ? Eigen::Matrix2d(bar_mass_lumped(el.rho, el.area, el.length).asDiagonal())
                   : bar_mass_consistent(el.rho, el.area, el.length);
  // A lumped mass is the same in every frame (equal x and y translational masses).
  if (lumped_) return Mat6(frame_mass_lumped(el.rho, el.area, el.inertia, el.length, rotary_).asDiagonal());
  return to_global(frame_mass_consistent_local(el.rho, el.area, el.length), c, s);
}

int Model::equation(int n, int c) const {
  if (c >= dofs_per_node_) return -1;
  return dof_to_eq_[n * dofs_per_node_ + c];
}

std::vector<DofTerm> Model::project(int n, const Vec2& d) const {
  std::vector<DofTerm> terms;
  append_projection(n, d, 1.0, terms);
  return terms;
}

void Model::append_projection(int n, const Vec2& d, double scale, std::vector<DofTerm>& out) const {
  if (dofs_per_node_ == 3) {
    for (int c = 0; c < 2; ++c)
      if (const int e = equation(n, c); e >= 0 && d[c] != 0.0) out.push_back({e, scale * d[c]});
  } else if (const int e = equation(n, 0); e >= 0) {
    const double a = dot(axis_, d);
    if (a != 0.0) out.push_back({e, scale * a});
  }
}

Vec2 Model::node_vector(const Eigen::VectorXd& U, int n) const {
  if (dofs_per_node_ == 3) {
    const int ex = equation(n, 0), ey = equation(n, 1);
    return {ex >= 0 ? U(ex) : 0.0, ey >= 0 ? U(ey) : 0.0};
  }
  const int e = equation(n, 0);
  const double u = e >= 0 ? U(e) : 0.0;
  return {u * axis_[0], u * axis_[1]};
}

Eigen::VectorXd Model::initial_velocity() const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(size());
  for (int n = 0; n < num_nodes(); ++n) {
    const Vec2& bv = body_velocity_[node_body_[n]];
    if (dofs_per_node_ == 3) {
      if (const int e = equation(n, 0); e >= 0) v(e) = bv[0];
      if (const int e = equation(n, 1); e >= 0) v(e) = bv[1];
    } else if (const int e = equation(n, 0); e >= 0) {
      v(e) = dot(bv, axis_);
    }
  }
  return v;
}

Eigen::Matrix<int, 6, 1> Model::element_equations(int e) const {
  Eigen::Matrix<int, 6, 1> eq = Eigen::Matrix<int, 6, 1>::Constant(-1);
  const int nodes[2] = {elements_[e].n1, elements_[e].n2};
  for (int k = 0; k < 2; ++k)
    for (int c = 0; c < dofs_per_node_; ++c) eq(k * dofs_per_node_ + c) = equation(nodes[k], c);
  return eq;
}

}  // namespace beamimpact
