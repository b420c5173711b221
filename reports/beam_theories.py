#!/usr/bin/env python3
"""@brief Convergence of impulse and peak force under dt and mesh ladders, per beam theory and
contact law: S2 (verification/scenes/paper/s2_transverse.toml) with Euler-Bernoulli + hard,
Timoshenko + hard, Euler-Bernoulli + Hertz and Timoshenko + Hertz contact.

Usage: beam_theories.py [--build build] [--runs out/beam_theories] [--out reports/beam_theories]
                        [--levels 6] [--replot]

Each point is `beamimpact run` (the paper method) as a child process. The dt ladder keeps the
scene's mesh and halves dt from the paper's 0.01 s; the mesh ladder doubles every body's
elements with dt = 0.5 x the critical step of each mesh. The Hertz stiffness comes from the
scene's material: a sphere of radius 0.2 m (half of the 0.4 m depth) on a flat of the same
material, k = 4/3 E* sqrt(R), E* = E / (2 (1 - nu^2)) with nu = 0.3.

For each quantity q (impulse, peak force) the observed order between rungs h, h/2, h/4 is
log2(|q_h - q_h/2| / |q_h/2 - q_h/4|); a peak force that grows without converging is fitted
instead as q ~ dt^(-a) (the log-log slope over the last three rungs; Euler-Bernoulli theory:
a = 1/2). Writes OUT/ladders.json, OUT/ladders.md (the table) and OUT/ladders.png.
"""
import argparse
import json
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SCENE = "verification/scenes/paper/s2_transverse.toml"
NU = 0.3
E = 100.0  # N/m^2, S2's material
RADIUS = 0.2  # m
MODULUS = E / (2.0 * (1.0 - NU * NU))  # E*, N/m^2
ELEMENTS = {"A": 5, "B": 10}
TIMOSHENKO = ["bodies.A.theory=timoshenko", "bodies.B.theory=timoshenko"]
HERTZ = ["contacts[0].law=hertz", f"contacts[0].radius={RADIUS}", f"contacts[0].modulus={MODULUS!r}"]
VARIANTS = {
    "EB + hard": [],
    "Timoshenko + hard": TIMOSHENKO,
    "EB + Hertz": HERTZ,
    "Timoshenko + Hertz": TIMOSHENKO + HERTZ,
}


def run(exe, out, sets):
    """Runs the paper method on S2 with the overrides; returns its summary.json."""
    if not os.path.exists(os.path.join(out, "summary.json")):
        cmd = [exe, "run", SCENE, "--out", out, "--quiet", "--allow-long"]
        for s in sets + ["output.history=false"]:
            cmd += ["--set", s]
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"beam_theories: {' '.join(cmd)} failed: {r.stderr.strip()}")
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def quantities(summary, hertz):
    c = summary["contacts"][0]
    # The hard law's closure step carries the impact impulse m v / dt as a "force": its peak is
    # taken without the closure steps; the Hertz law has no closure impulse.
    peak = c["peak_R"] if hertz else c["peak_R_excluding_closure"]
    return {"impulse": c["impulse_normal"], "peak": peak, "intervals": len(c["intervals"]),
            "dt": summary["dt"] if "dt" in summary else None}


def orders(values):
    """Observed orders log2(|q_h - q_h/2| / |q_h/2 - q_h/4|) along a halving ladder."""
    out = []
    for a, b, c in zip(values, values[1:], values[2:]):
        d1, d2 = abs(a - b), abs(b - c)
        out.append(math.log2(d1 / d2) if d1 > 0 and d2 > 0 else None)
    return out


