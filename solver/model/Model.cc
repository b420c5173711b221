#include <solver/model/Model.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <solver/model/frame_element.hpp>
#include <solver/model/timoshenko_element.hpp>
#include <solver/scene/collinear.hpp>
#include <solver/scene/support_axes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

double dot(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }

/// A nonzero entry (i, j) of an element matrix.
struct Nonzero {
  int i, j;
  double v;
};

/// What assembly needs of a group of equal elements' matrices: K_e's and M_e's nonzero entries
/// by rows, and M_e r for the two rigid translations r (columns: global x, y).
struct GroupEntries {
  std::vector<Nonzero> k, m;
  Eigen::Matrix<double, 6, 2> mr = Eigen::Matrix<double, 6, 2>::Zero();
};

/// A sparse matrix built from entries given twice in the same order: a counting pass (add()
/// before place()), then a placing pass. Each column's duplicates are summed in the order given
/// and its rows sorted: the bits of SparseMatrix::setFromTriplets on the same entries, without
/// storing them as triplets (100 MB at 1e6 DOFs) and without setFromTriplets' row-major copy and
/// its transpose.
class ColumnBuilder {
 public:
  explicit ColumnBuilder(int n) : A_(n, n), start_(static_cast<std::size_t>(n) + 1, 0) {}

  /// Entry (r, c) += v: counted before place(), stored after it.
  void add(int r, int c, double v) {
    if (!placing_) {
      ++start_[c + 1];
      return;
    }
    const int k = fill_[c]++;
    A_.innerIndexPtr()[k] = r;
    A_.valuePtr()[k] = v;
  }

  /// add(eq[z.i], eq[z.j], z.v) for each of an element's nonzeros z in order, those of a fixed
  /// DOF (-1) left out: the element loop's add() with the matrix's arrays held in registers.
  void add_element(const std::vector<Nonzero>& nonzeros, const int* eq) {
    if (!placing_) {
      int* count = start_.data() + 1;
      for (const Nonzero& z : nonzeros)
        if (eq[z.i] >= 0 && eq[z.j] >= 0) ++count[eq[z.j]];
      return;
    }
    int* fill = fill_.data();
    int* row = A_.innerIndexPtr();
    double* val = A_.valuePtr();
    for (const Nonzero& z : nonzeros)
      if (eq[z.i] >= 0 && eq[z.j] >= 0) {
        const int k = fill[eq[z.j]]++;
        row[k] = eq[z.i];
        val[k] = z.v;
      }
  }

  /// Ends the counting pass: each column's entries get their slots, in the order they come.
  void place() {
    const int n = static_cast<int>(A_.cols());
    for (int j = 0; j < n; ++j) start_[j + 1] += start_[j];
    A_.resizeNonZeros(start_[n]);
    fill_.assign(start_.begin(), start_.end() - 1);
    placing_ = true;
  }

  /// Moves the matrix into `out`: each column sorted by row (stable insertion sort: duplicates
  /// keep their order), then its duplicates summed in that order, compacted in place.
  void finish(SparseMatrix& out) {
    const int n = static_cast<int>(A_.cols());
    int* outer = A_.outerIndexPtr();
    int* row = A_.innerIndexPtr();
    double* val = A_.valuePtr();
    int nnz = 0;
    outer[0] = 0;
    for (int j = 0; j < n; ++j) {
      for (int a = start_[j] + 1; a < start_[j + 1]; ++a) {
        const int r = row[a];
        const double v = val[a];
        int b = a;
        for (; b > start_[j] && row[b - 1] > r; --b) {
          row[b] = row[b - 1];
          val[b] = val[b - 1];
        }
        row[b] = r;
        val[b] = v;
      }
      for (int a = start_[j]; a < start_[j + 1]; ++a) {
        if (nnz > outer[j] && row[nnz - 1] == row[a]) {
          val[nnz - 1] += val[a];
          continue;
        }
        row[nnz] = row[a];
        val[nnz] = val[a];
        ++nnz;
      }
      outer[j + 1] = nnz;
    }
    A_.resizeNonZeros(nnz);
    out.swap(A_);  // Eigen 3.4's SparseMatrix has no move assignment: it would copy
  }

 private:
  SparseMatrix A_;
  std::vector<int> start_;  ///< counts, then where each column's entries start
  std::vector<int> fill_;   ///< the next free slot of each column
  bool placing_ = false;
};

}  // namespace

