#include <references/exact/CoaxialRodsCost.hpp>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <references/exact/CoaxialRods.hpp>
#include <references/exact/output_times.hpp>

namespace beamimpact::exact {
namespace {

/// Measured on two_rods_second_contact (Release, one core, loaded machine): 2.5e5 pieces in
/// 0.07 s (time.end = 1e5 s, a row every 10 s), and 2e5 rows of 28 wave reads each in 0.47 s
/// more (a row every 0.5 s), the rows' recording and writing included. A piece is a std::set
/// insertion and two binary searches, a wave read one binary search.
constexpr double kPiecesPerSecond = 2e6;
constexpr double kWaveReadsPerSecond = 1e7;
/// Beyond this many terms a count is taken from its continuum limit.
constexpr double kMostTerms = 1e7;

/// Sums a TA + b TB below span, all distinct: for each b, the a with a TA < span - b TB.
double distinct_pairs(double TA, double TB, double span) {
  const double B = std::ceil(span / TB);  // b = 0 .. B - 1
  if (B > kMostTerms) return span * span / (2.0 * TA * TB) + span / TA + span / TB;
  double n = 0.0;
  for (double b = 0.0; b < B; b += 1.0) n += std::max(0.0, std::ceil((span - b * TB) / TA));
  return n;
}

}  // namespace

double breakpoint_sums(double TA, double TB, double span, double merge) {
  if (!(span > 0.0)) return 0.0;
  // The smallest q with q TA = p TB to within the merging distance over the whole span: the
  // sums are then the multiples m d (d = TA / p) with m = a p + b q, p and q coprime; for each
  // residue b q (b < p) the m = b q + k p, k >= 0, below span / d.
  const double qmax = std::min(span / TA, kMostTerms);
  for (double q = 1.0; q <= qmax; q += 1.0) {
    const double p = std::round(q * TA / TB);
    if (p < 1.0 || std::abs(q * TA - p * TB) * std::max(1.0, span / (q * TA)) > merge) continue;
    const double d = TA / p, M = std::ceil(span / d) - 1.0;  // the largest m with m d < span
    if (std::min(p, M / q) > kMostTerms) return M + 1.0 - (p - 1.0) * (q - 1.0) / 2.0;
    double n = 0.0;
    for (double b = 0.0; b < p && b * q <= M; b += 1.0) n += std::floor((M - b * q) / p) + 1.0;
    return n;
  }
  return distinct_pairs(TA, TB, span);
}

double CoaxialRodsCost::seconds() const {
  return pieces / kPiecesPerSecond + wave_reads / kWaveReadsPerSecond;
}

std::string CoaxialRodsCost::to_string() const {
  return fmt::format(
      "{:.3g} pieces, {:.3g} rows x {:.3g} wave reads; about {:.3g} min of one core and {:.3g} GB", pieces,
      rows, (wave_reads - 2.0 * pieces) / std::max(rows, 1.0), seconds() / 60.0, bytes / 1e9);
}

CoaxialRodsCost estimate_coaxial_rods_cost(const Rod& a, const Rod& b, double v0, double gap, double t_end,
                                           double dt_out) {
  const double TA = a.round_trip(), TB = b.round_trip();
  const double t0 = v0 > 0.0 ? gap / v0 : t_end, span = std::max(0.0, t_end - t0);
  CoaxialRodsCost c;
  // As CoaxialRods::solve: breakpoints closer than 1e-12 max(T_A, T_B, t_end) are one.
  c.pieces = 1.0 + breakpoint_sums(TA, TB, span, 1e-12 * std::max({TA, TB, t_end}));
  c.rows = output_row_count(dt_out, t_end);
  // A row's field: each rod cut at the piece starts of its last round trip (T_X (pieces - 1) /
  // span of them on average over the rows), two reads per interval.
  const double density = span > 0.0 ? (c.pieces - 1.0) / span : 0.0;
  c.wave_reads = 2.0 * c.pieces + c.rows * 2.0 * (density * (TA + TB) + 2.0);
  c.bytes = c.pieces * sizeof(RodsSegment) + c.rows * kBytesPerRow;
  return c;
}

}  // namespace beamimpact::exact
