#include <solver/model/critical_dt.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include <solver/model/top_eigenvalue.hpp>

namespace beamimpact {
namespace {

/// Largest eigenvalue of K x = lambda M x (K, M symmetric, lower triangles used), infinity when
/// the solve fails (a singular mass). A diagonal, positive M (lumped) is reduced to the standard
/// problem C = M^-1/2 K M^-1/2 with exactly the operations of Eigen's generalized solver (its
/// Cholesky factor of a diagonal is sqrt(m); its two triangular solves scale row i and column j
/// by the reciprocals 1/sqrt(m)), so the result is the same to the last bit at about half the
/// cost: no dense Cholesky, no dense triangular solves.
double largest_generalized(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, bool diagonal_mass) {
  const Eigen::Index d = K.rows();
  if (diagonal_mass && (M.diagonal().array() > 0.0).all()) {
    Eigen::MatrixXd C = K.selfadjointView<Eigen::Lower>();
    Eigen::VectorXd r(d);
    for (Eigen::Index i = 0; i < d; ++i) r(i) = 1.0 / std::sqrt(M(i, i));
    for (Eigen::Index j = 0; j < d; ++j)
      for (Eigen::Index i = 0; i < d; ++i) C(i, j) = (C(i, j) * r(i)) * r(j);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(C, Eigen::EigenvaluesOnly);
    return es.info() == Eigen::Success ? es.eigenvalues().maxCoeff()
                                       : std::numeric_limits<double>::infinity();
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M, Eigen::EigenvaluesOnly);
  return es.info() == Eigen::Success ? es.eigenvalues().maxCoeff() : std::numeric_limits<double>::infinity();
}

/// The critical step of central differences for a mode of angular frequency omega under Rayleigh
/// damping: 2/omega (sqrt(1 + xi^2) - xi), xi = a0/(2 omega) + a1 omega/2 (decreasing in omega).
double step_of(const Model& model, double omega) {
  if (!(omega > 0.0) || !std::isfinite(omega)) return 0.0;
  const double xi = model.rayleigh_mass() / (2 * omega) + model.rayleigh_stiffness() * omega / 2;
  return 2.0 / omega * (std::sqrt(1 + xi * xi) - xi);
}

/// Scratch of run_pencil(), kept across runs.
struct RunScratch {
  std::vector<int> eqs, first;
  std::vector<Eigen::Matrix<int, 6, 1>> locs;
};

/// The pencil of a run of elements e, e + 1, ... (their equations: `eqk`) on its free equations
/// but the sorted `held` ones (held at zero). Supported DOFs stay out: the model's vectors are
/// zero there, so the run's quotient only needs its free DOFs.
EnvelopePencil run_pencil(const Model& model, int e, const std::vector<Eigen::Matrix<int, 6, 1>>& eqk,
                          const std::vector<int>& held, RunScratch& s) {
  const int ne = 2 * model.dofs_per_node();
  auto is_held = [&](int q) { return std::binary_search(held.begin(), held.end(), q); };
  s.eqs.clear();
  for (const Eigen::Matrix<int, 6, 1>& eq : eqk)
    for (int i = 0; i < ne; ++i)
      if (eq(i) >= 0 && !is_held(eq(i))) s.eqs.push_back(eq(i));
  std::sort(s.eqs.begin(), s.eqs.end());
  s.eqs.erase(std::unique(s.eqs.begin(), s.eqs.end()), s.eqs.end());
  const int d = static_cast<int>(s.eqs.size());
  // An element's local indices: its equations' ranks in the run (-1: supported or held).
  s.locs.clear();
  for (const Eigen::Matrix<int, 6, 1>& eq : eqk) {
    Eigen::Matrix<int, 6, 1> loc = Eigen::Matrix<int, 6, 1>::Constant(-1);
    for (int i = 0; i < ne; ++i) {
      if (eq(i) < 0) continue;
      const auto it = std::lower_bound(s.eqs.begin(), s.eqs.end(), eq(i));
      if (it != s.eqs.end() && *it == eq(i)) loc(i) = static_cast<int>(it - s.eqs.begin());
    }
    s.locs.push_back(loc);
  }
  // The envelope: row r starts at the lowest local index of any element holding r.
  s.first.assign(static_cast<std::size_t>(d), d);
  for (const Eigen::Matrix<int, 6, 1>& loc : s.locs) {
    int low = d;
    for (int i = 0; i < ne; ++i) low = loc(i) >= 0 ? std::min(low, loc(i)) : low;
    for (int i = 0; i < ne; ++i)
      if (loc(i) >= 0) s.first[loc(i)] = std::min(s.first[loc(i)], low);
  }
  EnvelopePencil run(s.first);
  for (int k = e; k < e + static_cast<int>(eqk.size()); ++k) {
    const Eigen::MatrixXd &Ke = model.reference_stiffness(k), &Me = model.reference_mass(k);
    const Eigen::Matrix<int, 6, 1>& loc = s.locs[k - e];
    for (int i = 0; i < ne; ++i)
      for (int j = 0; j < ne; ++j)
        if (loc(i) >= 0 && loc(j) >= 0 && loc(j) <= loc(i)) run.add(loc(i), loc(j), Ke(i, j), Me(i, j));
  }
  return run;
}

/// The equations of elements [e, f).
void run_equations(const Model& model, int e, int f, std::vector<Eigen::Matrix<int, 6, 1>>& eqk) {
  eqk.clear();
  for (int k = e; k < f; ++k) eqk.push_back(model.element_equations(k));
}

/// A run whose top eigenvalue Laguerre's iteration solved: its bound and its elements [e, f).
struct Solved {
  double upper;
  int e, f;
};

/// The largest of element e's equations (-1 when all are fixed).
int top_equation(const Model& model, int e) {
  const std::span<const int> q = model.element_dofs(e);
  return std::max(-1, *std::max_element(q.begin(), q.end()));
}

/// Whether elements a and b have equal matrices: those of one group (Model::element_group) have;
/// others when they have the same section and geometry and, when some node is in its body's
/// axes, the same axes at their nodes.
bool same_matrices(const Model& model, int a, int b) {
  const int g = model.element_group(a);
  if (g >= 0 && g == model.element_group(b)) return true;
  const Model::Element &x = model.elements()[a], &y = model.elements()[b];
  if (!(x.E == y.E && x.area == y.area && x.inertia == y.inertia && x.rho == y.rho && x.length == y.length &&
        x.c == y.c && x.s == y.s))
    return false;
  if (!model.any_rotated()) return true;
  for (const auto& [p, q] : {std::pair{x.n1, y.n1}, std::pair{x.n2, y.n2}})
    if (!(model.node_axis(p)[0] == model.node_axis(q)[0] && model.node_axis(p)[1] == model.node_axis(q)[1]))
      return false;
  return true;
}

/// Whether the runs of `count` elements from e and `count_l` from le have equal matrices: as
/// many elements, each with the same matrices (same_matrices) and the same equation pattern
/// relative to its run's first element's largest equation. Compared in place, element by element
/// (no key formed, no equations copied).
bool same_run(const Model& model, int e, int count, int le, int count_l) {
  if (count_l == 0 || count != count_l) return false;
  const int ne = 2 * model.dofs_per_node();
  const int a0 = top_equation(model, e), b0 = top_equation(model, le);
  for (int k = 0; k < count; ++k) {
    if (!same_matrices(model, e + k, le + k)) return false;
    const std::span<const int> eqk = model.element_dofs(e + k), eql = model.element_dofs(le + k);
    for (int i = 0; i < ne; ++i) {
      const int p = eqk[i], q = eql[i];
      if ((p >= 0) != (q >= 0) || (p >= 0 && p - a0 != q - b0)) return false;
    }
  }
  return true;
}

/// A run with the equations it shares with the rest of its body held at zero is the whole
/// model's pencil restricted to its other equations: by Cauchy's interlacing its top eigenvalue
/// is a lower bound of the model's. The largest over the solved runs, tried from the highest
/// bound down (a held run's top is below its own bound, so the search stops when the next bound
/// is below the best so far); each from its bound (1e-8: the factorization's roundoff), and
/// Laguerre's bracket gives the lower end. Returns max(lower, what the held runs give).
double held_runs_lower_bound(const Model& model, std::vector<Solved> solved, double lower,
                             RunScratch& scratch) {
  const std::vector<Model::Element>& els = model.elements();
  const int nel = static_cast<int>(els.size()), ne = 2 * model.dofs_per_node();
  std::vector<Eigen::Matrix<int, 6, 1>> eqk;
  std::sort(solved.begin(), solved.end(), [](const Solved& a, const Solved& b) { return a.upper > b.upper; });
  std::vector<int> held;
  for (const auto& [upper, e, f] : solved) {
    if (upper <= lower) break;
    held.clear();
    for (int k : {e - 1, f})
      if (k >= 0 && k < nel && els[k].body == els[e].body)
        for (int i = 0; i < ne; ++i)
          if (const int q = model.element_equations(k)(i); q >= 0) held.push_back(q);
    std::sort(held.begin(), held.end());
    run_equations(model, e, f, eqk);
    const TopEigenvalue top = top_eigenvalue(run_pencil(model, e, eqk, held, scratch), upper * (1 + 1e-8));
    if (top.ok) lower = std::max(lower, top.lower);
  }
  return lower;
}

/// The subdomain bound's scan over runs, in order: the largest top eigenvalue so far (lam), the
/// largest lower end of Laguerre's brackets, and the runs it solved.
struct RunScan {
  RunScan(const Model& m, double lam_e) : model(m), lam_element(lam_e) {}

