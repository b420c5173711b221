#pragma once
/// @file Model.hpp
/// @brief The assembled beam model of a scene: DOF numbering with supports eliminated, sparse
/// stiffness K, mass M (a diagonal when lumped), Rayleigh damping, initial state, and the maps
/// from nodes to equations that contact, output and references need.
///
/// Two layouts: "frame" (3 DOF per node: u_x, u_y, theta) and "rod" (1 DOF per node: the
/// displacement along the common axis of an all-collinear scene). Supported DOFs are removed from
/// the equations; equation(node, component) returns -1 for them.
///
/// A frame node's translations are in its own axes: a node whose supports hold one direction of
/// an inclined body's own axes (a roller across or along it: fix = ["normal"] or ["axial"]) has
/// components 0 and 1 along the body's axial and normal directions (node_axis()), and its
/// elements' matrices are T^T K_e T with T the rotation from those axes to global ones. Every
/// other node uses global x, y. project(), node_vector() and translation() give global vectors
/// for both; code that reads components 0 and 1 of equation() directly must use node_axis().

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <solver/scene/Scene.hpp>

namespace beamimpact {

/// @brief Sparse matrix type of the project (column-major, double).
using SparseMatrix = Eigen::SparseMatrix<double>;

/// @brief One term of a linear functional of the equation vector: coeff * U[eq].
struct DofTerm {
  int eq;
  double coeff;
};

/// @brief The assembled linear model (reference configuration, global axes).
class Model {
 public:
  /// @brief Assembles the scene. bending = false builds the rod layout (the scene must be
  /// collinear: InputError otherwise).
  Model(const Scene& scene, bool bending);

  /// @brief 3 (frame) or 1 (rod).
  int dofs_per_node() const { return dofs_per_node_; }
  /// @brief Unit axis of the rod layout (undefined for frames).
  const Vec2& rod_axis() const { return axis_; }
  /// @brief Number of equations (free DOFs).
  int size() const { return static_cast<int>(free_.size()); }
  /// @brief Total number of nodes over all bodies.
  int num_nodes() const { return static_cast<int>(node_pos_.size()); }
  /// @brief Global node id of node `i` of body `b`.
  int node_id(int b, int i) const { return body_first_node_[b] + i; }
  /// @brief Body that owns global node `n`.
  int body_of_node(int n) const { return node_body_[n]; }
  /// @brief Reference position of global node `n` (m).
  const Vec2& node_position(int n) const { return node_pos_[n]; }
  /// @brief Equation of component c (0 = x, 1 = y, 2 = theta; rod layout: 0 = axial) of node n,
  /// or -1 when that DOF is fixed or absent. On a rotated node (rotated()) components 0 and 1 are
  /// along node_axis(n) and that turned +90 degrees.
  int equation(int n, int c) const;
  /// @brief True when node n's translations are in the axes of its body (see the file comment).
  bool rotated(int n) const { return !frame_.empty() && frame_[n] >= 0; }
  /// @brief Global unit direction of translational component 0 of node n: (1, 0) unless rotated();
  /// component 1 is this turned +90 degrees (frame layout).
  Vec2 node_axis(int n) const { return rotated(n) ? frames_[frame_[n]] : Vec2{1.0, 0.0}; }
  /// @brief True when some node is rotated().
  bool any_rotated() const { return !frame_.empty(); }
  /// @brief The components of a global vector d in node n's axes (d itself unless rotated()).
  Vec2 to_node(int n, const Vec2& d) const {
    const Vec2 a = node_axis(n);
    return {a[0] * d[0] + a[1] * d[1], -a[1] * d[0] + a[0] * d[1]};
  }
  /// @brief A = T^T A T for an element matrix (6 x 6, global axes) of element e: its rotated
  /// nodes' translations into their node axes; unchanged when neither node is rotated.
  void to_node_axes(int e, Eigen::MatrixXd& A) const;
  /// @brief v = T^T v for an element vector (6, global axes) of element e (see to_node_axes).
  void to_node_axes(int e, Eigen::VectorXd& v) const;
  /// @brief Terms of d . u(node n) for a direction d in global axes (handles both layouts).
  std::vector<DofTerm> project(int n, const Vec2& d) const;
  /// @brief Appends scale * (terms of d . u(node n)) to out (no allocation once out has capacity).
  void append_projection(int n, const Vec2& d, double scale, std::vector<DofTerm>& out) const;
  /// @brief Global displacement (x, y) of node n from the equation vector U.
  Vec2 node_vector(const Eigen::VectorXd& U, int n) const;

