#!/usr/bin/python3
"""@brief The discrete stick threshold of the paper's closure step against the closure phase.

At the step in which an open contact closes, the paper's stick test compares the tangential
increment of the whole step with a penetration that builds up only after the closure instant.
The smallest mu at which the closure step sticks therefore moves with where in the
step the contact closes. This script measures that threshold, black-box, with the `beamimpact`
program: S4 (verification/scenes/paper/s4_oblique_*.toml) is started with the striker shifted
along its velocity by f |v| dt (f = 0, 1/N, ..., (N-1)/N: the closure phase phi sweeps one step),
and mu is bisected for the smallest value whose first closed step is a stick (state 1 in
history.csv). It does so for the paper's test ([paper] closure_slip = "step") and for the
option that measures the increment from the closure instant ("from_closure"), and plots both
against cot(alpha0), the ratio of tangential to normal approach speed (the threshold if the
contact's normal and tangential compliances were equal).

Usage: reports/stick_threshold.py [--binary build/beamimpact] [--out out/stick_threshold]
         [--angles 60,45] [--phases 8]
Writes OUT/stick_threshold.json, OUT/stick_threshold.png, OUT/stick_threshold.md and
OUT/stick_threshold_figures.json (the figure's manifest: command, scenes, version, date, caption;
nothing of it is drawn into the image).
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import tomllib

from figure_sets import manifest_figure, write_manifest
from report_files import save_figure_atomic, write_json_atomic, write_text_atomic

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(binary, scene, out, sets):
    cmd = [binary, "run", scene, "--out", out, "--quiet"] + [a for s in sets for a in ("--set", s)]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"stick_threshold: {' '.join(cmd)} failed ({p.returncode}): {p.stderr.strip()}")
    return json.load(open(os.path.join(out, "summary.json")))


def first_closed_state(out):
    with open(os.path.join(out, "history.csv")) as f:
        for row in csv.DictReader(f):
            if row["state"] != "0":
                return int(row["state"])
    return 0


def threshold(binary, scene, base_sets, tmp, hi=10.0, rel=1e-4):
    """Smallest mu (to rel) at which the first closed step sticks; inf when not even at hi."""
    def sticks(mu):
        out = os.path.join(tmp, "run")
        run(binary, scene, out, base_sets + [f"contacts[0].friction={mu!r}"])
        return first_closed_state(out) == 1
    if not sticks(hi):
        return math.inf
    lo = 0.0
    while hi - lo > rel * hi:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if sticks(mid) else (mid, hi)
    return hi


TITLE = "Discrete stick threshold of the closure step against the closure phase"
CAPTION = ("The paper's closure step sticks only above cot(alpha0)/(1 - phi); [paper] closure_slip = "
           "\"from_closure\" gives cot(alpha0) at every phase. phi: the fraction of the closure step before the "
           "contact closes; threshold: the smallest mu (bisected to 1e-4) whose first closed step sticks.")


def draw(result):
    """@brief One panel per angle: the threshold against the closure phase for both options, with
    cot(alpha0) and cot(alpha0) / (1 - phi); every label inside the image (constrained layout), how it
    was made in the manifest's caption. @return the matplotlib figure"""
    fig, axes = plt.subplots(1, len(result["angles"]), figsize=(5.5 * len(result["angles"]), 4.2), squeeze=False,
                             layout="constrained")
    for ax, e in zip(axes[0], result["angles"]):
        pts = sorted(e["points"], key=lambda p: p["phi"])
        ax.plot([p["phi"] for p in pts], [p["step"] for p in pts], "o-", label='paper: "step"')
        ax.plot([p["phi"] for p in pts], [p["from_closure"] for p in pts], "s-", label='"from_closure"')
        ax.axhline(e["cot_alpha0"], color="k", ls="--", lw=0.8, label="cot(alpha0)")
        phis = [i / 200 for i in range(0, 196)]
        ax.plot(phis, [e["cot_alpha0"] / (1 - f) for f in phis], color="gray", lw=0.8,
                label="cot(alpha0) / (1 - phi)")
        ax.set_ylim(0, 1.15 * max(p["step"] for p in pts if math.isfinite(p["step"])))
        ax.set_xlabel("closure phase phi (fraction of the step before closure)")
        ax.set_ylabel("stick threshold mu")
        ax.set_title(f"{e['scene']} (dt = {e['dt']:.3g} s)", fontsize=9)
        ax.legend(fontsize=8)
    return fig