/// The assembly's scratch: K and M built column by column, the summed lumped masses, and each
/// group's nonzero entries.
struct Model::Assembly {
  Assembly(int n, bool lumped) : kb(n), mb(lumped ? 0 : n), mdiag(Eigen::VectorXd::Zero(n)) {}
  ColumnBuilder kb, mb;  ///< mb: the consistent mass only (a lumped one is mdiag)
  Eigen::VectorXd mdiag;
  std::vector<GroupEntries> entries;
};

Model::Model(const Scene& scene, bool bending)
    : dofs_per_node_(bending ? 3 : 1),
      lumped_(scene.model.mass == MassKind::kLumped),
      rotary_(scene.model.rotary_inertia),
      a0_(scene.model.rayleigh_mass),
      a1_(scene.model.rayleigh_stiffness) {
  if (!bending && !scene_is_collinear(scene, &axis_))
    throw InputError(scene.file, "effects.bending",
                     "false requires all bodies and velocities on one line; this scene is not collinear");
  number_equations(scene, add_bodies(scene));
  assemble(scene, form_groups());
}

std::vector<char> Model::add_bodies(const Scene& scene) {
  // Nodes and fixed DOFs. A rigid body's nodes have none of their own (all fixed here): they
  // follow the body's centre, whose DOFs come after every node's.
  const int dpn = dofs_per_node_;
  std::size_t nodes = 0, elements = 0;  // room for all: no copy of a grown vector, no page touched twice
  for (const Body& body : scene.bodies) {
    nodes += static_cast<std::size_t>(body.nodes());
    elements += static_cast<std::size_t>(body.elements);
  }
  node_pos_.reserve(nodes);
  node_body_.reserve(nodes);
  elements_.reserve(elements);
  std::vector<char> fixed;
  fixed.reserve(nodes * dpn);
  for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b) {
    const Body& body = scene.bodies[b];
    body_centre_.push_back({0.5 * (body.start[0] + body.end[0]), 0.5 * (body.start[1] + body.end[1])});
    body_first_node_.push_back(static_cast<int>(node_pos_.size()));
    body_velocity_.push_back(body.velocity);
    body_mass_.push_back(body.rho * body.area * body.length());
    for (int i = 0; i < body.nodes(); ++i) {
      node_pos_.push_back(body.node_position(i));
      node_body_.push_back(b);
    }
    fixed.resize(node_pos_.size() * dpn, 0);
    if (body.rigid) std::fill(fixed.end() - body.nodes() * dpn, fixed.end(), 1);
    hold_supported(body, b, fixed);
    const Vec2 d = body.axis();
    const bool timoshenko = body.theory == BeamTheory::kTimoshenko && !body.rigid && dpn == 3;
    const double le = body.length() / body.elements;
    const double phi =
        timoshenko ? shear_parameter(body.inertia, body.area, le, body.shear_coefficient, body.poisson) : 0.0;
    for (int i = 0; i < body.elements; ++i)
      elements_.push_back({b, body_first_node_[b] + i, body_first_node_[b] + i + 1, body.rigid, timoshenko,
                           body.E, body.area, body.inertia, body.rho, le, d[0], d[1], phi});
  }
  if (!frame_.empty()) frame_.resize(node_pos_.size(), -1);
  return fixed;
}