  /// Run [e, f): the last new run's eigenvalue when their matrices are equal, else its own.
  void add(int e, int f) {
    if (same_run(model, e, f - e, e_last, count_last)) {  // equal matrices: reuse the last eigenvalue
      lam = std::max(lam, lam_last);
      return;
    }
    e_last = e;
    count_last = f - e;
    run_equations(model, e, f, eqk);
    const EnvelopePencil run = run_pencil(model, e, eqk, {}, scratch);
    const int d = run.size();
    lam_last = 0.0;  // no free DOF: nothing moves
    if (d > 0 && lam > 0.0 && above_spectrum(run, lam)) {
      lam_last = lam;  // proven below the largest so far: it cannot raise the bound
    } else if (d > 0) {
      // Down from Irons' bound, which no run's eigenvalue exceeds (1e-8: its roundoff).
      const TopEigenvalue top = top_eigenvalue(run, lam_element * (1 + 1e-8));
      if (top.ok) {
        lam_last = top.upper;
        bracket_lower = std::max(bracket_lower, top.lower);
        solved.push_back({top.upper, e, f});
      } else {  // M not positive definite (no rotary inertia): the dense solve says inf
        Eigen::MatrixXd Kc, Mc;
        run.to_dense(Kc, Mc);
        lam_last = largest_generalized(Kc, Mc, model.lumped());
      }
    }
    lam = std::max(lam, lam_last);
  }

