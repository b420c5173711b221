#!/usr/bin/env python3
"""@brief Plots one `beamimpact sweep` result: timestep sensitivity and work-precision.

Usage: plot_sweep.py SWEEP_DIR --title TITLE --command CMD --version VERSION [--norm impulse]
Writes SWEEP_DIR/sensitivity.png, SWEEP_DIR/work_precision.png and their manifest
SWEEP_DIR/figures.json (the report's figure-set format, reports/figure_sets.py): the command that
made the data, the scene, the reference, the version and the date are said there once, as each
figure's caption, not drawn into the images.
"""
import argparse
import csv
import json
import os
import sys

from figure_sets import made_now, manifest_figure, write_manifest
from report_files import save_figure_atomic

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

KINDS = {"sensitivity": "timestep sensitivity", "work_precision": "work-precision"}
LABELS = {"impulse": "relative impulse error", "ua.rel_l2": "relative L2 error of striker displacement",
          "I.rel_linf": "max running-impulse error / total"}


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


def draw(rows, kind, title, norm):
    """@brief One figure of the sweep, one curve per mesh: the `norm` error against dt
    (kind "sensitivity") or against the solver's wall time ("work_precision"); every label inside
    the image (constrained layout).
    @return the matplotlib figure"""
    fig, ax = plt.subplots(figsize=(6.4, 4.8), layout="constrained")
    for mesh, rs in by_mesh(rows).items():
        xs = [float(r["dt"]) if kind == "sensitivity" else max(float(r["solver_seconds"]), 1e-6) for r in rs]
        ys = [max(float(r[norm]), 1e-16) for r in rs]
        ax.loglog(xs, ys, "o-", label=f"mesh x{mesh} ({rs[0]['steps']}+ steps)")
    ax.set_xlabel("dt (s)" if kind == "sensitivity" else "solver wall time (s)")
    ax.set_ylabel(LABELS.get(norm, norm))
    ax.set_title(f"{title}: {KINDS[kind]}")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def plot(args):
    rows, meta = read(args.dir)
    made, figures = made_now(), []
    caption = (f"{LABELS.get(args.norm, args.norm)} of {meta['method']} against {meta['reference']}, one curve "
               "per mesh multiplier (x1: the scene's own mesh); solver wall time from each run's summary.")
    for kind, what in KINDS.items():
        fig = draw(rows, kind, args.title, args.norm)
        save_figure_atomic(fig, os.path.join(args.dir, f"{kind}.png"), dpi=110)
        plt.close(fig)
        figures.append(manifest_figure(f"{kind}.png", f"{args.title}: {what}", args.command, meta["scene"],
                                       args.version, caption, made))
    write_manifest(os.path.join(args.dir, "figures.json"), args.title, figures,
                   about=f"`beamimpact sweep` of {meta['scene']} ({meta['method']}) against {meta['reference']}.")


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("dir")
    p.add_argument("--title", required=True)
    p.add_argument("--command", required=True)
    p.add_argument("--version", required=True)
    p.add_argument("--norm", default="impulse")
    plot(p.parse_args())