void Model::number_equations(const Scene& scene, std::vector<char> fixed) {
  // Rigid bodies' centre DOFs: immovable when supported (the scene allows only a full fix).
  const int dpn = dofs_per_node_;
  const std::size_t node_dofs = fixed.size();
  std::vector<int> rigid_first(scene.bodies.size(), -1);
  for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b)
    if (scene.bodies[b].rigid) {
      rigid_first[b] = static_cast<int>(fixed.size());
      fixed.resize(fixed.size() + dpn, scene.bodies[b].supports.empty() ? 0 : 1);
    }
  dof_to_eq_.assign(fixed.size(), -1);
  free_.reserve(fixed.size());
  for (std::size_t d = 0; d < fixed.size(); ++d)
    if (!fixed[d]) {
      dof_to_eq_[d] = static_cast<int>(free_.size());
      free_.push_back(static_cast<int>(d));
    }
  rigid_eq_.assign(scene.bodies.size(), {kNotRigid, kNotRigid, kNotRigid});
  for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b)
    if (rigid_first[b] >= 0) {
      rigid_eq_[b] = {-1, -1, -1};
      for (int c = 0; c < dpn; ++c) rigid_eq_[b][c] = dof_to_eq_[rigid_first[b] + c];
    }
  dof_to_eq_.resize(node_dofs);  // node DOFs only: equation() never sees the centres' slots
  // Each element's equations, looked up once: the set-up asks for them several times an element.
  // An elastic body's element joins nodes n and n + 1, whose DOFs are consecutive: its equations
  // are those DOFs' (equation() without its per-DOF body lookup).
  const std::size_t w = 2 * static_cast<std::size_t>(dpn);
  element_eq_.resize(elements_.size() * w);
  for (int b = 0; b < num_bodies(); ++b) {
    const auto [first, end] = body_elements(b);
    for (int e = first; e < end; ++e) {
      int* out = element_eq_.data() + static_cast<std::size_t>(e) * w;
      const int n1 = body_first_node_[b] + (e - first);
      if (!rigid(b)) {
        std::copy_n(dof_to_eq_.data() + static_cast<std::size_t>(n1) * dpn, w, out);
        continue;
      }
      for (int k = 0; k < 2; ++k)
        for (int c = 0; c < dpn; ++c) out[k * dpn + c] = equation(n1 + k, c);
    }
  }
}

std::array<int, 2> Model::body_elements(int b) const {
  const int first_node = body_first_node_[b];
  const int end_node = b + 1 < num_bodies() ? body_first_node_[b + 1] : num_nodes();
  return {first_node - b, end_node - b - 1};
}

std::vector<int> Model::form_groups() {
  // Consecutive elements with equal matrices form a group; each group's matrices are formed once.
  group_.assign(elements_.size(), -1);
  std::vector<int> group_first;  // the first element of each group
  int last = -1;                 // the current group's first element
  for (int b = 0; b < num_bodies(); ++b) {
    const auto [first, end] = body_elements(b);
    if (first == end || elements_[first].rigid) continue;  // geometry only
    // add_bodies gives a body's elements copies of the same fields: with no node in its body's
    // axes, each after the first compares with `last` as the first did (joined: true), or as
    // `last` with itself when the body started the group (false with a NaN field).
    bool joined = false;
    for (int e = first; e < end; ++e) {
      const bool joins = e > first && !any_rotated() ? joined : last >= 0 && same_element_matrices(e, last);
      if (!joins) {
        const Element& el = elements_[e];
        ElementGroup& grp =
            groups_.emplace_back(ElementGroup{element_stiffness(e, el.c, el.s), element_mass(e, el.c, el.s)});
        to_node_axes(e, grp.K);
        if (!lumped_) to_node_axes(e, grp.M);  // a lumped mass is the same in every frame
        group_first.push_back(e);
        last = e;
      }
      joined = joins || same_element_matrices(e, e);
      group_[e] = static_cast<int>(groups_.size()) - 1;
    }
  }
  return group_first;
}

void Model::collect_entries(const std::vector<int>& group_first, Assembly& a) const {
  const int dpn = dofs_per_node_, ne = 2 * dpn;
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    const ElementGroup& grp = groups_[g];
    GroupEntries& ge = a.entries.emplace_back();
    for (int i = 0; i < ne; ++i)
      for (int j = 0; j < ne; ++j) {
        if (grp.K(i, j) != 0.0) ge.k.push_back({i, j, grp.K(i, j)});
        if (grp.M(i, j) != 0.0) ge.m.push_back({i, j, grp.M(i, j)});
      }
    for (int c = 0; c < 2; ++c) {  // rigid translation along global axis c, in element DOFs
      Eigen::VectorXd r = Eigen::VectorXd::Zero(ne);
      for (int k = 0; k < 2; ++k) {
        if (dpn == 3)
          r(3 * k + c) = 1.0;
        else
          r(k) = axis_[c];
      }
      to_node_axes(group_first[g], r);
      const Eigen::VectorXd m_r = grp.M * r;
      for (int i = 0; i < ne; ++i) ge.mr(i, c) = m_r(i);
    }
  }
}