  /// @brief Stiffness, free x free.
  const SparseMatrix& K() const { return K_; }
  /// @brief Mass, free x free (diagonal when lumped).
  const SparseMatrix& M() const { return M_; }
  /// @brief True when the mass is lumped (then lumped_mass() is its diagonal).
  bool lumped() const { return lumped_; }
  /// @brief Diagonal of the lumped mass (empty for consistent mass).
  const Eigen::VectorXd& lumped_mass() const { return m_diag_; }
  /// @brief Rayleigh coefficients (a0 1/s, a1 s); damped() when any is non-zero.
  double rayleigh_mass() const { return a0_; }
  double rayleigh_stiffness() const { return a1_; }
  bool damped() const { return a0_ != 0.0 || a1_ != 0.0; }

  /// @brief Initial velocity (each body's rigid velocity on its free DOFs).
  Eigen::VectorXd initial_velocity() const { return translation(body_velocity_); }
  /// @brief The equation vector of a rigid translation of each body b by d[b] (m or m/s): d[b]
  /// on its nodes' x, y DOFs (rod layout: d[b] along the axis; a rigid body: its centre), no
  /// rotation; fixed DOFs left out.
  /// @param d one vector per body, global axes
  Eigen::VectorXd translation(const std::vector<Vec2>& d) const;
  /// @brief Momentum covector of body b along direction c (0 = x, 1 = y): p = m^T V.
  /// Includes the mass of every free DOF of the body (consistent mass: rotations too).
  const Eigen::VectorXd& momentum_covector(int b, int c) const { return momentum_[b][c]; }
  /// @brief Total mass of body b (kg).
  double body_mass(int b) const { return body_mass_[b]; }
  /// @brief Number of bodies.
  int num_bodies() const { return static_cast<int>(body_first_node_.size()); }
  /// @brief The range [first, end) of body b's elements in elements() (a body's elements are
  /// consecutive: per-body loops need not read every element's `body`).
  /// @param b body index
  std::array<int, 2> body_elements(int b) const;
  /// @brief One element: its body, global node ids, section and reference geometry.
  struct Element {
    int body, n1, n2;
    bool rigid = false;            ///< of a rigid body: geometry only (no stiffness, no mass of its own)
    bool timoshenko = false;       ///< Timoshenko element (timoshenko_element.hpp), else Euler-Bernoulli
    double E, area, inertia, rho;  ///< N/m^2, m^2, m^4, kg/m^3
    double length, c, s;           ///< m; direction cosines of the reference axis
    double phi = 0.0;              ///< shear parameter 12 E I / (kappa G A length^2); 0 when Euler-Bernoulli
  };
  /// @brief The element list (per-element work: corotation, bounds), body by body in the scene's
  /// order and each body's from its start to its end: a body's elements are one range, sorted by
  /// `body` (DeformedSurface finds it by bisection).
  const std::vector<Element>& elements() const { return elements_; }
  /// @brief The group of element e: a run of consecutive elastic elements with the same section,
  /// material, length and direction, hence equal matrices; -1 for an element of a rigid body.
  /// Per-element work that depends only on the matrices (eigenvalues, blocks) is done per group.
  int element_group(int e) const { return group_[e]; }
  /// @brief Stiffness of elastic element e in global axes at its reference direction, formed
  /// once per group (element_group()).
  const Eigen::MatrixXd& reference_stiffness(int e) const { return groups_[group_[e]].K; }
  /// @brief Mass of elastic element e in global axes, formed once per group.
  const Eigen::MatrixXd& reference_mass(int e) const { return groups_[group_[e]].M; }
  /// @brief Element stiffness in global axes at direction (c, s): 6x6 (frame) or 2x2 (rod).
  Eigen::MatrixXd element_stiffness(int e, double c, double s) const;
  /// @brief Element mass in global axes at direction (c, s): 6x6 (frame) or 2x2 (rod).
  Eigen::MatrixXd element_mass(int e, double c, double s) const;
  /// @brief True when body b is rigid: its nodes move with the 3 (frame) or 1 (rod) DOFs of its
  /// centre, u(node) = u_c + theta x (X_node - X_c) (small rotations).
  bool rigid(int b) const { return rigid_eq_[b][0] != kNotRigid; }
  /// @brief Equation index of each of the element's 6 (frame) or 2 (rod) DOFs, -1 when fixed.
  Eigen::Matrix<int, 6, 1> element_equations(int e) const;
  /// @brief element_equations(e) in place: its 2 x dofs_per_node() entries, no copy (the set-up's
  /// loops over every element read them this way).
  /// @param e element index
  std::span<const int> element_dofs(int e) const {
    const std::size_t w = 2 * static_cast<std::size_t>(dofs_per_node_);
    return {element_eq_.data() + static_cast<std::size_t>(e) * w, w};
  }

