#include <beamimpact/model/critical_dt.hpp>

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <beamimpact/model/MassSolver.hpp>

namespace beamimpact {
namespace {

double largest_ritz(const std::vector<double>& alpha, const std::vector<double>& beta) {
  const int m = static_cast<int>(alpha.size());
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(m, m);
  for (int i = 0; i < m; ++i) {
    T(i, i) = alpha[i];
    if (i + 1 < m) T(i, i + 1) = T(i + 1, i) = beta[i + 1];
  }
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(T, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
}

/// Largest omega^2 of any single element with its own mass. Irons' element bound: the assembled
/// omega_max^2 never exceeds it (and supports only lower the assembled value).
double element_bound(const Model& model) {
  double lam = 0.0;
  for (int e = 0; e < static_cast<int>(model.elements().size()); ++e) {
    const Model::Element& el = model.elements()[e];
    if (el.rigid) continue;  // a rigid body has no element stiffness
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(
        model.element_stiffness(e, el.c, el.s), model.element_mass(e, el.c, el.s), Eigen::EigenvaluesOnly);
    if (es.info() == Eigen::Success) lam = std::max(lam, es.eigenvalues().maxCoeff());
  }
  return lam;
}

}  // namespace

double largest_eigenvalue(const Model& model, int max_iter, int* iterations) {
  const int n = model.size();
  if (n == 0) return 0.0;
  const MassSolver minv(model);
  const SparseMatrix& K = model.K();
  const SparseMatrix& M = model.M();
  // Deterministic start vector with energy in every DOF.
  Eigen::VectorXd q(n), q_prev = Eigen::VectorXd::Zero(n), w(n), Mq(n);
  unsigned s = 12345u;
  for (int i = 0; i < n; ++i) {
    s = s * 1103515245u + 12345u;
    q(i) = 0.5 + static_cast<double>((s >> 8) & 0xffff) / 65536.0;
  }
  q /= std::sqrt(q.dot(M * q));
  std::vector<double> alpha, beta = {0.0};
  double last = 0.0;
  int stable = 0, it = 0;
  const int m = std::min(max_iter, n);
  for (it = 0; it < m; ++it) {
    const Eigen::VectorXd Kq = K * q;
    alpha.push_back(q.dot(Kq));
    minv.apply(Kq, w);  // w = M^-1 K q
    w -= alpha.back() * q + beta.back() * q_prev;
    Mq = M * w;
    const double b = std::sqrt(std::max(0.0, w.dot(Mq)));
    const double ritz = largest_ritz(alpha, beta);
    stable = std::abs(ritz - last) <= 1e-12 * std::abs(ritz) ? stable + 1 : 0;
    last = ritz;
    if (stable >= 5 || b <= 1e-14 * std::sqrt(std::abs(alpha.back()) + 1e-300)) break;
    beta.push_back(b);
    q_prev = q;
    q = w / b;
  }
  if (iterations) *iterations = it + 1;
  return last;
}

CriticalStep critical_step(const Model& model) {
  CriticalStep c;
  const double lam = largest_eigenvalue(model, 400, &c.iterations);
  c.omega_max = std::sqrt(std::max(lam, 0.0));
  // Central difference with Rayleigh damping: dt <= 2/omega (sqrt(1 + xi^2) - xi).
  const double xi = c.omega_max > 0 ? model.rayleigh_mass() / (2 * c.omega_max) +
                                          model.rayleigh_stiffness() * c.omega_max / 2
                                    : 0.0;
  c.dt = c.omega_max > 0 ? 2.0 / c.omega_max * (std::sqrt(1 + xi * xi) - xi) : 0.0;
  const double lam_e = element_bound(model);
  c.element_bound_dt = lam_e > 0 ? 2.0 / std::sqrt(lam_e) : 0.0;
  return c;
}

}  // namespace beamimpact