void Model::assemble(const Scene& scene, const std::vector<int>& group_first) {
  // Element matrices in global axes, scattered to the free equations. Two passes over the
  // elements: the first counts the entries of K and M in each column and sums the momentum
  // covectors and lumped masses, the second places the entries.
  const int n = size();
  Assembly a(n, lumped_);
  momentum_.resize(static_cast<std::size_t>(num_bodies()));
  for (auto& covectors : momentum_)
    for (Eigen::VectorXd& v : covectors) v.setZero(n);
  collect_entries(group_first, a);
  for (int pass = 0; pass < 2; ++pass) {
    const bool counting = pass == 0;
    if (!counting) {
      a.kb.place();
      a.mb.place();
    }
    add_rigid_masses(scene, counting, a);
    add_elements(counting, a);
  }
  a.kb.finish(K_);
  if (!lumped_) {
    a.mb.finish(M_);
    return;
  }
  // M is the diagonal of the summed masses, every entry stored (a zero too).
  M_.resize(n, n);
  M_.resizeNonZeros(n);
  for (int i = 0; i < n; ++i) {
    M_.outerIndexPtr()[i] = i;
    M_.innerIndexPtr()[i] = i;
    M_.valuePtr()[i] = a.mdiag(i);
  }
  M_.outerIndexPtr()[n] = n;
  m_diag_ = std::move(a.mdiag);
}

void Model::add_rigid_masses(const Scene& scene, bool counting, Assembly& a) {
  // Rigid bodies: m, m, m L^2 / 12 at the centre.
  const int dpn = dofs_per_node_;
  for (int b = 0; b < num_bodies(); ++b) {
    if (!rigid(b)) continue;
    const Body& body = scene.bodies[b];
    const double m = body_mass_[b], L = body.length();
    const double masses[3] = {m, m, m * L * L / 12.0};
    for (int c = 0; c < dpn; ++c) {
      const int eq = rigid_eq_[b][c];
      if (eq < 0) continue;
      const double mc = dpn == 3 ? masses[c] : m;
      if (!lumped_)
        a.mb.add(eq, eq, mc);
      else if (counting)
        a.mdiag(eq) += mc;
      if (!counting) continue;
      if (dpn == 3 && c < 2)
        momentum_[b][c](eq) += mc;  // the centre's x or y translation
      else if (dpn == 1)
        for (int k = 0; k < 2; ++k) momentum_[b][k](eq) += mc * axis_[k];  // the rod axis
    }
  }
}

void Model::add_elements(bool counting, Assembly& a) {
  const int ne = 2 * dofs_per_node_;
  for (int b = 0; b < num_bodies(); ++b) {
    const auto [first, end] = body_elements(b);
    if (rigid(b)) continue;  // geometry only
    double* momentum[2] = {momentum_[b][0].data(), momentum_[b][1].data()};
    for (int e = first; e < end; ++e) {
      const GroupEntries& grp = a.entries[group_[e]];
      const int* eq = element_eq_.data() + static_cast<std::ptrdiff_t>(e) * ne;
      if (counting)
        for (int c = 0; c < 2; ++c)
          for (int i = 0; i < ne; ++i)
            if (eq[i] >= 0) momentum[c][eq[i]] += grp.mr(i, c);
      a.kb.add_element(grp.k, eq);
      if (!lumped_) {
        a.mb.add_element(grp.m, eq);
      } else if (counting) {
        for (const Nonzero& z : grp.m)
          if (eq[z.i] >= 0 && eq[z.j] >= 0) a.mdiag(eq[z.i]) += z.v;
      }
    }
  }
}

bool Model::same_element_matrices(int a, int b) const {
  const Element &x = elements_[a], &y = elements_[b];
  return x.E == y.E && x.area == y.area && x.inertia == y.inertia && x.rho == y.rho && x.length == y.length &&
         x.c == y.c && x.s == y.s && x.rigid == y.rigid && x.timoshenko == y.timoshenko && x.phi == y.phi &&
         !rotated(x.n1) && !rotated(x.n2) && !rotated(y.n1) && !rotated(y.n2);
}