def growth_exponent(steps, values):
    """a in q ~ step^(-a) from the last three rungs (least squares in log-log)."""
    xs = [math.log(s) for s in steps[-3:]]
    ys = [math.log(v) for v in values[-3:]]
    mx, my = sum(xs) / 3, sum(ys) / 3
    return -sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def ladders(exe, runs, levels):
    data = {}
    for name, sets in VARIANTS.items():
        hertz = bool(sets and "hertz" in " ".join(sets))
        tag = name.replace(" + ", "_").replace(" ", "").lower()
        dt_rungs, mesh_rungs = [], []
        for k in range(levels):
            dt = 0.01 / 2 ** k
            s = run(exe, os.path.join(runs, tag, f"dt{k}"), sets + [f"time.dt={dt!r}"])
            dt_rungs.append({"dt": dt, **quantities(s, hertz)})
        for k in range(min(levels, 5)):
            m = 2 ** k
            mesh = [f"bodies.{b}.elements={n * m}" for b, n in ELEMENTS.items()]
            s = run(exe, os.path.join(runs, tag, f"mesh{k}"), sets + mesh + ["time.dt=\"auto\""])
            mesh_rungs.append({"refinement": m, "dt": s.get("dt"), **quantities(s, hertz)})
        entry = {"sets": sets, "dt_ladder": dt_rungs, "mesh_ladder": mesh_rungs}
        for lad, key in (("dt_ladder", "dt"), ("mesh_ladder", "refinement")):
            rungs = entry[lad]
            for q in ("impulse", "peak"):
                entry[f"{lad}.{q}.orders"] = orders([r[q] for r in rungs])
            steps = [r[key] if key == "dt" else 1.0 / r[key] for r in rungs]
            entry[f"{lad}.peak.growth_exponent"] = growth_exponent(steps, [r["peak"] for r in rungs])
        data[name] = entry
    return data


def fmt(x, spec=".3g"):
    return "-" if x is None else format(x, spec)


def table(data):
    lines = ["| variant | ladder | impulse (finest) | impulse orders | peak (finest) | peak orders | peak ~ h^-a, a |",
             "|---|---|---|---|---|---|---|"]
    for name, e in data.items():
        for lad in ("dt_ladder", "mesh_ladder"):
            r = e[lad][-1]
            lines.append(f"| {name} | {lad.split('_')[0]} | {r['impulse']:.6g} N s | "
                         f"{', '.join(fmt(o, '.2f') for o in e[f'{lad}.impulse.orders'])} | {r['peak']:.4g} N | "
                         f"{', '.join(fmt(o, '.2f') for o in e[f'{lad}.peak.orders'])} | "
                         f"{e[f'{lad}.peak.growth_exponent']:.2f} |")
    return "\n".join(lines) + "\n"


def plot(data, path):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for name, e in data.items():
        dts = [r["dt"] for r in e["dt_ladder"]]
        axes[0].loglog(dts, [r["peak"] for r in e["dt_ladder"]], "o-", label=name)
        ms = [r["refinement"] for r in e["mesh_ladder"]]
        axes[1].loglog(ms, [r["peak"] for r in e["mesh_ladder"]], "o-", label=name)
    axes[0].set_xlabel("dt (s)")
    axes[0].set_ylabel("peak contact force (N)")
    axes[0].set_title("S2, scene mesh: peak force vs dt")
    axes[0].invert_xaxis()
    axes[1].set_xlabel("mesh refinement (x elements), dt = 0.5 critical")
    axes[1].set_title("S2: peak force vs mesh")
    for ax in axes:
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--runs", default="out/beam_theories")
    ap.add_argument("--out", default="reports/beam_theories")
    ap.add_argument("--levels", type=int, default=6)
    ap.add_argument("--replot", action="store_true", help="re-plot OUT/ladders.json without running")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    if a.replot:
        with open(os.path.join(a.out, "ladders.json")) as f:
            data = json.load(f)
    else:
        exe = os.path.join(a.build, "beamimpact")
        if not os.path.exists(exe):
            sys.exit(f"beam_theories: no {exe}; build first (tools/build.sh)")
        data = ladders(exe, a.runs, a.levels)
        with open(os.path.join(a.out, "ladders.json"), "w") as f:
            json.dump(data, f, indent=1)
    with open(os.path.join(a.out, "ladders.md"), "w") as f:
        f.write(table(data))
    plot(data, os.path.join(a.out, "ladders.png"))
    print(table(data))


if __name__ == "__main__":
    main()
