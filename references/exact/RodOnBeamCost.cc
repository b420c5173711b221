#include <references/exact/RodOnBeamCost.hpp>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <references/exact/output_times.hpp>

namespace beamimpact::exact {
namespace {

/// Measured on S2 (Release, one core) with 128 and 256 modes: 3.6-4.7e6 rk8pd state-steps per
/// second (13 stages of rhs() each), 2e6 memory evaluations per second (degree-11 Lagrange).
constexpr double kStateStepsPerSecond = 4e6;
constexpr double kFieldPointsPerSecond = 2e6;
/// Bytes per memory sample (time and value, vector growth).
constexpr double kBytesPerSample = 32.0;

}  // namespace

double RodOnBeamCost::seconds() const {
  return state_steps / kStateStepsPerSecond + field_points / kFieldPointsPerSecond;
}

std::string RodOnBeamCost::to_string() const {
  return fmt::format(
      "{} modes: {:.3g} integrator stops {:.3g} s apart, {:.3g} state-steps in all; {:.3g} rows x "
      "{:.3g} memory reads for the rod's energies; about {:.3g} min of one core and {:.3g} GB",
      modes, samples, sample_dt, state_steps, rows, field_points / std::max(rows, 1.0), seconds() / 60.0,
      bytes / 1e9);
}

RodOnBeamCost estimate_rod_on_beam_cost(const RodOnBeamSetup& s, const std::vector<int>& mode_counts) {
  RodOnBeamCost c;
  const double T = s.rod.round_trip();
  const double t0 = s.v0 > 0.0 ? s.gap / s.v0 : s.t_end;
  const double span = std::max(0.0, s.t_end - t0);  // integrated from the first touch
  c.rows = output_row_count(s.dt_out, s.t_end);
  for (int n : mode_counts) {
    const double delta =
        std::min(0.25 / top_frequency(s.beam, s.shear, n), T / 32.0);  // as Integration's delta_
    const double samples = span / delta;
    c.state_steps += samples * (2.0 * n + 3.0);
    if (n < c.modes) continue;
    c.modes = n;
    c.sample_dt = delta;
    c.samples = samples;
    // rod_field(): 5-point Gauss panels 4 samples of the wave (4 c delta) long over the rod, two
    // memory reads per point, for every row after the first touch.
    const double panels = std::ceil(s.rod.length / (4.0 * s.rod.wave_speed() * delta));
    c.field_points = (span > 0.0 ? c.rows : 0.0) * panels * 10.0;
    c.bytes = samples * kBytesPerSample + c.rows * kBytesPerRow;
  }
  return c;
}

}  // namespace beamimpact::exact
