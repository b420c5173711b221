#!/usr/bin/env python3
"""@brief Plots one `beamimpact sweep` result: timestep sensitivity and work-precision.

Usage: plot_sweep.py SWEEP_DIR --title TITLE --command CMD --version VERSION [--norm impulse]
Writes SWEEP_DIR/sensitivity.png and SWEEP_DIR/work_precision.png. Each figure carries, in its
footer, the command that made the data, the scene and the version (a figure must say how it was made).
"""
import argparse
import csv
import json
import os
import sys
import textwrap

from report_files import save_figure_atomic

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(sweep_dir):
    rows = [r for r in csv.DictReader(open(os.path.join(sweep_dir, "sweep.csv"))) if r["status"] == "ok"]
    meta = json.load(open(os.path.join(sweep_dir, "sweep.json")))
    if not rows:
        sys.exit(f"plot_sweep: {sweep_dir}/sweep.csv has no successful run")
    return rows, meta


def by_mesh(rows):
    meshes = {}
    for r in rows:
        meshes.setdefault(r["mesh"] or "1", []).append(r)  # no --mesh: the scene's own mesh
    return {m: sorted(v, key=lambda r: -float(r["dt"])) for m, v in sorted(meshes.items(), key=lambda kv: float(kv[0]))}


def footer(fig, args, meta):
    lines = textwrap.wrap(args.command, 105) + textwrap.wrap(
        f"scene: {meta['scene']}   reference: {meta['reference']}   beamimpact {args.version}", 105)
    fig.text(0.01, 0.01, "\n".join(lines), fontsize=6.5, family="monospace", va="bottom")


def plot(args):
    rows, meta = read(args.dir)
    groups = by_mesh(rows)
    norm = args.norm
    label = {"impulse": "relative impulse error", "ua.rel_l2": "relative L2 error of striker displacement",
             "I.rel_linf": "max running-impulse error / total"}.get(norm, norm)
    for kind in ("sensitivity", "work_precision"):
        fig, ax = plt.subplots(figsize=(6.4, 4.8))
        fig.subplots_adjust(left=0.14, right=0.97, bottom=0.25)
        for mesh, rs in groups.items():
            xs = [float(r["dt"]) if kind == "sensitivity" else max(float(r["solver_seconds"]), 1e-6) for r in rs]
            ys = [max(float(r[norm]), 1e-16) for r in rs]
            ax.loglog(xs, ys, "o-", label=f"mesh x{mesh} ({rs[0]['steps']}+ steps)")
        ax.set_xlabel("dt (s)" if kind == "sensitivity" else "solver wall time (s)")
        ax.set_ylabel(label)
        ax.set_title(f"{args.title}: {'timestep sensitivity' if kind == 'sensitivity' else 'work-precision'}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
        footer(fig, args, meta)
        save_figure_atomic(fig, os.path.join(args.dir, f"{kind}.png"), dpi=110)
        plt.close(fig)


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("dir")
    p.add_argument("--title", required=True)
    p.add_argument("--command", required=True)
    p.add_argument("--version", required=True)
    p.add_argument("--norm", default="impulse")
    plot(p.parse_args())
