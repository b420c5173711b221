#include <beamimpact/model/critical_dt.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>

#include <beamimpact/model/MassSolver.hpp>
#include <beamimpact/model/top_eigenvalue.hpp>
#include <beamimpact/util/spread_vector.hpp>

namespace beamimpact {
namespace {

/// Every this many iterations the top Ritz pair of T_k is solved (O(k^2), negligible next to
/// the O(n) iteration) and Lanczos stops once its residual is below kResidualTol of it.
constexpr int kCheckEvery = 8;
constexpr double kResidualTol = 1e-12;

/// Top Ritz value of the Lanczos tridiagonal T_k (alpha on the diagonal, beta below it) and the
/// residual norm beta_{k+1} |s_k| of its Ritz vector, by the tridiagonal QR method.
void top_ritz_pair(const std::vector<double>& alpha, const std::vector<double>& beta, LanczosEstimate& est) {
  const int k = static_cast<int>(alpha.size());
  const Eigen::Map<const Eigen::VectorXd> diag(alpha.data(), k);
  // beta[j] couples q_j and q_{j+1}; the first k-1 are T_k's sub-diagonal, beta[k-1] = beta_{k+1}.
  Eigen::VectorXd sub(std::max(k - 1, 0));
  for (int j = 0; j + 1 < k; ++j) sub(j) = beta[j];
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es;
  es.computeFromTridiagonal(diag, sub, Eigen::ComputeEigenvectors);
  est.ritz = es.eigenvalues()(k - 1);  // ascending
  est.residual = beta[k - 1] * std::abs(es.eigenvectors()(k - 1, k - 1));
  est.iterations = k;
}

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
    return es.info() == Eigen::Success ? es.eigenvalues().maxCoeff() : std::numeric_limits<double>::infinity();
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
  // Consecutive elements of a body are usually identical: their matrices are compared and the
  // eigenvalue reused, so a uniform body costs one 6x6 eigen-solve.
  double lam = 0.0;
  Eigen::MatrixXd K_last, M_last;
  double lam_last = 0.0;
  int last = -1;  // the last element whose matrices were formed
  for (int e = 0; e < static_cast<int>(model.elements().size()); ++e) {
    const Model::Element& el = model.elements()[e];
    if (el.rigid) continue;  // a rigid body has no element stiffness
    if (last >= 0 && model.same_element_matrices(e, last)) {  // equal matrices: no need to form them
      lam = std::max(lam, lam_last);
      continue;
    }
    last = e;
    Eigen::MatrixXd Ke = model.element_stiffness(e, el.c, el.s), Me = model.element_mass(e, el.c, el.s);
    if (Ke.size() != K_last.size() || Ke != K_last || Me != M_last) {
      lam_last = largest_generalized(Ke, Me, model.lumped());  // singular mass (no rotary inertia): inf
      K_last = std::move(Ke);
      M_last = std::move(Me);
    }
    lam = std::max(lam, lam_last);
  }
  return lam;
}

double subdomain_bound(const Model& model, int max_elements) {
  return subdomain_bound(model, max_elements, element_bound(model)).upper;
}

SubdomainBound subdomain_bound(const Model& model, int max_elements, double lam_element) {
  const std::vector<Model::Element>& els = model.elements();
  const int nel = static_cast<int>(els.size()), ne = 2 * model.dofs_per_node();
  SubdomainBound out;
  out.exact = true;
  double lam = 0.0, lam_last = 0.0;
  std::vector<int> eqs, first;
  std::vector<Eigen::Matrix<int, 6, 1>> eqk, locs;  // the run's elements' equations, local indices
  std::vector<double> key, key_last;
  Eigen::MatrixXd Ke, Me;  // the matrices of element `formed`: consecutive equal elements share them
  int formed = -1;
  for (int e = 0; e < nel;) {
    if (els[e].rigid) {  // a rigid body has no element stiffness
      ++e;
      continue;
    }
    int f = e;  // the subdomain: elements [e, f) of one elastic body
    while (f < nel && f - e < max_elements && els[f].body == els[e].body && !els[f].rigid) ++f;
    if ((e > 0 && els[e - 1].body == els[e].body) || (f < nel && els[f].body == els[e].body)) out.exact = false;
    // The run's key: each element's section, geometry and equation pattern relative to the
    // run's first equation. An equal key gives equal matrices: reuse the last eigenvalue.
    key.clear();
    eqs.clear();
    eqk.clear();
    for (int k = e; k < f; ++k) eqk.push_back(model.element_equations(k));
    const int first_eq = eqk.front().maxCoeff();
    for (int k = e; k < f; ++k) {
      const Model::Element& el = els[k];
      key.insert(key.end(), {el.E, el.area, el.inertia, el.rho, el.length, el.c, el.s});
      const Eigen::Matrix<int, 6, 1>& eq = eqk[k - e];
      for (int i = 0; i < ne; ++i) {
        key.push_back(eq(i) >= 0 ? eq(i) - first_eq : -1e9);
        if (eq(i) >= 0) eqs.push_back(eq(i));
      }
    }
    if (key == key_last) {
      lam = std::max(lam, lam_last);
      e = f;
      continue;
    }
    key_last = key;
    std::sort(eqs.begin(), eqs.end());
    eqs.erase(std::unique(eqs.begin(), eqs.end()), eqs.end());
    const int d = static_cast<int>(eqs.size());
    // Supported DOFs stay out: the model's vectors are zero there, so the subdomain's quotient
    // only needs its free DOFs. An element's local indices: its equations' ranks in the run.
    locs.clear();
    for (const Eigen::Matrix<int, 6, 1>& eq : eqk) {
      Eigen::Matrix<int, 6, 1> loc = Eigen::Matrix<int, 6, 1>::Constant(-1);
      for (int i = 0; i < ne; ++i)
        if (eq(i) >= 0) loc(i) = static_cast<int>(std::lower_bound(eqs.begin(), eqs.end(), eq(i)) - eqs.begin());
      locs.push_back(loc);
    }
    // The envelope: row r starts at the lowest local index of any element holding r.
    first.assign(static_cast<std::size_t>(d), d);
    for (const Eigen::Matrix<int, 6, 1>& loc : locs) {
      int low = d;
      for (int i = 0; i < ne; ++i) low = loc(i) >= 0 ? std::min(low, loc(i)) : low;
      for (int i = 0; i < ne; ++i)
        if (loc(i) >= 0) first[loc(i)] = std::min(first[loc(i)], low);
    }
    EnvelopePencil run(first);
    for (int k = e; k < f; ++k) {
      if (formed < 0 || !model.same_element_matrices(k, formed)) {
        Ke = model.element_stiffness(k, els[k].c, els[k].s);
        Me = model.element_mass(k, els[k].c, els[k].s);
        formed = k;
      }
      const Eigen::Matrix<int, 6, 1>& loc = locs[k - e];
      for (int i = 0; i < ne; ++i)
        for (int j = 0; j < ne; ++j)
          if (loc(i) >= 0 && loc(j) >= 0 && loc(j) <= loc(i)) run.add(loc(i), loc(j), Ke(i, j), Me(i, j));
    }
    lam_last = 0.0;  // no free DOF: nothing moves
    if (d > 0 && lam > 0.0 && above_spectrum(run, lam)) {
      lam_last = lam;  // proven below the largest so far: it cannot raise the bound
    } else if (d > 0) {
      // Down from Irons' bound, which no run's eigenvalue exceeds (1e-8: its roundoff).
      const TopEigenvalue top = top_eigenvalue(run, lam_element * (1 + 1e-8));
      if (top.ok) {
        lam_last = top.upper;
        out.lower = std::max(out.lower, top.lower);
      } else {  // M not positive definite (no rotary inertia): the dense solve says inf
        Eigen::MatrixXd Kc, Mc;
        run.to_dense(Kc, Mc);
        lam_last = largest_generalized(Kc, Mc, model.lumped());
      }
    }
    lam = std::max(lam, lam_last);
    e = f;
  }
  out.upper = lam;
  return out;
}

LanczosEstimate lanczos_largest(const Model& model, int max_iter) {
  LanczosEstimate est;
  const int n = model.size();
  if (n == 0 || max_iter <= 0) return est;
  const MassSolver minv(model);
  const bool lumped = model.lumped();
  const Eigen::VectorXd& m = model.lumped_mass();
  const Eigen::VectorXd& minv_diag = minv.inverse_diagonal();
  const SparseMatrix& K = model.K();
  const SparseMatrix& M = model.M();
  auto m_norm2 = [&](const Eigen::VectorXd& x, Eigen::VectorXd& scratch) {
    if (lumped) return x.dot(m.cwiseProduct(x));
    scratch.noalias() = M * x;
    return x.dot(scratch);
  };
  Eigen::VectorXd q = spread_vector(n),  // every DOF (every mode) carries energy
                  q_prev = Eigen::VectorXd::Zero(n), w(n), Kq(n), scratch(n);
  q /= std::sqrt(m_norm2(q, scratch));
  std::vector<double> alpha, beta;
  double b_prev = 0.0, a_max = 0.0;
  const int iters = std::min(max_iter, n);
  for (int j = 0; j < iters; ++j) {
    Kq.noalias() = K * q;
    const double a = q.dot(Kq);
    // w = M^-1 K q - a q - b_prev q_prev: the three-term recurrence in the M-inner product.
    if (lumped) {
      w.array() = Kq.array() * minv_diag.array() - a * q.array() - b_prev * q_prev.array();
    } else {
      minv.apply(Kq, w);
      w -= a * q + b_prev * q_prev;
    }
    const double b = std::sqrt(std::max(0.0, m_norm2(w, scratch)));
    alpha.push_back(a);
    beta.push_back(b);
    a_max = std::max(a_max, std::abs(a));
    const bool exhausted = b <= 1e-14 * a_max;  // invariant subspace: T_k holds exact eigenvalues
    if (exhausted || j + 1 == iters || (j + 1) % kCheckEvery == 0) {
      top_ritz_pair(alpha, beta, est);
      if (exhausted || est.residual <= kResidualTol * std::abs(est.ritz)) break;
    }
    q_prev.swap(q);
    q = w / b;
    b_prev = b;
  }
  return est;
}

CriticalStep critical_step(const Model& model) {
  CriticalStep c;
  const double lam_e = element_bound(model);
  const SubdomainBound sub = subdomain_bound(model, kSubdomainElements, lam_e);
  const double lam_s = sub.upper;
  c.element_bound_dt = step_of(model, std::sqrt(lam_e));
  if (sub.exact && sub.lower > 0.0) {
    // Every elastic body is one run: its Laguerre bracket already holds omega_max^2.
    c.ritz_omega = std::sqrt(sub.lower);
  } else {
    const LanczosEstimate lz = lanczos_largest(model, kLanczosMaxIterations);
    c.iterations = lz.iterations;
    c.ritz_omega = std::sqrt(std::max(lz.ritz, 0.0));
    c.residual = lz.residual;
    c.lanczos_dt = step_of(model, std::sqrt(std::max(lz.upper(), 0.0)));
  }
  if (lam_e <= 0.0) return c;  // no stiffness: no limit
  // Both bounds are proven; the subdomain one is never above the element one in exact
  // arithmetic, the min guards against its roundoff.
  const double lam = std::min(lam_s, lam_e);
  c.bound = lam_s < lam_e ? CriticalBound::kSubdomain : CriticalBound::kElement;
  c.omega_max = std::sqrt(lam);
  c.ritz_omega = std::min(c.ritz_omega, c.omega_max);  // a lower bound: roundoff may not lift it above
  c.dt = step_of(model, c.omega_max);
  return c;
}

}  // namespace beamimpact
