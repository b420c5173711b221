#include <references/exact/DelayMemory.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beamimpact::exact {

void DelayMemory::start_piece(double t) {
  starts_.push_back(t);
  t_.emplace_back();
  v_.emplace_back();
}

void DelayMemory::add(double t, double value) {
  if (starts_.empty()) throw std::logic_error("DelayMemory::add before start_piece");
  auto& ts = t_.back();
  // A sample at (almost) the same time as the last one would make the interpolation
  // ill-conditioned; keep the newer value.
  if (!ts.empty() && t <= ts.back() + 1e-14 * (1.0 + std::abs(t))) {
    v_.back().back() = value;
    return;
  }
  ts.push_back(t);
  v_.back().push_back(value);
}

long DelayMemory::piece_at(double s) const {
  auto it = std::upper_bound(starts_.begin(), starts_.end(), s);
  return static_cast<long>(it - starts_.begin()) - 1;
}

std::size_t DelayMemory::lower_bound_near(const std::vector<double>& ts, double s, std::size_t piece) const {
  // std::lower_bound's answer (the first sample >= s), searched outwards from the last answer on
  // this piece: the integrator's s advances by a few samples between calls, and a binary search
  // over a long memory costs a cache miss per level.
  const std::size_t n = ts.size();
  std::size_t lo = 0, hi = n;  // the answer lies in [lo, hi]
  if (piece == hint_piece_) {  // hint_ <= n: a piece's samples only grow
    std::size_t step = 1;
    if (hint_ < n && ts[hint_] < s) {  // the answer is above the hint
      lo = hint_ + 1;
      while (lo + step < n && ts[lo + step - 1] < s) {
        lo += step;
        step *= 2;
      }
      hi = std::min(n, lo + step);
    } else {  // ts[hint_] >= s (or hint_ = n): the answer is at or below the hint
      hi = hint_;
      while (hi >= step && ts[hi - step] >= s) {
        hi -= step;
        step *= 2;
      }
      lo = hi >= step ? hi - step : 0;
    }
  }
  const std::size_t k =
      static_cast<std::size_t>(std::lower_bound(ts.begin() + lo, ts.begin() + hi, s) - ts.begin());
  hint_piece_ = piece;
  hint_ = k;
  return k;
}

double DelayMemory::value(std::size_t i, double s) const {
  const auto& ts = t_[i];
  const auto& vs = v_[i];
  const std::size_t n = ts.size();
  if (n == 0) return 0.0;
  if (n == 1) return vs[0];
  // Degree-11 Lagrange on the 12 samples around s. With samples h = 1/(4 w) apart for the
  // highest modal frequency w, the error bound max|f^(12)| |prod(s - t_i)| / 12! is
  // (h w)^12 / 12 = 5e-9 of that mode's amplitude even for a one-sided stencil at a piece end,
  // and ~1e-11 in the middle of a piece.
  const std::size_t m = std::min<std::size_t>(12, n);
  const std::size_t k = lower_bound_near(ts, s, i);
  const std::size_t lo = std::min(k > m / 2 ? k - m / 2 : 0, n - m);
  // The same interpolant with the stencil's weights w_a = 1 / prod_{b != a} (t_a - t_b) computed
  // once per stencil: the integrator's stages ask for s in a few neighbouring stencils, over and
  // over (weights of the last few cached).
  const Stencil* st = nullptr;
  for (const Stencil& c : cache_)
    if (c.piece == i && c.lo == lo && c.m == m) st = &c;
  if (!st) {
    Stencil& c = cache_[next_slot_];
    next_slot_ = (next_slot_ + 1) % cache_.size();
    for (std::size_t a = 0; a < m; ++a) {
      double p = 1.0;
      for (std::size_t b = 0; b < m; ++b)
        if (b != a) p *= ts[lo + a] - ts[lo + b];
      c.w[a] = 1.0 / p;
    }
    c.piece = i;
    c.lo = lo;
    c.m = m;
    st = &c;
  }
  // p(s) = sum_a w_a v_a prod_{b != a} (s - t_b), the products from prefix and suffix
  // products: O(m) multiplications and no division.
  double d[12], suffix[13];
  suffix[m] = 1.0;
  for (std::size_t a = m; a-- > 0;) {
    d[a] = s - ts[lo + a];
    if (d[a] == 0.0) return vs[lo + a];  // on a sample: its value
    suffix[a] = suffix[a + 1] * d[a];
  }
  double prefix = 1.0, sum = 0.0;
  for (std::size_t a = 0; a < m; ++a) {
    sum += st->w[a] * vs[lo + a] * (prefix * suffix[a + 1]);
    prefix *= d[a];
  }
  return sum;
}

double DelayMemory::value(double s) const {
  const long i = piece_at(s);
  return i < 0 ? 0.0 : value(static_cast<std::size_t>(i), s);
}

std::size_t DelayMemory::samples() const {
  std::size_t n = 0;
  for (const auto& ts : t_) n += ts.size();
  return n;
}

}  // namespace beamimpact::exact
