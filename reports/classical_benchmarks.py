#!/usr/bin/env python3
"""@brief The classical impact benchmarks against their exact answers: for the rod on a rigid wall,
the bouncing bar and the two rods with a second contact period (verification/scenes/benchmarks,
docs/benchmarks.md), every method that
accepts the scene is run at the scene's settings and drawn against the exact solution (contact
force and the contact node's displacement), with a table of the sequence norms of `beamimpact
compare` (impacts, impulse, contact starts, energy drift per impact, force oscillation).

Usage: classical_benchmarks.py [--build build] [--out reports/classical_benchmarks] [--runs DIR]
                               [--methods paper,paper:64,ida,siconos,example]

Writes OUT/<scene>.png and OUT/figures.json (the figure set the HTML report reads). A method that
refuses a scene (exit 2) is listed as not applicable with its reason. Exit 2 on bad input.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tomllib

from figure_sets import manifest_figure, write_manifest
from report_files import save_figure_atomic

import matplotlib


matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SCENES = ("rod_on_wall", "bouncing_bar", "two_rods_second_contact")
NORMS = ("impacts", "impulse", "contact_starts", "energy_drift_per_impact", "R_variation")
UNITS = {"impacts": "count difference", "impulse": "1", "contact_starts": "s", "energy_drift_per_impact": "1",
         "R_variation": "peak R"}


def fail(msg):
    print(f"classical_benchmarks: {msg}", file=sys.stderr)
    sys.exit(2)


def history(run_dir):
    with open(os.path.join(run_dir, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    cols = {k: [float(r[k]) for r in rows] for k in rows[0]}
    # The contact node's displacement along the component that moves most (x for the rod, y for the bar).
    ux, uy = cols["ua_x"], cols["ua_y"]
    cols["u"] = ux if max(map(abs, ux)) >= max(map(abs, uy)) else uy
    return cols


def run(exe, scene, entry, out):
    """`beamimpact run` of a methods entry: NAME, or NAME:M for M times the elements at dt / M."""
    method, _, mesh = entry.partition(":")
    extra = []
    if mesh:
        with open(scene, "rb") as f:
            dt = tomllib.load(f)["time"]["dt"]
        extra = ["--mesh", mesh, "--dt", repr(dt / int(mesh))]
    r = subprocess.run([exe, "run", scene, "--method", method, "--out", out, "--quiet"] + extra,
                       capture_output=True, text=True)
    reason = (r.stderr.strip().splitlines() or [""])[-1]
    return r.returncode, reason


def compare(exe, run_dir, ref_dir):
    js = os.path.join(run_dir, "compare.json")
    r = subprocess.run([exe, "compare", run_dir, ref_dir, "--json", js], capture_output=True, text=True)
    if r.returncode not in (0, 1):
        return {}
    with open(js) as f:
        return {n["name"]: n.get("value") for n in json.load(f)["norms"]}


def cell(v, name):
    if v is None:
        return "n/a"
    return f"{v:.0f}" if name == "impacts" else f"{v:.3g}"


def scene_figure(name, ref, runs, png):
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    a1.plot(ref["t"], ref["R"], "k-", lw=2.2, label="exact")
    a2.plot(ref["t"], ref["u"], "k-", lw=2.2, label="exact")
    for i, (method, h) in enumerate(runs):
        a1.plot(h["t"], h["R"], "-", lw=0.9, color=f"C{i}", label=method)
        a2.plot(h["t"], h["u"], "-", lw=0.9, color=f"C{i}", label=method)
    a1.set_ylabel("contact force R (N)")
    a2.set_ylabel("contact node displacement (m)")
    a2.set_xlabel("t (s)")
    a1.set_title(f"{name}: every method at the scene's settings against the exact solution", fontsize=10)
    a1.legend(fontsize=7, loc="upper right")
    a1.grid(alpha=0.3)
    a2.grid(alpha=0.3)
    fig.tight_layout()
    save_figure_atomic(fig, png, dpi=100)
    plt.close(fig)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="reports/classical_benchmarks")
    ap.add_argument("--runs", default="out/classical_benchmarks")
    ap.add_argument("--methods", default="paper,paper:64,ida,siconos,example",
                    help="methods entries: NAME, or NAME:M for M times the elements at dt / M")
    args = ap.parse_args(argv)
    exe = os.path.join(args.build, "beamimpact")
    if not os.access(exe, os.X_OK):
        fail(f"{exe}: expected the beamimpact program (--build DIR; build it with tools/build.sh beamimpact)")
    version = subprocess.run([exe, "--version"], capture_output=True, text=True).stdout.strip()
    os.makedirs(args.out, exist_ok=True)
    command = "/usr/bin/python3 reports/classical_benchmarks.py " + " ".join(argv)
    rows, figures = [], []
    for name in SCENES:
        scene = f"verification/scenes/benchmarks/{name}.toml"
        ref_dir = os.path.join(args.runs, name, "exact")
        code, why = run(exe, scene, "exact", ref_dir)
        if code != 0:
            fail(f"{scene}: the exact method failed (exit {code}): {why}")
        drawn = []
        for method in args.methods.split(","):
            out = os.path.join(args.runs, name, method.replace(":", "_x"))
            code, why = run(exe, scene, method, out)
            print(f"classical_benchmarks: {name} {method}: exit {code}", file=sys.stderr)
            if code != 0:
                status = "not applicable" if code == 2 else f"failed (exit {code})"
                why = why.removeprefix("error: ").split(" (accepts.")[0]  # the reason, not where it was declared
                rows.append([name, method, f"{status}: {why}"] + [""] * (len(NORMS) - 1))
                continue
            norms = compare(exe, out, ref_dir)
            rows.append([name, method] + [cell(norms.get(n), n) for n in NORMS])
            drawn.append((method, history(out)))
        png = f"{name}.png"
        scene_figure(name, history(ref_dir), drawn, os.path.join(args.out, png))
        figures.append(manifest_figure(
            png, f"{name}: contact force and contact node against the exact solution", command, scene, version,
            "Each method at the scene's own mesh and step (NAME:M: M times the elements at dt / M); exact in black "
            "(references/exact/RodOnWall.hpp, CoaxialRods.hpp)."))
    write_manifest(os.path.join(args.out, "figures.json"), "Classical impact benchmarks against their exact answers",
                   figures,
                   about="The rod on a rigid wall (d'Alembert), the bouncing bar (Doyen, Ern, Piperno 2011) and two "
                         "rods with a second contact period (Escalona, Mayo, Dominguez 1999), docs/benchmarks.md. "
                         "Norms of beamimpact compare against the exact run: "
                         + ", ".join(f"{n} ({UNITS[n]})" for n in NORMS) + ".",
                   tables=[{"title": "Sequence norms against exact", "columns": ["scene", "method"] + list(NORMS),
                            "rows": rows}])
    print(f"classical_benchmarks: wrote {args.out}/figures.json")


if __name__ == "__main__":
    main(sys.argv[1:])
