#pragma once
/// @file rod_on_beam_testing.hpp
/// @brief Tests' S2 rod-on-beam data: the setup the rod-on-beam solution and its cost estimate
/// are checked on.

#include <gtest/gtest.h>

#include <references/exact/RodOnBeam.hpp>

namespace beamimpact::exact {

/// @brief S2 (docs/paper-scenes.md) as a rod-on-beam setup, the paper's soft material: rod 5 m,
/// E 100 Pa, rho 1, A 0.4 (c = 10 m/s, T_A = 1 s, Z_A = 4 N s/m); beam 10 m pinned at both ends,
/// I = 0.4^3 / 12 m^4 (a = sqrt(E I / (rho A)) = 1.1547 m^2/s); struck at midspan at 1 m/s across
/// a 0.1 m gap (first touch 0.1 s); rows every 0.01 s. Sections 1 m wide and `depth` deep: depth 1
/// is the stocky S2 (verification/scenes/extra/s2_stocky.toml: A = 1 m^2, I = 1/12 m^4, L/h = 10).
/// @param modes the beam modes kept (default: RodOnBeamSetup's)
/// @param t_end the end time (s)
/// @param depth both bodies' depth (m): A = depth, I = depth^3 / 12
inline RodOnBeamSetup s2_rod_on_beam(int modes = RodOnBeamSetup{}.modes, double t_end = 3.0,
                                     double depth = 0.4) {
  RodOnBeamSetup s;
  s.rod = Rod{5.0, 100.0, 1.0, depth};
  s.beam = SimpleBeam{10.0, 100.0, 1.0, depth, depth * depth * depth / 12.0};
  s.x_c = 5.0;
  s.v0 = 1.0;
  s.gap = 0.1;
  s.modes = modes;
  s.t_end = t_end;
  s.dt_out = 0.01;
  return s;
}

/// @brief Newton and energy on every row of a rod-on-beam solution struck at v0 = 1 m/s: the rod's
/// momentum integrated over its wave field equals m_A v0 - integral of P, and rod field energy +
/// beam modal energy equals m_A v0^2 / 2. The field comes from the interpolated memory (error ~1e-9
/// of P) and 3-point Gauss panels: 1e-7 relative is ample. The beam's modal energy equals the work
/// of P on it up to the rk8pd tolerance (1e-10 x scales): 1e-8.
/// @param sol the solution
/// @param rod_mass m_A = rho A L of the rod (kg)
inline void expect_momentum_and_energy_kept(const RodOnBeamSolution& sol, double rod_mass) {
  const double m = rod_mass, E0 = 0.5 * m;
  for (const RodOnBeamRow& row : sol.rows) {
    EXPECT_NEAR(row.rod.momentum, m - row.impulse, 1e-7 * m) << row.t;
    EXPECT_NEAR(row.rod.kinetic + row.rod.strain + row.beam_kinetic + row.beam_strain, E0, 1e-7 * E0)
        << row.t;
    EXPECT_GE(row.P, 0.0);
    EXPECT_GE(row.gap, -1e-9);
  }
  EXPECT_LT(sol.energy_error, 1e-8 * E0);
}

}  // namespace beamimpact::exact
