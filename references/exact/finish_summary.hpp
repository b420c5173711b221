#pragma once
/// @file finish_summary.hpp
/// @brief What every exact solution does with its rows: records them and reports what it knows
/// exactly (event times, impulse, peak force) in place of the output grid's sampling.

#include <array>
#include <vector>

#include <nlohmann/json.hpp>

#include <solver/record/ResultRecorder.hpp>

namespace beamimpact::exact {

/// @brief The vector s d (d a unit direction, s a signed length or speed along it).
inline Vec2 along(Vec2 d, double s) { return {d[0] * s, d[1] * s}; }

/// @brief One row's contact sample of a 1D solution along the impact direction d: closed
/// while the force is positive.
/// @param d unit vector, striker towards target
/// @param R N, contact force
/// @param gap m
/// @param ua striker contact point's displacement along d (m)
/// @param va its velocity along d (m/s)
/// @param ub struck point's displacement along d (m)
/// @param vb its velocity along d (m/s)
inline ContactSample along_sample(Vec2 d, double R, double gap, double ua, double va, double ub, double vb) {
  ContactSample c;
  c.R = R;
  c.gap = gap;
  c.ua = along(d, ua);
  c.va = along(d, va);
  c.ub = along(d, ub);
  c.vb = along(d, vb);
  c.state = R > 0.0 ? ContactState::kClosed : ContactState::kOpen;
  return c;
}

/// @brief Records the rows (energies, momentum drift, output-grid contact statistics) and then
/// reports the exact solution's event times, impulse and peak force; the output-grid values are
/// kept in the contact's extra (comparable with a stepping method's sampling).
/// @param rec the recorder of the run
/// @param rows the output rows, one contact each
/// @param intervals s, the contact intervals from the located events
/// @param impulse N s, exact impulse over the run
/// @param peak N, exact peak force
/// @param first N, force just after the first touch
/// @param kind the contact's kind
/// @param contact_extra what the solution adds to the contact's summary
SimulationResult finish_summary(ResultRecorder& rec, std::vector<HistoryRow> rows,
                                const std::vector<std::array<double, 2>>& intervals, double impulse,
                                double peak, double first, ContactKind kind, nlohmann::json contact_extra);

}  // namespace beamimpact::exact
