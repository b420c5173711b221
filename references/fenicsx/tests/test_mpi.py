"""Serial and `mpirun -n 2` runs give the same results to 1e-10 relative.

Runs S2 (supports, frictionless node-to-surface contact, 3 s), S4 at 60 deg (friction,
stick and slip) up to 0.025 s (the first two contact intervals) and the bouncing bar (gravity,
an immovable rigid ground; coarse, to 2 s: the first impact) in both ways. Every history
column is compared relative to the scale of its kind (displacements to the largest
displacement, velocities to the largest velocity, forces to the peak R, energies to E0,
momenta to the largest momentum; energies and load work to E0 + max |load_work|), so that a quantity that is zero by symmetry is not judged
by its own roundoff. Why 1e-10 can hold at all: every contact decision is taken from the same
gathered numbers on every rank; only the order of the sums inside K u and the reductions
differs (roundoff 1e-16), and the explicit scheme amplifies it only mildly in 10^3 steps."""

import os

import numpy as np

import common

common.require_dolfinx()
if common.mpirun_prefix(2) is None:
    print("SKIP: mpirun not found")
    raise SystemExit(common.SKIP)
work = common.work_dir()
check = common.check
KINDS = {"disp": ["ua_x", "ua_y", "ub_x", "ub_y", "gap"], "vel": ["va_x", "va_y", "vb_x", "vb_y"],
         "force": ["R", "tau"], "energy": ["kinetic", "strain", "dissipated", "load_work"], "mom": ["px", "py"]}

BAR = os.path.join(common.SOURCE, "verification", "scenes", "benchmarks", "bouncing_bar.toml")
for scene, args in (("s2_transverse.toml", []), ("s4_oblique_60.toml", ["--end", "0.025"]),
                    (BAR, ["--mesh", "coarse", "--end", "2"])):
    name = os.path.basename(scene)[:-5]
    s1, h1 = common.run(scene, os.path.join(work, name + "_serial"), *args)
    s2, h2 = common.run(scene, os.path.join(work, name + "_mpi2"), *args, ranks=2)
    check(s2["fenicsx"]["ranks"] == 2 and s1["fenicsx"]["ranks"] == 1, f"{name}: ranks recorded 1 and 2")
    check(len(h1) == len(h2) and s1["dt"] == s2["dt"], f"{name}: same rows ({len(h1)}) and step")
    worst = 0.0
    for kind, cols in KINDS.items():
        scale = max(np.abs(h1[c]).max() for c in cols)
        if kind == "energy":
            scale = s1["energy_initial"] + np.abs(h1["load_work"]).max()
        for c in cols:
            d = np.abs(h1[c] - h2[c]).max() / scale
            worst = max(worst, d)
            if d > 1e-10:
                check(False, f"{name}: column {c} differs by {d:.3g} of its scale")
    check(worst <= 1e-10, f"{name}: all history columns agree to {worst:.3g} relative (<= 1e-10)")
    c1, c2 = s1["contacts"][0], s2["contacts"][0]
    for key in ("impulse_normal", "impulse_tangential", "peak_R"):
        ref = max(abs(c1["impulse_normal"]) if key.startswith("impulse") else c1["peak_R"], 1e-300)
        d = abs(c1[key] - c2[key]) / ref
        check(d <= 1e-10, f"{name}: {key} {c1[key]:.10g} vs {c2[key]:.10g} ({d:.2g} relative)")
    check(c1["intervals"] == c2["intervals"] and c1["stick_steps"] == c2["stick_steps"]
          and c1["slip_steps"] == c2["slip_steps"], f"{name}: same intervals and stick/slip counts")
common.finish()