def markdown(result):
    """@brief stick_threshold.md: how it was made, then one table per angle."""
    md = [f"# {TITLE}", "", f"Made by `{result['command']}` with beamimpact {result['version']}.", "",
          "phi: fraction of the closure step before the contact closes (linear in time). Threshold: the "
          "smallest mu (bisected to 1e-4) at which the first closed step sticks.", ""]
    for e in result["angles"]:
        pts = sorted(e["points"], key=lambda p: p["phi"])
        md += [f"## alpha0 = {e['alpha0_deg']} deg (`{e['scene']}`, dt = {e['dt']:.4g} s, cot alpha0 = "
               f"{e['cot_alpha0']:.4g})", "", "| phi | threshold, step (paper) | threshold, from_closure |",
               "|---|---|---|"]
        md += [f"| {p['phi']:.3f} | {p['step']:.4g} | {p['from_closure']:.4g} |" for p in pts]
        s = [p["step"] for p in pts]
        c = [p["from_closure"] for p in pts]
        md += ["", f"Spread over phi: step {min(s):.4g} .. {max(s):.4g}; from_closure {min(c):.4g} .. "
               f"{max(c):.4g}.", ""]
    return "\n".join(md) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default=os.path.join(ROOT, "build/beamimpact"))
    ap.add_argument("--out", default=os.path.join(ROOT, "out/stick_threshold"))
    ap.add_argument("--angles", default="60,45")
    ap.add_argument("--phases", type=int, default=8)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    version = subprocess.run([a.binary, "--version"], capture_output=True, text=True).stdout.strip()
    command = "reports/stick_threshold.py " + " ".join(sys.argv[1:])
    result = {"command": command, "version": version, "angles": []}
    with tempfile.TemporaryDirectory() as tmp:
        for angle in [int(x) for x in a.angles.split(",")]:
            scene = os.path.join(ROOT, f"verification/scenes/paper/s4_oblique_{angle}.toml")
            probe = run(a.binary, scene, os.path.join(tmp, "probe"), ["time.end=1e-6"])
            dt = probe["dt"]
            # The striker's end positions and velocity, read from the scene file itself.
            with open(scene, "rb") as f:
                toml = tomllib.load(f)
            A = toml["bodies"][0]
            v = A["velocity"]
            speed = math.hypot(*v)
            t_close = (A["end"][1] - toml["bodies"][1]["start"][1]) / -v[1]
            entry = {"alpha0_deg": angle, "scene": os.path.relpath(scene, ROOT), "dt": dt,
                     "cot_alpha0": 1 / math.tan(math.radians(angle)), "points": []}
            for k in range(a.phases):
                f = k / a.phases
                d = f * speed * dt  # m along the velocity: the contact closes f dt earlier
                shift = lambda p: f"[{p[0] + d * v[0] / speed!r}, {p[1] + d * v[1] / speed!r}]"
                sets = [f"bodies.A.start={shift(A['start'])}", f"bodies.A.end={shift(A['end'])}",
                        f"time.end={t_close + 4 * dt!r}", "time.output_every=1"]
                # closure phase phi: fraction of the closure step before the gap reaches zero
                t0 = t_close - f * dt
                phi = t0 / dt - math.floor(t0 / dt)
                point = {"shift_fraction_of_step": f, "phi": phi}
                for opt in ("step", "from_closure"):
                    point[opt] = threshold(a.binary, scene, sets + [f'paper.closure_slip="{opt}"'], tmp)
                print(f"alpha0 {angle} deg, phi {phi:.3f}: threshold step {point['step']:.4g}, "
                      f"from_closure {point['from_closure']:.4g} (cot {entry['cot_alpha0']:.4g})", flush=True)
                entry["points"].append(point)
            result["angles"].append(entry)
    write_json_atomic(os.path.join(a.out, "stick_threshold.json"), result)

    fig = draw(result)
    save_figure_atomic(fig, os.path.join(a.out, "stick_threshold.png"), dpi=110)
    plt.close(fig)
    write_text_atomic(os.path.join(a.out, "stick_threshold.md"), markdown(result))
    write_manifest(os.path.join(a.out, "stick_threshold_figures.json"), TITLE,
                   [manifest_figure("stick_threshold.png", TITLE, command,
                                    ", ".join(e["scene"] for e in result["angles"]), version, CAPTION)])
    print(f"wrote {a.out}/stick_threshold.{{json,png,md}} and stick_threshold_figures.json")


if __name__ == "__main__":
    main()
