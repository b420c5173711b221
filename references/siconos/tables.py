#!/usr/bin/python3
"""The tables of docs/siconos.md.

  /usr/bin/python3 references/siconos/tables.py s1 --beamimpact build/beamimpact --work DIR [--elements 10,100]
  /usr/bin/python3 references/siconos/tables.py scenes --beamimpact build/beamimpact --work DIR

s1: Siconos, the minimal example, the paper integrator and the exact solution on S1 (central
collision) at 10, 100 and 1000 elements per body, dt = 0.1 le / c (the paper's 0.01 s at 10
elements, scaled with the mesh): impulse (N s), first contact interval (s), final velocities (m/s).
scenes: Siconos, the example and the paper integrator on the other paper scenes as shipped (S4
with kinematics = "linear", the formulation the export can write): impulse, impacts, first
interval, peak force excluding closures."""

import argparse
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = os.path.join(ROOT, "verification", "scenes", "paper", "s1_central.toml")
PY = "/usr/bin/python3"


def run(method, scene, sets, work, exe, mesh=None, dt=None, tag=""):
    out = os.path.join(work, f"{method}_{os.path.basename(scene)[:-5]}{tag}")
    if method in ("paper", "exact"):
        cmd = [exe, "run", scene, "--out", out, "--method", method, "--quiet", "--allow-long"]
        for s in sets:
            cmd += ["--set", s]
    elif method == "siconos":
        cmd = [PY, os.path.join(ROOT, "references", "siconos", "run.py"), scene, "--out", out,
               "--beamimpact", exe, "--quiet"] + [x for s in sets for x in ("--set", s)]
    else:
        cmd = [PY, os.path.join(ROOT, "examples", "external_solver", "penalty_central.py"), scene, "--out", out,
               "--beamimpact", exe, "--quiet"]
        cmd += ["--mesh", str(mesh)] if mesh else []
        cmd += ["--dt", str(dt)] if dt else []
    subprocess.run(cmd, check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def s1_table(a, exe):
    print("| elements | method | impulse (N s) | first interval (s) | intervals | v_A (m/s) | v_B (m/s) | wall (s) |")
    print("|---|---|---|---|---|---|---|---|")
    for n in (int(x) for x in a.elements.split(",")):
        sets = [f"bodies.A.elements={n}", f"bodies.B.elements={n}", f"time.dt={0.1 / n}"]
        for method in ("exact", "paper", "siconos", "example"):
            s = run(method, SCENE, sets, a.work, exe, mesh=n // 10, dt=0.1 / n, tag=f"_{n}")
            c = s["contacts"][0]
            iv = c["intervals"][0] if c["intervals"] else [float("nan")] * 2
            va, vb = s["bodies"]["A"]["final_velocity"][0], s["bodies"]["B"]["final_velocity"][0]
            print(f"| {n} | {method} | {c['impulse_normal']:.5f} | [{iv[0]:.4g}, {iv[1]:.4g}] | "
                  f"{len(c['intervals'])} | {va:.5f} | {vb:.5f} | {s['wall_seconds']:.3g} |")
            sys.stdout.flush()


def scenes_table(a, exe):
    print("| scene | method | impulse (N s) | impacts | first interval (s) | peak R excl. closure (N) | wall (s) |")
    print("|---|---|---|---|---|---|---|")
    for name in ("s2_transverse", "s3_surface_10", "s3_surface_20", "s4_oblique_90", "s4_oblique_60",
                 "s4_oblique_45"):
        scene = os.path.join(ROOT, "verification", "scenes", "paper", name + ".toml")
        sets = ['model.kinematics="linear"'] if name.startswith("s4") else []
        for method in ("paper", "siconos", "example"):
            if method == "example" and (sets or name.startswith("s4")):
                print(f"| {name} | {method} | refused (friction) | | | | |")
                continue
            s = run(method, scene, sets, a.work, exe)
            c = s["contacts"][0]
            iv = c["intervals"][0] if c["intervals"] else [float("nan")] * 2
            print(f"| {name}{' (linear)' if sets else ''} | {method} | {c['impulse_normal']:.5g} | {c['impacts']} | "
                  f"[{iv[0]:.4g}, {iv[1]:.4g}] | {c['peak_R_excluding_closure']:.5g} | {s['wall_seconds']:.3g} |")
            sys.stdout.flush()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("table", choices=["s1", "scenes"])
    ap.add_argument("--beamimpact", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--elements", default="10,100,1000")
    a = ap.parse_args()
    exe = os.path.abspath(a.beamimpact)
    (s1_table if a.table == "s1" else scenes_table)(a, exe)


if __name__ == "__main__":
    main()
