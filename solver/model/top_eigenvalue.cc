#include <beamimpact/model/top_eigenvalue.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace beamimpact {
namespace {

/// Trial values of sigma factored in one pass, one per lane. The LDL^T recurrence is bound by
/// the latency of its chain of dependent operations, not by arithmetic, so two lanes cost about
/// as much as one.
template <std::size_t N>
using Lanes = std::array<double, N>;

/// A quantity of the factorization of A(sigma) = sigma M - K with its first two derivatives in
/// sigma (forward-mode differentiation through the LDL^T recurrence), in each of N lanes.
template <std::size_t N>
struct Jet {
  Lanes<N> v{}, d1{}, d2{};
};
template <std::size_t N>
Jet<N> operator-(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r;
  for (std::size_t l = 0; l < N; ++l) {
    r.v[l] = a.v[l] - b.v[l];
    r.d1[l] = a.d1[l] - b.d1[l];
    r.d2[l] = a.d2[l] - b.d2[l];
  }
  return r;
}
template <std::size_t N>
Jet<N> operator*(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r;
  for (std::size_t l = 0; l < N; ++l) {
    r.v[l] = a.v[l] * b.v[l];
    r.d1[l] = a.d1[l] * b.v[l] + a.v[l] * b.d1[l];
    r.d2[l] = a.d2[l] * b.v[l] + 2 * a.d1[l] * b.d1[l] + a.v[l] * b.d2[l];
  }
  return r;
}
/// 1/a with its derivatives: one division per pivot instead of one per entry of L.
template <std::size_t N>
Jet<N> reciprocal(const Jet<N>& a) {
  Jet<N> r;
  for (std::size_t l = 0; l < N; ++l) {
    r.v[l] = 1.0 / a.v[l];
    r.d1[l] = -a.d1[l] * r.v[l] * r.v[l];
    r.d2[l] = -(a.d2[l] * r.v[l] + 2 * a.d1[l] * r.d1[l]) * r.v[l];
  }
  return r;
}
double reciprocal(double a) { return 1.0 / a; }
/// The lanes whose value is positive, as a bit mask.
unsigned positive(double x) { return x > 0.0 ? 1u : 0u; }
template <std::size_t N>
unsigned positive(const Jet<N>& x) {
  unsigned mask = 0;
  for (std::size_t l = 0; l < N; ++l) mask |= x.v[l] > 0.0 ? 1u << l : 0u;
  return mask;
}
/// The entry (i, j) of sigma M - K.
double entry(const EnvelopePencil& p, int i, int j, const Lanes<1>& sigma, double*) {
  return sigma[0] * p.m(i, j) - p.k(i, j);
}
template <std::size_t N>
Jet<N> entry(const EnvelopePencil& p, int i, int j, const Lanes<N>& sigma, Jet<N>*) {
  Jet<N> r;
  for (std::size_t l = 0; l < N; ++l) {
    r.v[l] = sigma[l] * p.m(i, j) - p.k(i, j);
    r.d1[l] = p.m(i, j);
  }
  return r;
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
template <std::size_t N>
unsigned laguerre_sums(const EnvelopePencil& p, const Lanes<N>& sigma, unsigned lanes, Factors<Jet<N>>& f,
                       Lanes<N>& G, Lanes<N>& H) {
  G.fill(0.0);
  H.fill(0.0);
  return factor(p, sigma, lanes, f, [&](const Jet<N>& piv, const Jet<N>& inv) {
    for (std::size_t l = 0; l < N; ++l) {
      const double r = piv.d1[l] * inv.v[l];  // (log D_i)'
      G[l] += r;
      H[l] += r * r - piv.d2[l] * inv.v[l];   // -(log D_i)''
    }
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
  return factor(p, Lanes<1>{sigma}, 1u, f, [](double, double) {}) != 0;
}

TopEigenvalue top_eigenvalue(const EnvelopePencil& p, double start) {
  TopEigenvalue r;
  const double n = p.size(), eps = std::numeric_limits<double>::epsilon();
  Factors<Jet<2>> f;
  Lanes<2> G{}, H{};
  r.factorizations = 1;
  if (p.size() == 0 || !std::isfinite(start) || !(laguerre_sums<2>(p, Lanes<2>{start, start}, 1u, f, G, H) & 1u))
    return r;
  double hi = start, G_hi = G[0], H_hi = H[0];
  double lo = -std::numeric_limits<double>::infinity();  // below: a sigma proven not above lambda_max
  for (int it = 0; it < 60; ++it) {
    // Laguerre's step, and the step that takes the top root as double: lane 1 tries it. A chain's
    // top is often a close pair (a mode at each end), where Laguerre's step is short.
    const double disc = n * H_hi - G_hi * G_hi;
    const double a = n / (G_hi + std::sqrt(std::max(0.0, (n - 1) * disc)));
    if (a <= 4 * eps * std::abs(hi)) break;  // converged to roundoff
    Lanes<2> trial{hi - a, hi - n / (G_hi + std::sqrt(std::max(0.0, (n / 2 - 1) * disc)))};
    unsigned lanes = trial[1] > lo ? 3u : 1u;  // lane 1 at or below lo would repeat a known failure
    if (trial[0] <= lo) {
      // Laguerre aimed at or below a point already known to be below lambda_max: it lies in
      // (lo, hi], close to lo after an iterate that roundoff put just below the root.
      trial[0] = lo + std::max(8 * eps * std::abs(lo), 1e-3 * (hi - lo));
      if (trial[0] >= hi) break;
    }
    if (lanes == 1u) trial[1] = trial[0];
    ++r.factorizations;
    const unsigned above = laguerre_sums<2>(p, trial, lanes, f, G, H);
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