 private:
  static constexpr int kNotRigid = -2;
  /// The reference matrices shared by a group of consecutive equal elements.
  struct ElementGroup {
    Eigen::MatrixXd K, M;
  };
  /// True when elements a and b have the same section, material, length and direction (and
  /// neither has a rotated node).
  bool same_element_matrices(int a, int b) const;
  /// Fixes the DOFs that the supports of body b hold, setting the node axes of its rotated nodes.
  void hold_supported(const Body& body, int b, std::vector<char>& fixed);
  /// The construction's steps, in order: nodes, elements and fixed DOFs (returned per node DOF);
  /// equations of the free DOFs and rigid centres; element groups (returned: each group's first
  /// element); K, M and the momentum covectors.
  std::vector<char> add_bodies(const Scene& scene);
  void number_equations(const Scene& scene, std::vector<char> fixed);
  std::vector<int> form_groups();
  struct Assembly;  ///< the assembly's scratch (Model.cc)
  void assemble(const Scene& scene, const std::vector<int>& group_first);
  /// Each group's nonzero entries of K_e and M_e and its M_e r for the rigid translations.
  void collect_entries(const std::vector<int>& group_first, Assembly& a) const;
  /// The assembly's passes (counting, then placing) over rigid bodies' masses and over elements.
  void add_rigid_masses(const Scene& scene, bool counting, Assembly& a);
  void add_elements(bool counting, Assembly& a);
  /// Per body: equations of its centre (x, y, theta; rods: axial), -1 when fixed, kNotRigid for
  /// an elastic body.
  std::vector<std::array<int, 3>> rigid_eq_;
  std::vector<Vec2> body_centre_;
  int dofs_per_node_ = 3;
  Vec2 axis_{1.0, 0.0};
  bool lumped_ = true;
  RotaryInertia rotary_ = RotaryInertia::kHrz;
  double a0_ = 0.0, a1_ = 0.0;
  std::vector<int> body_first_node_, node_body_;
  std::vector<Vec2> node_pos_;
  std::vector<int> frame_;       ///< node -> index into frames_, -1 global axes; empty: none rotated
  std::vector<Vec2> frames_;     ///< unit axis of component 0 of each rotated node
  std::vector<int> dof_to_eq_;   ///< node * dofs_per_node + c -> equation or -1
  std::vector<int> free_;        ///< equation -> node * dofs_per_node + c
  std::vector<int> element_eq_;  ///< element e's equations at [2 dofs_per_node e, ...), -1 when fixed
  std::vector<Element> elements_;
  std::vector<ElementGroup> groups_;
  std::vector<int> group_;  ///< element -> its group in groups_, -1 for a rigid body's
  std::vector<Vec2> body_velocity_;
  std::vector<double> body_mass_;
  std::vector<std::array<Eigen::VectorXd, 2>> momentum_;
  SparseMatrix K_, M_;
  Eigen::VectorXd m_diag_;
};

}  // namespace beamimpact
