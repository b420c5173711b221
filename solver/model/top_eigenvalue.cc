#include <solver/model/top_eigenvalue.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace beamimpact {
namespace {

/// The two trial values of sigma that one pass factors, one per lane of an SSE2 register (GCC
/// and Clang vector extension: arithmetic acts on both lanes, each lane's bits are those of the
/// scalar operation).
using Pair = double __attribute__((vector_size(2 * sizeof(double))));

/// A quantity of the factorization of A(sigma) = sigma M - K with its first two derivatives in
/// sigma (forward-mode differentiation through the LDL^T recurrence), in both lanes.
struct Jet {
  Pair v{}, d1{}, d2{};
};
Jet operator-(const Jet& a, const Jet& b) { return {a.v - b.v, a.d1 - b.d1, a.d2 - b.d2}; }
Jet operator*(const Jet& a, const Jet& b) {
  return {a.v * b.v, a.d1 * b.v + a.v * b.d1, a.d2 * b.v + 2 * a.d1 * b.d1 + a.v * b.d2};
}
/// 1/a with its derivatives: one division per pivot instead of one per entry of L.
Jet reciprocal(const Jet& a) {
  const Pair r = Pair{1.0, 1.0} / a.v, r1 = -a.d1 * r * r;
  return {r, r1, -(a.d2 * r + 2 * a.d1 * r1) * r};
}
double reciprocal(double a) { return 1.0 / a; }
/// The lanes whose value is positive, as a bit mask.
unsigned positive(double x) { return x > 0.0 ? 1u : 0u; }
unsigned positive(const Jet& x) { return (x.v[0] > 0.0 ? 1u : 0u) | (x.v[1] > 0.0 ? 2u : 0u); }
/// The entry (i, j) of sigma M - K.
double entry(const EnvelopePencil& p, int i, int j, double sigma, double*) {
  return sigma * p.m(i, j) - p.k(i, j);
}
Jet entry(const EnvelopePencil& p, int i, int j, const Pair& sigma, Jet*) {
  const Pair m{p.m(i, j), p.m(i, j)}, k{p.k(i, j), p.k(i, j)};
  return {sigma * m - k, m, Pair{}};
}

/// Scratch of factor(): E_ij = L_ij D_j and L_ij packed like the pencil's rows (first(i) <= j <
/// i, at the pencil's offset of (i, j)), and 1/D_i. Kept across the iterates of one pencil.
template <class T>
struct Factors {
  std::vector<T> E, L, Dinv;
};

/// LDL^T of sigma M - K within the envelope in the lanes of the mask `lanes`. A lane drops out at
/// its first pivot that is not positive (its later values are meaningless); the factorization
/// stops when no lane is left. Returns the lanes whose pivots were all positive, with
/// `pivot(D_i, 1/D_i)` called on every pivot.
template <class T, class Sigma, class OnPivot>
unsigned factor(const EnvelopePencil& p, const Sigma& sigma, unsigned lanes, Factors<T>& f, OnPivot pivot) {
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
    lanes &= positive(di);
    if (lanes == 0) return 0;
    f.Dinv[i] = reciprocal(di);
    pivot(di, f.Dinv[i]);
  }
  return lanes;
}

/// Per lane, G = sum 1/(sigma - lambda_i) and H = sum 1/(sigma - lambda_i)^2 from the pivots
/// (log det(sigma M - K) = sum log D_i); valid in the lanes returned: those above the spectrum.
unsigned laguerre_sums(const EnvelopePencil& p, const Pair& sigma, unsigned lanes, Factors<Jet>& f, Pair& G,
                       Pair& H) {
  G = H = Pair{};
  return factor(p, sigma, lanes, f, [&](const Jet& piv, const Jet& inv) {
    const Pair r = piv.d1 * inv.v;  // (log D_i)'
    G += r;
    H += r * r - piv.d2 * inv.v;  // -(log D_i)''
  });
}

}  // namespace

EnvelopePencil::EnvelopePencil(std::vector<int> first)
    : first_(std::move(first)), offset_(first_.size() + 1, 0) {
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
  return factor(p, sigma, 1u, f, [](double, double) {}) != 0;
}

TopEigenvalue top_eigenvalue(const EnvelopePencil& p, double start) {
  TopEigenvalue r;
  const double n = p.size(), eps = std::numeric_limits<double>::epsilon();
  Factors<Jet> f;
  Pair G{}, H{};
  r.factorizations = 1;
  if (p.size() == 0 || !std::isfinite(start) || !(laguerre_sums(p, Pair{start, start}, 1u, f, G, H) & 1u))
    return r;
  double hi = start, G_hi = G[0], H_hi = H[0];
  double lo = -std::numeric_limits<double>::infinity();  // below: a sigma proven not above lambda_max
  for (int it = 0; it < 60; ++it) {
    // Laguerre's step, and the step that takes the top root as double: lane 1 tries it. A chain's
    // top is often a close pair (a mode at each end), where Laguerre's step is short.
    const double disc = n * H_hi - G_hi * G_hi;
    const double a = n / (G_hi + std::sqrt(std::max(0.0, (n - 1) * disc)));
    if (a <= 4 * eps * std::abs(hi)) break;  // converged to roundoff
    Pair trial{hi - a, hi - n / (G_hi + std::sqrt(std::max(0.0, (n / 2 - 1) * disc)))};
    unsigned lanes = trial[1] > lo ? 3u : 1u;  // lane 1 at or below lo would repeat a known failure
    if (trial[0] <= lo) {
      // Laguerre aimed at or below a point already known to be below lambda_max: it lies in
      // (lo, hi], close to lo after an iterate that roundoff put just below the root.
      trial[0] = lo + std::max(8 * eps * std::abs(lo), 1e-3 * (hi - lo));
      if (trial[0] >= hi) break;
    }
    if (lanes == 1u) trial[1] = trial[0];
    ++r.factorizations;
    const unsigned above = laguerre_sums(p, trial, lanes, f, G, H);
    if (above & 2u) {  // the lower trial is proven above
      hi = trial[1];
      G_hi = G[1];
      H_hi = H[1];
    } else if (above & 1u) {
      hi = trial[0];
      G_hi = G[0];
      H_hi = H[0];
      if (lanes & 2u) lo = std::max(lo, trial[1]);
    } else {
      lo = std::max(lo, trial[0]);  // the higher trial failed
    }
    if (hi - lo <= 8 * eps * std::abs(hi)) break;
  }
  r.ok = true;
  r.upper = hi;
  r.lower = std::max(lo, hi - n / G_hi);  // G <= n / (sigma - lambda_max)
  return r;
}

}  // namespace beamimpact
