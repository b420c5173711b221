#include <beamimpact/model/top_eigenvalue.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace beamimpact {
namespace {

/// A quantity of the factorization of A(sigma) = sigma M - K with its first two derivatives in
/// sigma (forward-mode differentiation through the LDL^T recurrence).
struct Jet {
  double v = 0.0, d1 = 0.0, d2 = 0.0;
};
Jet operator-(Jet a, Jet b) { return {a.v - b.v, a.d1 - b.d1, a.d2 - b.d2}; }
Jet operator*(Jet a, Jet b) { return {a.v * b.v, a.d1 * b.v + a.v * b.d1, a.d2 * b.v + 2 * a.d1 * b.d1 + a.v * b.d2}; }
/// 1/a with its derivatives: one division per pivot instead of one per entry of L.
Jet reciprocal(Jet a) {
  const double r = 1.0 / a.v, r1 = -a.d1 * r * r;
  return {r, r1, -(a.d2 * r + 2 * a.d1 * r1) * r};
}
double reciprocal(double a) { return 1.0 / a; }
double value(double x) { return x; }
double value(const Jet& x) { return x.v; }
double entry(const EnvelopePencil& p, int i, int j, double sigma, double*) { return sigma * p.m(i, j) - p.k(i, j); }
Jet entry(const EnvelopePencil& p, int i, int j, double sigma, Jet*) {
  return {sigma * p.m(i, j) - p.k(i, j), p.m(i, j), 0.0};
}

/// LDL^T of sigma M - K within the envelope, stopping at the first pivot that is not positive.
/// Returns false then; otherwise true with `pivot` called on every pivot D_i.
/// Scratch of factor(): E_ij = L_ij D_j and L_ij packed like the pencil's rows (first(i) <= j <
/// i, at the pencil's offset of (i, j)), and 1/D_i. Kept across the iterates of one pencil.
template <class T>
struct Factors {
  std::vector<T> E, L, Dinv;
};

/// LDL^T of sigma M - K within the envelope, stopping at the first pivot that is not positive.
/// Returns false then; otherwise true with `pivot(D_i, 1/D_i)` called on every pivot.
template <class T, class OnPivot>
bool factor(const EnvelopePencil& p, double sigma, Factors<T>& f, OnPivot pivot) {
  const int d = p.size();
  f.E.resize(static_cast<std::size_t>(p.packed_size()));
  f.L.resize(f.E.size());
  f.Dinv.resize(static_cast<std::size_t>(d));
  for (int i = 0; i < d; ++i) {
    const int fi = p.first(i);
    T* Ei = f.E.data() + p.row_offset(i) - fi;  // Ei[j] = E_ij, j in [fi, i)
    T* Li = f.L.data() + p.row_offset(i) - fi;
    for (int j = fi; j < i; ++j) {
      const int fj = p.first(j);
      const T* Lj = f.L.data() + p.row_offset(j) - fj;
      T s = entry(p, i, j, sigma, static_cast<T*>(nullptr));
      for (int k = std::max(fi, fj); k < j; ++k) s = s - Ei[k] * Lj[k];
      Ei[j] = s;
      Li[j] = s * f.Dinv[j];
    }
    T di = entry(p, i, i, sigma, static_cast<T*>(nullptr));
    for (int k = fi; k < i; ++k) di = di - Ei[k] * Li[k];
    if (!(value(di) > 0.0)) return false;
    f.Dinv[i] = reciprocal(di);
    pivot(di, f.Dinv[i]);
  }
  return true;
}

/// sum 1/(sigma - lambda_i) and sum 1/(sigma - lambda_i)^2 at a sigma above the spectrum, from
/// the pivots: log det(sigma M - K) = sum log D_i. False when sigma is not above it.
bool laguerre_sums(const EnvelopePencil& p, double sigma, Factors<Jet>& f, double& G, double& H) {
  G = H = 0.0;
  return factor(p, sigma, f, [&](const Jet& piv, const Jet& inv) {
    const double r = piv.d1 * inv.v;  // (log D_i)'
    G += r;
    H += r * r - piv.d2 * inv.v;      // -(log D_i)''
  });
}

}  // namespace

EnvelopePencil::EnvelopePencil(std::vector<int> first) : first_(std::move(first)), offset_(first_.size() + 1, 0) {
  for (std::size_t i = 0; i < first_.size(); ++i)
    offset_[i + 1] = offset_[i] + static_cast<int>(i) - first_[i] + 1;
  k_.assign(static_cast<std::size_t>(offset_.back()), 0.0);
  m_ = k_;
}

EnvelopePencil EnvelopePencil::from_dense(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) {
  const int d = static_cast<int>(K.rows());
  std::vector<int> first(static_cast<std::size_t>(d));
  for (int i = 0; i < d; ++i) {
    int f = i;
    for (int j = 0; j < i; ++j)
      if (K(i, j) != 0.0 || M(i, j) != 0.0) {
        f = j;
        break;
      }
    first[i] = f;
  }
  EnvelopePencil p(first);
  for (int i = 0; i < d; ++i)
    for (int j = first[i]; j <= i; ++j) p.add(i, j, K(i, j), M(i, j));
  return p;
}

void EnvelopePencil::to_dense(Eigen::MatrixXd& K, Eigen::MatrixXd& M) const {
  K.setZero(size(), size());
  M.setZero(size(), size());
  for (int i = 0; i < size(); ++i)
    for (int j = first_[i]; j <= i; ++j) {
      K(i, j) = K(j, i) = k(i, j);
      M(i, j) = M(j, i) = m(i, j);
    }
}

bool above_spectrum(const EnvelopePencil& p, double sigma) {
  Factors<double> f;
  return factor(p, sigma, f, [](double, double) {});
}

TopEigenvalue top_eigenvalue(const EnvelopePencil& p, double start) {
  TopEigenvalue r;
  const double n = p.size(), eps = std::numeric_limits<double>::epsilon();
  Factors<Jet> f;
  double hi = start, G = 0.0, H = 0.0;
  r.factorizations = 1;
  if (p.size() == 0 || !std::isfinite(start) || !laguerre_sums(p, hi, f, G, H)) return r;
  double lo = -std::numeric_limits<double>::infinity();  // below: a sigma proven not above lambda_max
  for (int it = 0; it < 60; ++it) {
    const double a = n / (G + std::sqrt(std::max(0.0, (n - 1) * (n * H - G * G))));
    double trial = hi - a;
    if (a <= 4 * eps * std::abs(hi)) break;  // converged to roundoff
    if (trial <= lo) {
      // Laguerre aimed at or below a point already known to be below lambda_max: it lies in
      // (lo, hi], close to lo after an iterate that roundoff put just below the root.
      trial = lo + std::max(8 * eps * std::abs(lo), 1e-3 * (hi - lo));
      if (trial >= hi) break;
    }
    double Gt = 0.0, Ht = 0.0;
    ++r.factorizations;
    if (laguerre_sums(p, trial, f, Gt, Ht)) {
      hi = trial;
      G = Gt;
      H = Ht;
    } else {
      lo = trial;
      if (hi - lo <= 8 * eps * std::abs(hi)) break;
    }
  }
  r.ok = true;
  r.upper = hi;
  r.lower = std::max(lo, hi - n / G);  // G <= n / (sigma - lambda_max)
  return r;
}

}  // namespace beamimpact