  const Model& model;
  double lam_element;
  double lam = 0.0, lam_last = 0.0, bracket_lower = 0.0;
  std::vector<Solved> solved;  ///< the runs Laguerre's iteration solved
  RunScratch scratch;
  std::vector<Eigen::Matrix<int, 6, 1>> eqk;  ///< the run's elements' equations
  int e_last = 0, count_last = 0;             ///< the last new run's first element and size
};

}  // namespace

const char* to_string(CriticalBound b) {
  switch (b) {
    case CriticalBound::kElement: return "element";
    case CriticalBound::kSubdomain: return "subdomain";
    case CriticalBound::kNone: break;
  }
  return "none";
}

double element_bound(const Model& model) {
  // Consecutive equal elements share a group: one eigen-solve per group (a uniform body: one).
  double lam = 0.0, lam_last = 0.0;
  int last = -1;  // the group of the last elastic element
  for (int e = 0; e < static_cast<int>(model.elements().size()); ++e) {
    const int g = model.element_group(e);
    if (g < 0) continue;  // a rigid body has no element stiffness
    if (g != last) {      // singular mass (no rotary inertia): inf
      lam_last = largest_generalized(model.reference_stiffness(e), model.reference_mass(e), model.lumped());
      last = g;
    }
    lam = std::max(lam, lam_last);
  }
  return lam;
}

double subdomain_bound(const Model& model, int max_elements) {
  return subdomain_bound(model, max_elements, element_bound(model)).upper;
}

SubdomainBound subdomain_bound(const Model& model, int max_elements, double lam_element) {
  SubdomainBound out;
  out.exact = true;
  RunScan scan(model, lam_element);
  // Each elastic body in subdomains of up to max_elements (a rigid body has no element stiffness).
  for (int b = 0; b < model.num_bodies(); ++b) {
    const auto [first, end] = model.body_elements(b);
    if (model.rigid(b)) continue;
    for (int e = first, f = first; e < end; e = f) {
      f = end - e > max_elements ? e + max_elements : end;  // the subdomain: elements [e, f)
      if (e > first || f < end) out.exact = false;
      scan.add(e, f);
    }
  }
  out.upper = scan.lam;
  // Each body one run: its bracket holds its top eigenvalue; else the held runs give the lower end.
  out.lower = out.exact ? scan.bracket_lower
                        : held_runs_lower_bound(model, std::move(scan.solved), out.lower, scan.scratch);
  return out;
}

CriticalStep critical_step(const Model& model) {
  CriticalStep c;
  const double lam_e = element_bound(model);
  const SubdomainBound sub = subdomain_bound(model, kSubdomainElements, lam_e);
  const double lam_s = sub.upper;
  c.element_bound_dt = step_of(model, std::sqrt(lam_e));
  c.omega_lower = std::sqrt(sub.lower);
  if (lam_e <= 0.0) return c;  // no stiffness: no limit
  // Both bounds are proven; the subdomain one is never above the element one in exact
  // arithmetic, the min guards against its roundoff.
  const double lam = std::min(lam_s, lam_e);
  c.bound = lam_s < lam_e ? CriticalBound::kSubdomain : CriticalBound::kElement;
  c.omega_max = std::sqrt(lam);
  c.omega_lower = std::min(c.omega_lower, c.omega_max);  // a lower bound: roundoff may not lift it above
  c.dt = step_of(model, c.omega_max);
  return c;
}

}  // namespace beamimpact
