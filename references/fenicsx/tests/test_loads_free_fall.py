"""Gravity in the FEniCSx reference: two free S1 rods (coarse mesh) moving with the same initial
velocity v0 = (1, 0.5) m/s under g = (3, -10) m/s^2, so that the gap between them never closes.
Theory: every point moves rigidly by x(t) - x0 = v0 t + g t^2 / 2 with velocity v0 + g t; the
loads' work is W = m g . (v0 t + g t^2 / 2) per body (m = rho A L = 4 kg), and kinetic - W stays
at the initial kinetic energy 1/2 (2 m) |v0|^2 = 5 J, with no strain and no contact.

The explicit central difference is exact for a constant acceleration: its update is
u_{n+1} - 2 u_n + u_{n-1} = dt^2 g, which the quadratic v0 t + g t^2/2 satisfies exactly, and the
start v_{-1/2} = v0 - dt/2 g puts u_1 = v0 dt + g dt^2 / 2 on it. So the only error is roundoff.

Usage: test_loads_free_fall.py [--work DIR]"""

import os

import numpy as np

import common

common.require_dolfinx()
work = common.work_dir()
check = common.check
with open(os.path.join(common.SCENES, "s1_central.toml")) as f:
    text = f.read()
v0, g, T = np.array([1.0, 0.5]), np.array([3.0, -10.0]), 2.0
for old, new in (("[time]", f"[loads]\ngravity = [{g[0]}, {g[1]}]\n\n[time]"),
                 ("end = 4.0 ", f"end = {T} "),
                 ("velocity = [1.0, 0.0]", f"velocity = [{v0[0]}, {v0[1]}]"),
                 ("velocity = [0.0, 0.0]", f"velocity = [{v0[0]}, {v0[1]}]")):
    assert old in text, old
    text = text.replace(old, new, 1)
scene = os.path.join(work, "free_fall.toml")
with open(scene, "w") as f:
    f.write(text)
s, h = common.run(scene, os.path.join(work, "out"), "--mesh", "coarse")

t = h["t"]
x = v0[None, :] * t[:, None] + 0.5 * g[None, :] * t[:, None] ** 2
v = v0[None, :] + g[None, :] * t[:, None]
m = 1.0 * 0.4 * 10.0
# Roundoff: each step adds a few ulps of |x| <= 8 m (200 steps); 1e-11 of the 2 s scale
# (|v0| T + |g| T^2 / 2 = 23 m) is ~10^5 ulps. A start with v_{-1/2} = v0 (half a step off)
# would be off by g dt t / 2 = 0.1 m at 2 s.
scale = np.linalg.norm(v0) * T + np.linalg.norm(g) * T ** 2 / 2
for name in ("ua", "ub"):
    err = max(np.abs(h[f"{name}_x"] - x[:, 0]).max(), np.abs(h[f"{name}_y"] - x[:, 1]).max())
    check(err <= 1e-11 * scale, f"{name} = v0 t + g t^2/2 in every row ({len(t)} rows to {t[-1]} s): "
          f"error {err:.3g} m")
for name in ("va", "vb"):
    err = max(np.abs(h[f"{name}_x"] - v[:, 0]).max(), np.abs(h[f"{name}_y"] - v[:, 1]).max())
    check(err <= 1e-11 * np.linalg.norm(v[-1]), f"{name} = v0 + g t in every row: error {err:.3g} m/s")
W = 2 * m * (x @ g)
err = np.abs(h["load_work"] - W).max()
check(err <= 1e-11 * abs(W[-1]), f"load_work = 2 m g . (v0 t + g t^2/2): error {err:.3g} J of {W[-1]:.6g} J")
E0 = 0.5 * 2 * m * v0 @ v0
check(abs(s["energy_initial"] - E0) <= 1e-12 * E0, f"energy_initial {s['energy_initial']} = {E0} J")
# No strain in a rigid motion: K applied to a translation of up to 20 m is roundoff of K's
# entries (E b = 100 N/m) times 20 m, squared into 1/2 u' K u: far below 1e-9 of W.
acct = np.abs(h["kinetic"] + h["strain"] + h["dissipated"] - h["load_work"] - E0).max()
check(acct <= 1e-11 * abs(W[-1]) and np.abs(h["strain"]).max() <= 1e-9 * abs(W[-1]),
      f"kinetic + strain + dissipated - load_work = E0 within {acct:.3g} J; max |strain| "
      f"{np.abs(h['strain']).max():.3g} J")
check(np.all(h["R"] == 0) and not s["contacts"][0]["intervals"], "no contact (the gap stays 0.5 m)")
check("loads" in s["effects"], f"effects {s['effects']} list loads")
loads = s.get("loads", {})
check(loads.get("gravity") == list(g) and loads.get("point") == []
      and abs(loads.get("work_final", 0.0) - W[-1]) <= 1e-11 * abs(W[-1]),
      f"summary.json loads: {loads.get('gravity')}, work_final {loads.get('work_final')} J")
vf = v0 + g * s["end_time"]
for b in ("A", "B"):
    fv = np.array(s["bodies"][b]["final_velocity"])
    check(np.abs(fv - vf).max() <= 1e-11 * np.linalg.norm(vf), f"{b} final velocity {fv} = v0 + g T")
se = s["fenicsx"]["shadow_energy_error_max"]
check(se <= 1e-11 * abs(W[-1]), f"central-difference energy identity with the load term: {se:.3g} J")
common.finish()