void Model::hold_supported(const Body& body, int b, std::vector<char>& fixed) {
  if (body.rigid) return;  // a rigid body's support fixes its centre (in the constructor)
  for (const Support& s : body.supports) {
    const int n = body_first_node_[b] + s.node;
    const NodeHold h = node_hold(body, s.node);
    if (dofs_per_node_ == 1) {  // a rod only moves along its axis: holding an axial part fixes it
      fixed[n] |= h.held == 2 || (h.held == 1 && std::abs(dot(h.direction, axis_)) > 1e-12);
      continue;
    }
    fixed[3 * n + 2] |= h.theta;
    if (h.held == 0) continue;
    const Vec2& d = h.direction;
    if (h.held == 2 || d[1] == 0.0) fixed[3 * n] = 1;  // a pin, or exactly along x
    if (h.held == 2 || d[0] == 0.0) fixed[3 * n + 1] = 1;
    if (h.held == 2 || d[0] == 0.0 || d[1] == 0.0) continue;
    // One direction of an inclined body's own axes: the node's translations go into those axes,
    // component 0 axial, 1 normal, and the held one is fixed.
    if (frame_.size() < node_pos_.size()) frame_.resize(node_pos_.size(), -1);
    if (frame_[n] < 0) {
      frame_[n] = static_cast<int>(frames_.size());
      frames_.push_back(body.axis());
    }
    fixed[3 * n + (h.normal ? 1 : 0)] = 1;
  }
}

void Model::to_node_axes(int e, Eigen::MatrixXd& A) const {
  const Element& el = elements_[e];
  const int nodes[2] = {el.n1, el.n2};
  for (int k = 0; k < 2; ++k) {
    if (!rotated(nodes[k])) continue;
    const Vec2 a = node_axis(nodes[k]);
    Eigen::Matrix2d R;  // columns: the node's axes in global components
    R << a[0], -a[1], a[1], a[0];
    A.middleRows(3 * k, 2) = (R.transpose() * A.middleRows(3 * k, 2)).eval();
    A.middleCols(3 * k, 2) = (A.middleCols(3 * k, 2) * R).eval();
  }
}

void Model::to_node_axes(int e, Eigen::VectorXd& v) const {
  const Element& el = elements_[e];
  const int nodes[2] = {el.n1, el.n2};
  for (int k = 0; k < 2; ++k) {
    if (!rotated(nodes[k])) continue;
    const Vec2 a = node_axis(nodes[k]);
    const double x = v(3 * k), y = v(3 * k + 1);
    v(3 * k) = a[0] * x + a[1] * y;
    v(3 * k + 1) = -a[1] * x + a[0] * y;
  }
}

Eigen::MatrixXd Model::element_stiffness(int e, double c, double s) const {
  const Element& el = elements_[e];
  if (dofs_per_node_ == 1) return bar_stiffness(el.E, el.area, el.length);
  if (el.timoshenko)
    return to_global(timoshenko_stiffness_local(el.E, el.area, el.inertia, el.length, el.phi), c, s);
  return to_global(frame_stiffness_local(el.E, el.area, el.inertia, el.length), c, s);
}

Eigen::MatrixXd Model::element_mass(int e, double c, double s) const {
  const Element& el = elements_[e];
  if (dofs_per_node_ == 1)
    return lumped_ ? Eigen::Matrix2d(bar_mass_lumped(el.rho, el.area, el.length).asDiagonal())
                   : bar_mass_consistent(el.rho, el.area, el.length);
  // A lumped mass is the same in every frame (equal x and y translational masses).
  if (el.timoshenko && lumped_)
    return Mat6(timoshenko_mass_lumped(el.rho, el.area, el.inertia, el.length).asDiagonal());
  if (el.timoshenko)
    return to_global(timoshenko_mass_consistent_local(el.rho, el.area, el.inertia, el.length, el.phi), c, s);
  if (lumped_) return Mat6(frame_mass_lumped(el.rho, el.area, el.inertia, el.length, rotary_).asDiagonal());
  return to_global(frame_mass_consistent_local(el.rho, el.area, el.length), c, s);
}

int Model::equation(int n, int c) const {
  if (c >= dofs_per_node_) return -1;
  // Every point of a rigid body turns with its centre; its translations are not single DOFs.
  if (const auto& r = rigid_eq_[node_body_[n]]; r[0] != kNotRigid) return c == 2 ? r[2] : -1;
  return dof_to_eq_[n * dofs_per_node_ + c];
}

