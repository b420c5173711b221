"""Point forces in the FEniCSx reference: S1's rod A (L = 10 m, E A = 40 N, c = 10 m/s), free and
at rest, pulled by P = 0.4 N on its end node and -P on its start node from t = 0 (B is 0.5 m
away and never touched). Each force acts as a uniform traction on the end face.

Theory. Statically the rod stretches by P L / (E A) = 0.1 m. With nu = 0 the uniform stress
P / A is an exact plane-stress solution that Q2 represents exactly, so the continuum's static
answer is the 1D one with no mesh or modelling error. Dynamically (suddenly applied, undamped),
each half is a rod held at the midpoint with an end force: its end moves as a triangle wave
between 0 and 2 P (L/2) / (E A) = 0.1 m with period 4 (L/2) / c = 2 s, whose mean is the static
P L / (2 E A) = 0.05 m. The midpoint and the centre of mass stay at rest (no net force); the
loads' work is W = P (u_end - u_start) = 2 P u_end.

Usage: test_loads_rod_force.py [--work DIR]"""

import os

import numpy as np

import common

common.require_dolfinx()
work = common.work_dir()
check = common.check
with open(os.path.join(common.SCENES, "s1_central.toml")) as f:
    text = f.read()
P, L, EA, c, T = 0.4, 10.0, 100.0 * 0.4, 10.0, 10.0
loads = "".join(f'[[loads.point]]\nbody = "A"\nnode = "{end}"\nforce = [{f}, 0.0]\n\n'
                for end, f in (("end", P), ("start", -P)))
for old, new in (("[time]", loads + "[time]"), ("end = 4.0 ", f"end = {T} "),
                 ("velocity = [1.0, 0.0]", "velocity = [0.0, 0.0]")):
    assert old in text, old
    text = text.replace(old, new, 1)
scene = os.path.join(work, "rod_force.toml")
with open(scene, "w") as f:
    f.write(text)
s, h = common.run(scene, os.path.join(work, "out"), "--mesh", "coarse")
t, u = h["t"], h["ua_x"]
delta = P * L / (2 * EA)
period = 4 * (L / 2) / c

# The mean over five whole periods (trapezoid rule over the rows; the rows hit the triangle's
# corners): the exact wave's mean is delta. A cosine harmonic k of the triangle (k odd, amplitude
# a_k = 8 delta / (pi^2 k^2), the a_k sum to delta) whose frequency in the Q2 mesh is off by a
# fraction e_k leaves at most min(e_k, 1 / (2 pi N k)) a_k in a mean over N = 5 nominal periods.
# Bound 1 %: the low harmonics are within 1 % in frequency on 20 elements per rod, and the
# high ones leave less than 1 / (10 pi k) of theirs (measured 0.02 %).
assert abs(t[-1] - 5 * period) < 1e-9, t[-1]
mean = np.trapz(u, t) / t[-1]
check(abs(mean - delta) <= 0.01 * delta,
      f"mean end displacement over 5 periods {mean:.6g} m = P L / (2 E A) = {delta:.6g} m within 1 % "
      f"(extension {2 * mean:.6g} m vs P L / (E A) = {2 * delta:.6g} m)")
# Dynamic amplification 2: the first peak at t = period / 2 is 2 delta; the rounded corner of
# the continuum's wave front lowers it and its ringing can overshoot: 5 %.
first = u[t <= period].max()
check(abs(first - 2 * delta) <= 0.05 * 2 * delta, f"first peak {first:.6g} m = 2 P L / (2 E A) within 5 %")
# The end moves at P / (rho A c) = 0.1 m/s until the wave returns (t < 1 s): u = P t / (rho A c).
early = (t > 0.1) & (t < 0.9)
v_end = P / (1.0 * 0.4 * c)
err = np.abs(u[early] - v_end * t[early]).max()
check(err <= 0.05 * v_end * 0.9, f"end displacement {v_end} t before the wave returns: max error {err:.3g} m "
      "(<= 5 %: the front's rounding)")
# W = P (u_end - u_start) with u_start = -u_end by symmetry: 2 P ua_x, to roundoff.
err = np.abs(h["load_work"] - 2 * P * u).max()
check(err <= 1e-9 * P * 2 * delta, f"load_work = 2 P u_end in every row: error {err:.3g} J")
# No net force, no contact: total momentum stays 0 (roundoff of the symmetric nodal forces).
check(np.abs(h["px"]).max() <= 1e-12 and np.abs(h["py"]).max() <= 1e-12,
      f"momentum stays 0 (max |px| {np.abs(h['px']).max():.3g} N s)")
# Energy account: kinetic + strain - W = 0. The central-difference identity (with the load term)
# closes to roundoff; the history's kinetic energy uses v_n averaged from the half steps, which
# misstates a mode's energy by (omega dt)^2 / 8 of it (up to 0.4 at omega dt = 2 x 0.9), and the
# step-like load puts a small share of its work P x 2 delta into the modes near omega_max: 1 % of
# that scale (measured 0.28 %; a load work one step off, 2 P v_end dt, would be 2 %).
acct = np.abs(h["kinetic"] + h["strain"] + h["dissipated"] - h["load_work"]).max()
scale = P * 2 * delta
check(acct <= 1e-2 * scale, f"kinetic + strain + dissipated - load_work = 0 within {acct:.3g} J (scale {scale} J)")
se = s["fenicsx"]["shadow_energy_error_max"]
check(se <= 1e-9 * scale, f"central-difference energy identity with the load term: {se:.3g} J")
pts = s.get("loads", {}).get("point", [])
check(pts == [{"body": "A", "node": 10, "force": [P, 0.0]}, {"body": "A", "node": 0, "force": [-P, 0.0]}],
      f"summary.json loads.point {pts}")
check(np.all(h["R"] == 0), "no contact (B stays 0.5 m away)")
common.finish()
