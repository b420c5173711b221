#!/usr/bin/python3
"""@brief Animates a run's fields without ParaView: the beams in their deformed shape (the
deformation, i.e. each body's displacement relative to its mean translation, scaled), and the
contact forces as arrows, written as a GIF (matplotlib's Pillow writer) or an MP4 (ffmpeg).

Usage: reports/animate.py RUN_DIR [--out RUN_DIR/animation.gif] [--scale auto|S] [--every N]
         [--fps 20] [--frame T --out frame.png]
RUN_DIR comes from `beamimpact run SCENE --out RUN_DIR --fields`. --frame writes one PNG at the
time nearest T instead. Each picture shows the time and its scales (deformation, force arrows);
how it was made (this command, the run's scene, method and version, the date) is its manifest
OUT_figures.json beside it (reports/figure_sets.py), not drawn.
"""
import argparse
import importlib.util
import json
import os
import shlex
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import animation  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from figure_sets import manifest_figure, write_manifest  # noqa: E402
# The fields reader of the Python package, loaded by path: no compiled module needed here.
_spec = importlib.util.spec_from_file_location("beamimpact_fields", os.path.join(ROOT, "python", "beamimpact",
                                                                                  "fields.py"))
fields = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(fields)


def fail(message):
    print(f"animate: {message}", file=sys.stderr)
    sys.exit(2)


def writer_for(path, fps):
    """Pillow for .gif, ffmpeg for .mp4; a clear error when the one needed is missing."""
    ext = os.path.splitext(path)[1].lower()
    if ext == ".gif":
        if importlib.util.find_spec("PIL") is None:
            fail(f"{path}: a GIF needs Pillow (Debian: python3-pil); or write .mp4 (needs ffmpeg)")
        return animation.PillowWriter(fps=fps)
    if ext == ".mp4":
        if not animation.writers.is_available("ffmpeg"):
            fail(f"{path}: an MP4 needs ffmpeg on the PATH (Debian: ffmpeg); or write .gif (needs Pillow)")
        return animation.FFMpegWriter(fps=fps)
    fail(f"--out {path}: expected a .gif or .mp4 file (or --frame T with a .png)")


def shape(frame, scale):
    """Deformed node positions: reference + mean translation of each body + scale x the rest."""
    x = frame["points"][:, :2].copy()
    u = frame["displacement"][:, :2]
    for nodes in frame["bodies"]:
        mean = u[nodes].mean(axis=0)
        x[nodes] += mean + scale * (u[nodes] - mean)
    return x


def survey(steps):
    """One pass over the steps: the extent of the motion, the largest deformation and force."""
    lo, hi, defo, force = np.full(2, np.inf), np.full(2, -np.inf), 0.0, 0.0
    for _, path in steps:
        f = fields.read_vtu(path)
        x = f["points"][:, :2] + f["displacement"][:, :2]
        lo, hi = np.minimum(lo, x.min(axis=0)), np.maximum(hi, x.max(axis=0))
        u = f["displacement"][:, :2]
        for nodes in f["bodies"]:
            defo = max(defo, float(np.abs(u[nodes] - u[nodes].mean(axis=0)).max()))
        force = max(force, float(np.abs(f["contact_force"][:, :2]).max()))
    return lo, hi, defo, force


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("run_dir")
    p.add_argument("--out", help="animation (.gif/.mp4; default RUN_DIR/animation.gif) or, with --frame, a .png")
    p.add_argument("--scale", default="auto",
                   help="deformation scale; auto: 1, or larger so the largest deformation shows as 5 %% of the scene")
    p.add_argument("--every", type=int, default=1, help="use every n-th step of the fields")
    p.add_argument("--fps", type=int, default=20)
    p.add_argument("--frame", type=float, help="write one PNG at the step nearest this time (s)")
    a = p.parse_args(argv)
    try:
        steps = fields.steps(a.run_dir)[:: max(a.every, 1)]
        summary = json.load(open(os.path.join(a.run_dir, "summary.json")))
    except (OSError, ValueError) as e:
        fail(str(e))
    lo, hi, defo, fmax = survey(steps)
    size = float(np.max(hi - lo)) or 1.0
    if a.scale == "auto":
        scale = max(1.0, 0.05 * size / defo) if defo > 0 else 1.0
    else:
        try:
            scale = float(a.scale)
        except ValueError:
            fail(f"--scale {a.scale}: expected a number or auto")
    arrow = 0.1 * size / fmax if fmax > 0 else 0.0  # m per N: the largest force is 10 % of the scene
    pad = 0.08 * size

    fig, ax = plt.subplots(figsize=(8, 4.5), layout="constrained")
    ax.set_aspect("equal")
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    first = fields.read_vtu(steps[0][1])
    lines = [ax.plot([], [], "o-", ms=2.5, lw=1.8)[0] for _ in first["bodies"]]
    n = len(first["points"])  # one arrow per node; zero force draws nothing (minlength 0)
    quiver = ax.quiver(np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n), color="crimson",
                       angles="xy", scale_units="xy", scale=1.0, width=0.004, minlength=0)
    title = ax.set_title("")
    command = "reports/animate.py " + " ".join(shlex.quote(x) for x in argv)
    # What the picture's lengths mean is drawn with it; how it was made is the manifest's caption.
    legend = f"deformation x {scale:.3g}, contact force arrows {arrow:.3g} m/N"

    def draw(i):
        t, path = steps[i]
        f = fields.read_vtu(path)
        x = shape(f, scale)
        for line, nodes in zip(lines, f["bodies"]):
            line.set_data(x[nodes, 0], x[nodes, 1])
        F = f["contact_force"][:, :2]
        quiver.set_offsets(x)
        quiver.set_UVC(arrow * F[:, 0], arrow * F[:, 1])
        title.set_text(f"t = {t:.4g} s; {legend}")
        return lines + [quiver, title]

    if a.frame is not None:
        i = int(np.argmin([abs(t - a.frame) for t, _ in steps]))
        draw(i)
        out = a.out or os.path.join(a.run_dir, f"frame_{steps[i][0]:g}.png")
        fig.savefig(out, dpi=110)
    else:
        out = a.out or os.path.join(a.run_dir, "animation.gif")
        writer = writer_for(out, a.fps)
        animation.FuncAnimation(fig, draw, frames=len(steps), blit=False).save(out, writer=writer)
    manifest = os.path.splitext(out)[0] + "_figures.json"
    write_manifest(manifest, f"{summary['scene']} ({summary['method']})", [manifest_figure(
        os.path.basename(out), f"{summary['scene']} ({summary['method']})", command, summary["scene"],
        summary["version"], f"The beams in their deformed shape ({legend}); {len(steps)} steps of the run's fields.")])
    print(f"wrote {out} ({len(steps)} steps) and {manifest} (how it was made: its caption)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