std::vector<DofTerm> Model::project(int n, const Vec2& d) const {
  std::vector<DofTerm> terms;
  append_projection(n, d, 1.0, terms);
  return terms;
}

void Model::append_projection(int n, const Vec2& d, double scale, std::vector<DofTerm>& out) const {
  if (const auto& r = rigid_eq_[node_body_[n]]; r[0] != kNotRigid) {
    // u(node) = u_c + theta (-ry, rx), r = X_node - X_c.
    const Vec2& X = node_pos_[n];
    const Vec2& C = body_centre_[node_body_[n]];
    if (dofs_per_node_ == 3) {
      const double lever = d[0] * -(X[1] - C[1]) + d[1] * (X[0] - C[0]);
      const double coeff[3] = {d[0], d[1], lever};
      for (int c = 0; c < 3; ++c)
        if (r[c] >= 0 && coeff[c] != 0.0) out.push_back({r[c], scale * coeff[c]});
    } else if (r[0] >= 0 && dot(axis_, d) != 0.0) {
      out.push_back({r[0], scale * dot(axis_, d)});
    }
    return;
  }
  if (dofs_per_node_ == 3) {
    const Vec2 dn = rotated(n) ? to_node(n, d) : d;
    for (int c = 0; c < 2; ++c)
      if (const int e = equation(n, c); e >= 0 && dn[c] != 0.0) out.push_back({e, scale * dn[c]});
  } else if (const int e = equation(n, 0); e >= 0) {
    const double a = dot(axis_, d);
    if (a != 0.0) out.push_back({e, scale * a});
  }
}

Vec2 Model::node_vector(const Eigen::VectorXd& U, int n) const {
  if (const auto& r = rigid_eq_[node_body_[n]]; r[0] != kNotRigid) {
    auto at = [&](int c) { return r[c] >= 0 ? U(r[c]) : 0.0; };
    if (dofs_per_node_ != 3) return {at(0) * axis_[0], at(0) * axis_[1]};
    const Vec2& X = node_pos_[n];
    const Vec2& C = body_centre_[node_body_[n]];
    const double th = at(2);
    return {at(0) - th * (X[1] - C[1]), at(1) + th * (X[0] - C[0])};
  }
  if (dofs_per_node_ == 3) {
    const int ex = equation(n, 0), ey = equation(n, 1);
    const Vec2 u = {ex >= 0 ? U(ex) : 0.0, ey >= 0 ? U(ey) : 0.0};
    if (!rotated(n)) return u;
    const Vec2 a = node_axis(n);  // u = a u0 + (a turned +90 deg) u1
    return {a[0] * u[0] - a[1] * u[1], a[1] * u[0] + a[0] * u[1]};
  }
  const int e = equation(n, 0);
  const double u = e >= 0 ? U(e) : 0.0;
  return {u * axis_[0], u * axis_[1]};
}

Eigen::VectorXd Model::translation(const std::vector<Vec2>& d) const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(size());
  for (int b = 0; b < num_bodies(); ++b)
    if (rigid(b)) {  // translation of the centre, no spin
      const Vec2& bv = d[b];
      const double comp[3] = {dofs_per_node_ == 3 ? bv[0] : dot(bv, axis_), bv[1], 0.0};
      for (int c = 0; c < dofs_per_node_; ++c)
        if (rigid_eq_[b][c] >= 0) v(rigid_eq_[b][c]) = comp[c];
    }
  for (int n = 0; n < num_nodes(); ++n) {
    const Vec2& bv = d[node_body_[n]];
    if (dofs_per_node_ == 3) {
      const Vec2 bn = rotated(n) ? to_node(n, bv) : bv;
      if (const int e = equation(n, 0); e >= 0) v(e) = bn[0];
      if (const int e = equation(n, 1); e >= 0) v(e) = bn[1];
    } else if (const int e = equation(n, 0); e >= 0) {
      v(e) = dot(bv, axis_);
    }
  }
  return v;
}

Eigen::Matrix<int, 6, 1> Model::element_equations(int e) const {
  Eigen::Matrix<int, 6, 1> eq = Eigen::Matrix<int, 6, 1>::Constant(-1);
  const std::span<const int> q = element_dofs(e);
  for (std::size_t i = 0; i < q.size(); ++i) eq(static_cast<Eigen::Index>(i)) = q[i];
  return eq;
}

}  // namespace beamimpact
