#!/usr/bin/env python3
"""@brief Which beam theory comes closer to the 2D continuum on a stocky beam: S2 made stocky
(verification/scenes/extra/s2_stocky.toml, target L / h = 10) run by the paper integrator with
Euler-Bernoulli and with Timoshenko beams (mesh x 1, 2, 4, 8, dt = the automatic stable step) and
by FEniCSx (2D plane stress, Poisson 0; mesh presets coarse, default, fine: 1, 2, 4 Q2 elements
through the 1 m depth).

Usage: stocky_s2.py [--build build] [--runs out/stocky_s2] [--out reports/beam_theories]

The Timoshenko runs take Poisson 0 (G = E / 2, shear coefficient 5/6), the continuum's. Quantities
(each run's summary.json): total impulse (N s), the first contact's duration (s), the time in
contact (s, the sum of the intervals), the number of contact intervals, the peak force without closure steps (N; with the hard law it depends on the
mesh: reported, not compared) and the final velocities of A and B along y (m/s). Each beam theory's
finest mesh is compared with FEniCSx's finest (relative difference; absolute for the velocities).
Writes OUT/stocky_s2.json and OUT/stocky_s2.md. Exit 2 on bad input.
"""
import argparse
import json
import os
import subprocess
import sys

from report_files import write_json_atomic, write_text_atomic

SCENE = "verification/scenes/extra/s2_stocky.toml"
FENICSX = ["/usr/bin/python3", "references/fenicsx/run.py"]
THEORIES = {
    "Euler-Bernoulli": [],
    "Timoshenko": ["bodies.A.theory=timoshenko", "bodies.B.theory=timoshenko", "bodies.A.poisson=0",
                   "bodies.B.poisson=0"],
}
MESHES = [1, 2, 4, 8]
PRESETS = ["coarse", "default", "fine"]


def load(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def run(cmd, out):
    """Runs cmd (writing out/summary.json) unless out already holds it; returns the summary."""
    if not os.path.exists(os.path.join(out, "summary.json")):
        r = subprocess.run(cmd + ["--out", out, "--quiet"], capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"stocky_s2: {' '.join(cmd)} failed: {r.stderr.strip()}")
    return load(out)


def quantities(s):
    c = s["contacts"][0]
    iv = c["intervals"]
    fv = {name: b["final_velocity"][1] for name, b in s["bodies"].items()}
    return {"impulse": c["impulse_normal"], "duration": iv[0][1] - iv[0][0] if iv else 0.0,
            "in_contact": sum(b - a for a, b in iv),
            "contacts": len(iv), "peak": c.get("peak_R_excluding_closure", c["peak_R"]),
            "vA": fv["A"], "vB": fv["B"], "dt": s["dt"]}


def measure(exe, runs):
    data = {}
    for theory, sets in THEORIES.items():
        for m in MESHES:
            cmd = [exe, "run", SCENE, "--mesh", str(m)] + [a for s in sets for a in ("--set", s)]
            data[f"{theory} x{m}"] = quantities(run(cmd, os.path.join(runs, f"{theory[:2]}_{m}")))
    for p in PRESETS:
        data[f"FEniCSx {p}"] = quantities(run(FENICSX + [SCENE, "--mesh", p], os.path.join(runs, f"fx_{p}")))
    return data


def differences(data):
    ref = data[f"FEniCSx {PRESETS[-1]}"]
    out = {}
    for theory in THEORIES:
        q = data[f"{theory} x{MESHES[-1]}"]
        out[theory] = {"impulse": q["impulse"] / ref["impulse"] - 1.0, "duration": q["duration"] / ref["duration"] - 1.0,
                       "in_contact": q["in_contact"] / ref["in_contact"] - 1.0,
                       "vA": q["vA"] - ref["vA"], "vB": q["vB"] - ref["vB"]}
    return out


def table(data, diff):
    lines = ["| run | dt (s) | impulse (N s) | first contact (s) | in contact (s) | contacts | peak w/o closure (N) | "
             "v_A (m/s) | v_B (m/s) |", "|---|---|---|---|---|---|---|---|---|"]
    for k, q in data.items():
        lines.append(f"| {k} | {q['dt']:.3g} | {q['impulse']:.4f} | {q['duration']:.4f} | {q['in_contact']:.4f} | {q['contacts']} | "
                     f"{q['peak']:.3f} | {q['vA']:.4f} | {q['vB']:.4f} |")
    lines += ["", f"Finest beam mesh (x{MESHES[-1]}) against FEniCSx {PRESETS[-1]}:", "",
              "| theory | impulse | first contact | in contact | v_A (m/s) | v_B (m/s) |", "|---|---|---|---|---|---|"]
    for t, d in diff.items():
        lines.append(f"| {t} | {100 * d['impulse']:+.2f} % | {100 * d['duration']:+.2f} % | {100 * d['in_contact']:+.2f} % | {d['vA']:+.4f} | {d['vB']:+.4f} |")
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--runs", default="out/stocky_s2")
    ap.add_argument("--out", default="reports/beam_theories")
    a = ap.parse_args()
    exe = os.path.join(a.build, "beamimpact")
    if not os.access(exe, os.X_OK):
        print(f"stocky_s2: --build {a.build}: expected a build folder holding the beamimpact program", file=sys.stderr)
        return 2
    data = measure(exe, a.runs)
    diff = differences(data)
    os.makedirs(a.out, exist_ok=True)
    write_json_atomic(os.path.join(a.out, "stocky_s2.json"), {"runs": data, "against_fenicsx": diff})
    write_text_atomic(os.path.join(a.out, "stocky_s2.md"), table(data, diff))
    print(table(data, diff))
    return 0


if __name__ == "__main__":
    sys.exit(main())
