#!/usr/bin/env python3
"""@brief The set-up on the user's path in steps: reads the Markdown table of
benchmarks/setup_benchmark (saved with the load average before and after it), plots warm and cold
set-up against DOFs for rods and frames beside the limits (100 steps warm, 300 cold), and writes
the plot and the manifest the HTML report reads.

Usage: plot_setup_benchmark.py [--run] [--table reports/setup/setup_benchmark.md]
                               [--out reports/setup] [--build build]
--run  first runs build/benchmarks/setup_benchmark 1e6 (about 1.5 min) into --table.
"""
import argparse
import os
import subprocess
import sys

from figure_sets import manifest_figure, write_manifest
from report_files import save_figure_atomic, write_text_atomic

import matplotlib


matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LIMITS = {"warm (steps)": 100, "cold (steps)": 300}


def fail(msg):
    print(f"plot_setup_benchmark: {msg}", file=sys.stderr)
    sys.exit(2)


def run_benchmark(build, table):
    exe = os.path.join(build, "benchmarks", "setup_benchmark")
    if not os.path.exists(exe):
        fail(f"{exe} not found: build it with `cmake --build {build} --target setup_benchmark`")
    load = os.getloadavg()
    out = subprocess.run([exe, "1e6"], capture_output=True, text=True, check=True).stdout
    write_text_atomic(table, out + f"\nload average before: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; "
                      f"after: {' '.join(f'{x:.2f}' for x in os.getloadavg())}\n")


def read_table(table):
    """The benchmark's header line (its version) and rows as dicts keyed by the column names."""
    try:
        lines = open(table).read().splitlines()
    except FileNotFoundError:
        fail(f"{table} not found: run with --run")
    rows = [[c.strip() for c in ln.strip().strip("|").split("|")] for ln in lines if ln.startswith("|")]
    if len(rows) < 3:
        fail(f"{table}: expected the benchmark's Markdown table")
    names = rows[0]
    load = next((ln for ln in lines if ln.startswith("load average")), "load average not recorded")
    return lines[0], load, [dict(zip(names, r)) for r in rows[2:]]


def plot(rows, png):
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for scene, marker in (("rods", "o"), ("frames", "s")):
        pts = [r for r in rows if r["scene"] == scene]
        dofs = [float(r["DOFs"]) for r in pts]
        for col, style in (("warm (steps)", "-"), ("cold (steps)", "--")):
            ax.plot(dofs, [float(r[col]) for r in pts], style, marker=marker, label=f"{scene}, {col.split()[0]}")
    for col, limit in LIMITS.items():
        ax.axhline(limit, color="grey", lw=0.8, ls=":")
        ax.text(1e3, limit * 1.05, f"limit {col.split()[0]}: {limit}", fontsize=8, color="grey")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("DOFs")
    ax.set_ylabel("set-up before the first step (steps of the same run)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    save_figure_atomic(fig, png, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--run", action="store_true")
    ap.add_argument("--table", default="reports/setup/setup_benchmark.md")
    ap.add_argument("--out", default="reports/setup")
    ap.add_argument("--build", default="build")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    if a.run:
        run_benchmark(a.build, a.table)
    header, load, rows = read_table(a.table)
    plot(rows, os.path.join(a.out, "setup.png"))
    version = header.split("beamimpact ")[1].split(";")[0] if "beamimpact " in header else "unknown"
    cols = ["scene", "DOFs", "step (us)", "warm (steps)", "cold (steps)", "CLI process (steps)"]
    write_manifest(
        os.path.join(a.out, "figures.json"), "Set-up on the user's path (steps of the same run)",
        [manifest_figure("setup.png", "Set-up in steps against size, warm and cold",
                         "/usr/bin/python3 reports/plot_setup_benchmark.py --run",
                         "verification/scenes/paper/s1_central.toml (rods), s2_transverse.toml (frames), "
                         "bodies.*.elements set for the DOFs", version,
                         "Ratios within one run; the machine was shared (load average in the text).")],
        about="benchmarks/setup_benchmark.cc: beamimpact::run from the scene in memory to the first "
              "step (model, critical step, integrator, contact pairs, trackers, recorder, first row), a "
              "1-step run minus one step, in steps of the same run (the step from differencing runs of N "
              "and 2N steps); warm: best of repeated runs in one process; cold: a fresh process's first "
              f"run; CLI process: a whole `beamimpact run` of 1 step. {load}.",
        tables=[{"title": "set-up in steps", "columns": cols, "rows": [[r[c] for c in cols] for r in rows]}])

if __name__ == "__main__":
    main()
