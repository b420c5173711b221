#include <verification/compare/series.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <solver/record/ContactIntervals.hpp>

namespace beamimpact::verification {

std::vector<double> uniform_grid(double t0, double t1, double h) {
  if (!(h > 0.0) || !(t1 >= t0)) throw std::invalid_argument("uniform_grid: need h > 0 and t1 >= t0");
  // Round up so that the spacing never exceeds h; guard against round-off adding a point.
  const auto n = static_cast<std::size_t>(std::max(1.0, std::ceil((t1 - t0) / h - 1e-9)));
  std::vector<double> g(n + 1);
  for (std::size_t i = 0; i <= n; ++i)
    g[i] = t0 + (t1 - t0) * static_cast<double>(i) / static_cast<double>(n);
  return g;
}

std::vector<double> interpolate(const std::vector<double>& t, const std::vector<double>& y,
                                const std::vector<double>& at) {
  std::vector<double> out(at.size());
  if (t.empty()) return out;
  std::size_t j = 0;  // `at` is increasing in all uses; keep a moving bracket, fall back to search
  for (std::size_t i = 0; i < at.size(); ++i) {
    const double x = at[i];
    if (x <= t.front()) {
      out[i] = y.front();
      continue;
    }
    if (x >= t.back()) {
      out[i] = y.back();
      continue;
    }
    if (j >= t.size() - 1 || t[j] > x) j = 0;
    if (t[j + 1] < x) j = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), x) - t.begin()) - 1;
    const double w = (x - t[j]) / (t[j + 1] - t[j]);
    out[i] = (1.0 - w) * y[j] + w * y[j + 1];
  }
  return out;
}

std::vector<double> running_integral(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<double> I(t.size(), 0.0);
  for (std::size_t i = 1; i < t.size(); ++i) I[i] = I[i - 1] + 0.5 * (y[i] + y[i - 1]) * (t[i] - t[i - 1]);
  return I;
}

double l2_norm(const std::vector<double>& t, const Series& s) {
  double sum = 0.0;
  auto sq = [&](std::size_t i) {
    double v = 0.0;
    for (const auto& c : s) v += c[i] * c[i];
    return v;
  };
  for (std::size_t i = 1; i < t.size(); ++i) sum += 0.5 * (sq(i) + sq(i - 1)) * (t[i] - t[i - 1]);
  return std::sqrt(sum);
}

double linf_norm(const Series& s) {
  double m = 0.0;
  if (s.empty()) return m;
  for (std::size_t i = 0; i < s[0].size(); ++i) {
    double v = 0.0;
    for (const auto& c : s) v += c[i] * c[i];
    m = std::max(m, std::sqrt(v));
  }
  return m;
}

Series difference(const Series& a, const Series& b) {
  Series d = a;
  for (std::size_t c = 0; c < d.size(); ++c)
    for (std::size_t i = 0; i < d[c].size(); ++i) d[c][i] -= b[c][i];
  return d;
}

std::vector<double> window_average(const std::vector<double>& t, const std::vector<double>& I, double W,
                                   const std::vector<double>& at) {
  std::vector<double> lo(at.size()), hi(at.size());
  for (std::size_t i = 0; i < at.size(); ++i) {
    lo[i] = at[i] - 0.5 * W;
    hi[i] = at[i] + 0.5 * W;
  }
  const auto Ilo = interpolate(t, I, lo), Ihi = interpolate(t, I, hi);
  std::vector<double> out(at.size());
  for (std::size_t i = 0; i < at.size(); ++i) out[i] = (Ihi[i] - Ilo[i]) / W;
  return out;
}

std::vector<Interval> contact_intervals(const std::vector<double>& t, const std::vector<double>& R,
                                        double threshold, double merge_gap) {
  ContactIntervals merged(merge_gap);  // each run of samples above the threshold is a phase
  std::vector<Interval> out;
  bool in_contact = false;  // the previous sample is
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!(R[i] > threshold)) {
      in_contact = false;
      continue;
    }
    if (!in_contact && merged.begin(t[i])) out.push_back({0.0, 0.0, i, i});
    in_contact = true;
    merged.extend(t[i]);
    out.back().last = i;
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].start = merged.intervals()[k][0];
    out[k].end = merged.intervals()[k][1];
  }
  return out;
}

}  // namespace beamimpact::verification
