"""A point force on an interior node in the FEniCSx reference: a simply supported beam (pin at
the start, roller at the end, on the axis nodes) of L = 2 m, E = 100 N/m^2, A = 0.2 m^2,
I = A h^2 / 12 with h = 0.2 m (L / h = 10), loaded from t = 0 by P = 0.01 N down on its midspan
node, which the continuum applies as a line load P / h over the section at x = 1 m. A striker
1 m above never touches it. Coarse mesh (10 Q2 elements along, 1 through the depth).

Theory. The static midspan deflection of the beam is P L^3 / (48 E I) = 0.025 m
(Euler-Bernoulli) plus the shear deflection P L / (4 k G A) = 0.0006 m (Timoshenko, k = 5/6
for a rectangle, G = E / 2 with Poisson 0): 0.0256 m. The continuum is compared with the
Timoshenko value: what remains is the plane-stress strip's difference from a beam near the
supports and the load (order (h / L)^2 of the deflection, 1 %) and the Q2 mesh.
Dynamically the suddenly applied load makes the beam oscillate about the static shape (mode 1:
98.6 % of it, period T1 = 2 pi (L / pi)^2 sqrt(rho A / (E I)) = 4.41 s); the static value is
the mean of the midspan deflection with the Hann weight sin^2(pi t / T) over T = 5 T1: a mode of
N periods in T leaves at most 1 / (pi N (N^2 - 1)) of its amplitude in that mean (2.7e-3 at
N = 5, 3.7e-3 at N = 4.5 if the continuum's mode were 10 % slower), higher modes less.

Usage: test_loads_beam_point.py [--work DIR]"""

import os

import numpy as np

import common

common.require_dolfinx()
work = common.work_dir()
check = common.check
P, L, E, A, h = 0.01, 2.0, 100.0, 0.2, 0.2
I = A * h * h / 12
T1 = 2 * np.pi * (L / np.pi) ** 2 * np.sqrt(1.0 * A / (E * I))
scene_text = f"""name = "beam_point_force"
description = "simply supported beam, suddenly applied midspan force"
[time]
dt = 0.01
end = {5 * T1:.6f}
[[loads.point]]
body = "B"
node = 5
force = [0.0, {-P}]
[[bodies]]
name = "A"
start = [1.0, 2.1]
end = [1.0, 1.1]
elements = 5
E = {E}
rho = 1.0
area = {A}
inertia = {I!r}
supports = []
[[bodies]]
name = "B"
start = [0.0, 0.0]
end = [{L}, 0.0]
elements = 10
E = {E}
rho = 1.0
area = {A}
inertia = {I!r}
supports = [{{ at = "start", fix = ["x", "y"] }}, {{ at = "end", fix = ["y"] }}]
[[contacts]]
striker = "A"
node = "end"
target = "B"
"""
scene = os.path.join(work, "beam_point.toml")
with open(scene, "w") as f:
    f.write(scene_text)
s, hist = common.run(scene, os.path.join(work, "out"), "--mesh", "coarse")
t, u = hist["t"], hist["ub_y"]     # B's axis under the striker: x = 1 m, the loaded section
d_eb = P * L ** 3 / (48 * E * I)
d_timo = d_eb + P * L / (4 * (5 / 6) * (E / 2) * A)
w = np.sin(np.pi * t / t[-1]) ** 2
mean = -np.trapz(u * w, t) / np.trapz(w, t)
# Bound 1.5 %: the strip's difference from the Timoshenko beam near supports and load (1 %) and
# the Hann mean's residual (0.4 %). Euler-Bernoulli's 0.025 m is 2.3 % below the Timoshenko
# value, so a continuum without the shear deflection (or a load of the wrong size) fails.
check(abs(mean - d_timo) <= 0.015 * d_timo,
      f"static midspan deflection (Hann mean over 5 T1) {mean:.6g} m vs Timoshenko {d_timo:.6g} m "
      f"({mean / d_timo - 1:+.2%}; Euler-Bernoulli {d_eb:.6g} m)")
# The largest deflection of a suddenly applied load is about twice the static one (mode 1 carries
# 98.6 %; the higher modes' phases add or take a few percent): 2 delta within 5 %.
check(abs(-u.min() - 2 * d_timo) <= 0.05 * 2 * d_timo, f"largest deflection {-u.min():.6g} m ~ 2 x static")
# Energy: the identity with the load term is roundoff; the history's account K + S - W = 0
# within (omega dt)^2 / 8 of the vibration energy, which is at most the load work.
scale = P * 2 * d_timo
se = s["fenicsx"]["shadow_energy_error_max"]
check(se <= 1e-9 * scale, f"central-difference energy identity with the load term: {se:.3g} J")
acct = np.abs(hist["kinetic"] + hist["strain"] + hist["dissipated"] - hist["load_work"]).max()
check(acct <= (2 * 0.9) ** 2 / 8 * np.abs(hist["load_work"]).max(),
      f"kinetic + strain - load_work = 0 within {acct:.3g} J (load work up to {np.abs(hist['load_work']).max():.3g} J)")
check(np.all(hist["R"] == 0), "the striker never touches the beam")
common.finish()
