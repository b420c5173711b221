#include <beamimpact/exact/DelayMemory.hpp>

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
  const std::size_t k = static_cast<std::size_t>(std::lower_bound(ts.begin(), ts.end(), s) - ts.begin());
  const std::size_t lo = std::min(k > m / 2 ? k - m / 2 : 0, n - m);
  double sum = 0.0;
  for (std::size_t a = lo; a < lo + m; ++a) {
    double w = 1.0;
    for (std::size_t b = lo; b < lo + m; ++b)
      if (b != a) w *= (s - ts[b]) / (ts[a] - ts[b]);
    sum += w * vs[a];
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
