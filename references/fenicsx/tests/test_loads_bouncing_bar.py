"""Gravity with contact in the FEniCSx reference: the bouncing bar of Doyen, Ern and Piperno
(verification/scenes/benchmarks/bouncing_bar.toml: L = 10 m, E = 900 N/m^2, rho = 1 kg/m^3,
A = 1 m^2, c = 30 m/s, g = 10 m/s^2, lower end 5 m above an immovable rigid ground), at the
coarse mesh (a rod: 1 m square section, 10 Q2 elements along), half the usual step fraction
(dt = 0.005 s, a history row every step), to 8 s (two impacts).

Theory (references/exact/RodOnWall.hpp): free fall for sqrt(2 x 5 / g) = 1 s, touch at
g t = 10 m/s; the first contact lasts 2 L / c = 2/3 s and carries 2 m v + m g 2 L / c =
800/3 N s; the energy K + S - W_gravity stays 0. The continuum's closure is plastic for the
lower face's row of nodes (row-sum mass rho A le / 6 = 1/6 kg with le = 1 m), which loses
1/2 (1/6 kg) (10 m/s)^2 = 8.33 J at the first touch; every later re-closure loses more
(the account's `dissipated`), so only the first impact is compared with the exact numbers.

Usage: test_loads_bouncing_bar.py [--work DIR] ; env FENICSX_MESH=fine selects the fine mesh
(40 elements of 0.25 m along, 4 through: the face row is 1/24 kg)."""

import os

import numpy as np

import common

common.require_dolfinx()
work = common.work_dir()
check = common.check
scene = os.path.join(common.SOURCE, "verification", "scenes", "benchmarks", "bouncing_bar.toml")
mesh = os.environ.get("FENICSX_MESH", "coarse")
s, h = common.run(scene, os.path.join(work, "out"), "--mesh", mesh, "--fraction", "0.45",
                  "--output-interval", "0.005", "--end", "8")
t, dt = h["t"], s["dt"]
g, L, c, m, E_ref = 10.0, 10.0, 30.0, 10.0, 500.0   # E_ref: m g h, the kinetic energy at touch
iv = s["contacts"][0]["intervals"]

# Free fall is exact for the central difference (test_loads_free_fall.py): up to the touch the
# lower face's centre is at -g t^2 / 2 to roundoff (1e-12 of 5 m).
free = t < 1.0 - 1e-9
err = np.abs(h["ua_y"][free] + 0.5 * g * t[free] ** 2).max()
check(err <= 5e-12, f"free fall before the touch: ua_y = -g t^2/2 within {err:.3g} m")
# Touch at exactly 1 s: the face reaches the ground at a step boundary, so the first closing step
# is the one at 1 s (one step either way would be a timing error).
check(abs(iv[0][0] - 1.0) <= 1e-9, f"first contact starts at {iv[0][0]} s = 1 s")
# Release 2 L / c later; the Q2 mesh's dispersion delays the returning wave's tail: 2 steps of
# the scene's output (0.02 s), as the beam methods' rows allow.
check(abs(iv[0][1] - (1.0 + 2 * L / c)) <= 0.02, f"first contact ends at {iv[0][1]:.4g} s, exact {1 + 2 * L / c:.4g} s")
# First impulse from the momentum balance over the first contact (the ground's force and the
# weight are the only forces on the bar): J = py(t_a) - py(t_b) + m g (t_a - t_b), t_b the last
# row before the touch, t_a the first after the release.
i_b = int(np.flatnonzero(t < iv[0][0] - 1e-9)[-1])
i_a = int(np.flatnonzero(t > iv[0][1] + 1e-9)[0])
J = h["py"][i_a] - h["py"][i_b] + m * g * (t[i_a] - t[i_b])
J_exact = 2 * m * g * 1.0 + m * g * 2 * L / c
# The plastic closure keeps the face row's momentum (1/6 kg x 10 m/s = 1.7 N s, 0.6 %) out of
# the rebound, and the release within a step changes the weight's share by m g dt = 0.5 N s:
# 1 % together with margin.
check(abs(J - J_exact) <= 0.01 * J_exact, f"first impulse {J:.5g} N s vs exact 800/3 = {J_exact:.5g} N s (1 %)")
# The first closure's loss: 1/2 m_face v^2 with m_face = rho A le / 6. The central-difference
# work pairs v_{n-1/2} v_{n+1/2} = v^2 - (g dt / 2)^2 (relative 6e-6 here), and the rest of the
# bar does not act on the face row within that step: 1e-4.
m_face = 1.0 * 1.0 * (L / s["fenicsx"]["mesh"]["bar"]["elements_length"]) / 6
before_second = (t > iv[0][1] + 1e-9) & (t < iv[1][0] - 1e-9) if len(iv) > 1 else t > iv[0][1] + 1e-9
D1 = h["dissipated"][before_second]
loss = 0.5 * m_face * (g * 1.0) ** 2
check(np.ptp(D1) <= 1e-12 * loss and abs(D1[0] - loss) <= 1e-4 * loss,
      f"first closure loss {D1[0]:.7g} J = 1/2 m_face v^2 = {loss:.7g} J (1e-4)")
# The energy account with the load work. The central-difference identity (contact and load
# terms) closes to roundoff: 1e-9 of E_ref over 1600 steps.
se = s["fenicsx"]["shadow_energy_error_max"]
check(se <= 1e-9 * E_ref, f"central-difference energy identity with gravity and contact: {se:.3g} J")
# The history's account uses v_n averaged from the half steps: each mode's kinetic energy is
# misstated by (omega dt)^2 / 8 of its energy, omega dt <= 2 x 0.45 here, so at most 10 % of the
# vibration energy K + S - p^2 / (2 m) (measured: 1.0 J of 74 J off contact). In a contact row
# the plastic closure's step is booked half in that row: add the closure loss 1/2 m_face v^2
# (8.3 J at 10 m/s). At fraction 0.9 the account is 4.7 % of E_ref off, as (omega dt)^2.
acct = np.abs(h["kinetic"] + h["strain"] + h["dissipated"] - h["load_work"])
vib = h["kinetic"] + h["strain"] - 0.5 * (h["px"] ** 2 + h["py"] ** 2) / m
off = h["R"] == 0
bound = (2 * 0.45) ** 2 / 8 * vib[off].max()
check(acct[off].max() <= bound, f"kinetic + strain + dissipated - load_work = 0 off contact within "
      f"{acct[off].max():.3g} J <= {bound:.3g} J")
check(acct.max() <= bound + loss, f"... and in every row within {acct.max():.3g} J <= {bound + loss:.3g} J")
check("loads" in s["effects"] and s["loads"]["gravity"] == [0.0, -g], f"effects {s['effects']}, loads {s['loads']['gravity']}")
# The ground is immovable: its target point never moves.
check(np.abs(h["ub_x"]).max() == 0 and np.abs(h["ub_y"]).max() == 0, "the rigid ground does not move")
common.finish()
