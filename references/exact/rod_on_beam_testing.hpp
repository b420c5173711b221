#pragma once
/// @file rod_on_beam_testing.hpp
/// @brief Tests' S2 rod-on-beam data: the setup the rod-on-beam solution and its cost estimate
/// are checked on.

#include <references/exact/RodOnBeam.hpp>

namespace beamimpact::exact {

/// @brief S2 (shared/spec/scenes.md) as a rod-on-beam setup, the paper's soft material: rod 5 m,
/// E 100 Pa, rho 1, A 0.4 (c = 10 m/s, T_A = 1 s, Z_A = 4 N s/m); beam 10 m pinned at both ends,
/// I = 0.4^3 / 12 m^4 (a = sqrt(E I / (rho A)) = 1.1547 m^2/s); struck at midspan at 1 m/s across
/// a 0.1 m gap (first touch 0.1 s); rows every 0.01 s.
/// @param modes the beam modes kept (default: RodOnBeamSetup's)
/// @param t_end the end time (s)
inline RodOnBeamSetup s2_rod_on_beam(int modes = RodOnBeamSetup{}.modes, double t_end = 3.0) {
  RodOnBeamSetup s;
  s.rod = Rod{5.0, 100.0, 1.0, 0.4};
  s.beam = SimpleBeam{10.0, 100.0, 1.0, 0.4, 0.4 * 0.4 * 0.4 / 12.0};
  s.x_c = 5.0;
  s.v0 = 1.0;
  s.gap = 0.1;
  s.modes = modes;
  s.t_end = t_end;
  s.dt_out = 0.01;
  return s;
}

}  // namespace beamimpact::exact
