#!/usr/bin/env python3
"""@brief The paper's Figures 6-14 (Pu & Chi 2011) reproduced: the same quantities, axes and time
spans, the paper integrator's curve with the references that accept each scene overlaid (exact,
IDA, FEniCSx), and a table of each claim the paper's text makes next to what the suite measures.

Usage: paper_figures.py [--out reports/paper_figures] [--runs out/paper_figures] [--build build] [--reuse]

Runs every scene x method once (`beamimpact run`, FEniCSx through references/fenicsx/run.py; about
1-2 min on 2 cores), then writes OUT/fig06.png .. fig14.png, OUT/claims.md, OUT/claims.json and
OUT/figures.json (the manifest of the HTML report). Progress on stderr. A reference that refuses a
scene (exit 2, e.g. exact with friction) is left out of that figure and named in its caption
(figures.json: each figure's command, scenes, version, date and caption; nothing of it is drawn).
"""
import argparse
import csv
import functools
import json
import os
import subprocess
import sys
import time

from figure_sets import manifest_figure, write_manifest
from report_files import save_figure_atomic, write_json_atomic, write_text_atomic

import matplotlib


matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from work_precision import FENICSX_CMD, PAPER  # noqa: E402  (one owner of the scene folder and FEniCSx command)
METHODS = ("paper", "exact", "ida", "fenicsx")
STYLE = {"paper": dict(color="k", lw=1.4), "exact": dict(color="C3", lw=1.0, ls="--"),
         "ida": dict(color="C0", lw=1.0, ls=":"), "fenicsx": dict(color="C2", lw=1.0, ls="-.")}
LABEL = {"paper": "paper integrator", "exact": "exact", "ida": "IDA (same beams)", "fenicsx": "FEniCSx (2D continuum)"}
SCENES = ("s1_central", "s2_transverse", "s3_surface_10", "s3_surface_20", "s4_oblique_90", "s4_oblique_60",
          "s4_oblique_45")


def fail(msg):
    print(f"paper_figures: {msg}", file=sys.stderr)
    sys.exit(2)


def run_all(a):
    """Runs every scene x method; returns {(scene, method): run dir or None (refused / failed)} and notes."""
    runs, notes, t0 = {}, {}, time.monotonic()
    jobs = [(s, m) for s in SCENES for m in METHODS]
    for k, (s, m) in enumerate(jobs):
        el = time.monotonic() - t0
        left = el / k * (len(jobs) - k) if k else float("nan")
        print(f"[paper-figures] {s} {m} ({k + 1}/{len(jobs)}, elapsed {el:.0f} s, ~{left:.0f} s left)",
              file=sys.stderr, flush=True)
        scene, out = f"{PAPER}/{s}.toml", os.path.join(a.runs, f"{s}.{m}")
        cmd = (FENICSX_CMD + [scene, "--out", out, "--quiet"] if m == "fenicsx"
               else [a.exe, "run", scene, "--out", out, "--quiet", "--method", m])
        if a.reuse and os.path.exists(os.path.join(out, "summary.json")):
            runs[(s, m)] = out
            continue
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode == 0:
            runs[(s, m)] = out
        else:
            runs[(s, m)] = None
            why = r.stderr.strip().splitlines()[-1] if r.stderr.strip() else f"exit {r.returncode}"
            why = why.split("cannot solve this scene: ")[-1].split(";")[0]  # the failed condition only
            notes[(s, m)] = f"{m} ({s}) refused: {why[:120]}"
            print(f"[paper-figures]   {notes[(s, m)]}", file=sys.stderr)
    return runs, notes


@functools.cache
def history(d):
    with open(os.path.join(d, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


@functools.cache
def summary(d):
    with open(os.path.join(d, "summary.json")) as f:
        return json.load(f)


def draw(runs, num, title, panels, xlabel):
    """@brief One of the paper's figures from the runs: one panel per (ylabel, curves), every method
    that ran the curve's scene on it; every label inside the image (constrained layout), nothing of
    how it was made drawn (the manifest's caption says it).
    @param runs {(scene, method): run directory or None}
    @param panels [(ylabel, [(scene, column, transform, {"color", "text"})])]
    @return the matplotlib figure"""
    fig, axes = plt.subplots(len(panels), 1, figsize=(7.5, 2.6 * len(panels) + 0.8), squeeze=False,
                             layout="constrained")
    for ax, (ylabel, curves) in zip(axes[:, 0], panels):
        tops = []
        for (scene, col, f, suffix) in curves:
            for m in METHODS:
                d = runs.get((scene, m))
                if not d:
                    continue
                h = history(d)
                if col not in h:
                    continue
                st = dict(STYLE[m])
                if suffix.get("color"):
                    st["color"] = suffix["color"]
                ys = [f(v) for v in h[col]]
                ax.plot(h["t"], ys, label=f"{LABEL[m]}{suffix.get('text', '')}", **st)
                tops.append(sorted(ys)[int(0.97 * (len(ys) - 1))])
        if col == "R" and tops:
            # Closure rows (the paper's one-step impulse, IDA's penalty spike) would flatten the plot:
            # the axis stops above the largest 97th percentile; the peaks are in the claims table.
            ax.set_ylim(bottom=-0.05 * max(tops), top=1.6 * max(tops))
            ax.text(0.01, 0.97, "closure spikes clipped", transform=ax.transAxes, fontsize=6, va="top")
        ax.set_ylabel(ylabel)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=6, ncol=3)
    axes[-1, 0].set_xlabel(xlabel)
    fig.suptitle(f"Figure {num}: {title}", fontsize=10)
    return fig


COMMAND = "/usr/bin/python3 reports/paper_figures.py"


class Figures:
    def __init__(self, a, runs, notes, version):
        self.a, self.runs, self.notes, self.version, self.manifest = a, runs, notes, version, []

    def make(self, num, title, scenes, panels, xlabel, caption):
        """Draws and saves one figure; its manifest entry says how it was made and, in its caption,
        which reference refused which scene (left out of the figure)."""
        fig = draw(self.runs, num, title, panels, xlabel)
        png = f"fig{num:02d}.png"
        save_figure_atomic(fig, os.path.join(self.a.out, png), dpi=100)
        plt.close(fig)
        missing = sorted({self.notes[(s, m)] for (s, m) in self.notes if s in scenes})
        caption = " ".join(filter(None, [caption, f"Not shown: {'; '.join(missing)}." if missing else ""]))
        self.manifest.append(manifest_figure(png, f"Figure {num}: {title}", COMMAND,
                                             ", ".join(f"{PAPER}/{s}.toml" for s in scenes), self.version, caption))


def ident(v):
    return v


def all_figures(F):
    C = lambda color, text: {"color": color, "text": text}  # noqa: E731
    F.make(6, "force of central collision (S1)", ["s1_central"], [("R (N)", [("s1_central", "R", ident, {})])],
           "t (s)", "Paper: the contact force, 10 + 10 elements, dt = 0.01 s, against the analytical 2 N on [0.5, 2.5] s.")
    F.make(7, "velocity of the contact nodes (S1)", ["s1_central"],
           [("v_x of node i (A's end) (m/s)", [("s1_central", "va_x", ident, {})]),
            ("v_x of node j (B's end) (m/s)", [("s1_central", "vb_x", ident, {})])],
           "t (s)", "Node i ends at rest, node j at 1 m/s (exact).")
    F.make(8, "position of the contact nodes (S1)", ["s1_central"],
           [("x of node i (m)", [("s1_central", "ua_x", lambda v: 10.0 + v, {})]),
            ("x of node j (m)", [("s1_central", "ub_x", lambda v: 10.5 + v, {})])],
           "t (s)", "The paper's axis is the position (9.25-11 m): initial coordinate + displacement.")
    F.make(9, "force of transverse collision (S2)", ["s2_transverse"], [("R (N)", [("s2_transverse", "R", ident, {})])],
           "t (s)", "The paper reports three collisions in 3 s.")
    F.make(10, "vertical displacement of the contact nodes (S2)", ["s2_transverse"],
           [("u_y of node i (m)", [("s2_transverse", "ua_y", ident, {})]),
            ("u_y of node j (m)", [("s2_transverse", "ub_y", ident, {})])], "t (s)", "A large deformation: soft beams.")
    F.make(11, "vertical velocity of the contact nodes (S2)", ["s2_transverse"],
           [("v_y of node i (m/s)", [("s2_transverse", "va_y", ident, {})]),
            ("v_y of node j (m/s)", [("s2_transverse", "vb_y", ident, {})])], "t (s)", "")
    F.make(12, "vertical displacement at x = 4.5 m: interpolated (10 el.) vs node (20 el.) model (S3)",
           ["s3_surface_10", "s3_surface_20"],
           [("u_y at x = 4.5, 10 elements (m)", [("s3_surface_10", "ub_y", ident, {})]),
            ("u_y at x = 4.5, 20 elements (m)", [("s3_surface_20", "ub_y", ident, {})])], "t (s)",
           "Each panel: that mesh's paper and IDA runs; exact and FEniCSx do not depend on B's beam mesh.")
    F.make(13, "y displacement of node i (A) and of B's centre j, alpha0 = 90 / 60 / 45 deg (S4)",
           ["s4_oblique_90", "s4_oblique_60", "s4_oblique_45"],
           [(f"{lab} (m)", [(f"s4_oblique_{ang}", col, ident, C(f"C{k}", f", {ang} deg"))
                            for k, ang in enumerate((90, 60, 45))]) for lab, col in (("u_y of node i", "ua_y"),
                                                                                    ("u_y of B's centre j", "ub_y"))],
           "t (s)", "Colours: angle; line style: method (solid paper, dotted IDA, dash-dot FEniCSx).")
    F.make(14, "normal contact force, alpha0 = 90 and 45 deg (S4)", ["s4_oblique_90", "s4_oblique_45"],
           [("R (N)", [(f"s4_oblique_{ang}", "R", ident, C(f"C{k}", f", {ang} deg")) for k, ang in enumerate((90, 45))])],
           "t (s)", "Colours: angle; line style: method.")


def peak(d, col, sign=1.0):
    h = history(d)
    return max(sign * v for v in h[col])


def claims(runs):
    """Each claim of the paper's text, the measured value per method, and whether it holds."""
    out = []

    def per_method(scene, f):
        return {m: f(runs[(scene, m)]) for m in METHODS if runs.get((scene, m))}

    imp = per_method("s1_central", lambda d: summary(d)["contacts"][0]["impulse_normal"])
    out.append({"figure": "6-8", "claim": "the algorithm is reliable against the analytical solution (S1): "
                "impulse 4 N s, contact [0.5, 2.5] s",
                "measured": {m: f"impulse {v:.4g} N s ({(v - 4) / 4:+.1%}), contact "
                             + ", ".join(f"[{a:.3f}, {b:.3f}]" for a, b in summary(runs[("s1_central", m)])["contacts"][0]["intervals"])
                             + " s" for m, v in imp.items()},
                "holds": abs(imp["paper"] - 4.0) / 4.0 < 0.05})
    cnt = per_method("s2_transverse", lambda d: len(summary(d)["contacts"][0]["intervals"]))
    out.append({"figure": "9-10", "claim": "three separate collisions in the simulated time (S2, 3 s; each method's own merge rule for chatter)",
                "measured": {m: f"{v} collision(s)" for m, v in cnt.items()}, "holds": cnt.get("paper") == 3})
    defl = per_method("s2_transverse", lambda d: peak(d, "ub_y", -1.0))
    out.append({"figure": "10", "claim": "a large deformation (S2)", "measured":
                {m: f"max downward deflection of j {v:.3g} m (beam 10 m)" for m, v in defl.items()},
                "holds": defl.get("paper", 0) > 0.1})
    d10 = per_method("s3_surface_10", lambda d: peak(d, "ub_y", -1.0))
    d20 = per_method("s3_surface_20", lambda d: peak(d, "ub_y", -1.0))
    out.append({"figure": "12", "claim": "the interpolated (10-element) model gives the smaller maximal "
                "displacement at x = 4.5 m than the 20-element node model; the two are close",
                "measured": {m: f"10 el. {d10[m]:.4g} m vs 20 el. {d20[m]:.4g} m ({(d10[m] - d20[m]) / d20[m]:+.1%})"
                             for m in d10 if m in d20},
                "holds": d10["paper"] < d20["paper"] and abs(d10["paper"] - d20["paper"]) / d20["paper"] < 0.1})
    if "exact" in d20:
        out.append({"figure": "12", "claim": "with 20 elements the results are more exact",
                    "measured": {"paper": f"10 el. off the exact maximum by {abs(d10['paper'] - d20['exact']):.3g} m, "
                                          f"20 el. by {abs(d20['paper'] - d20['exact']):.3g} m (exact {d20['exact']:.4g} m)"},
                    "holds": abs(d20["paper"] - d20["exact"]) < abs(d10["paper"] - d20["exact"])})
    angles = (90, 60, 45)
    for what, col, f in (("B's y displacement (max downward at its centre, m)", "ub_y", lambda d: peak(d, "ub_y", -1.0)),
                         ("the rebound vertical velocity of A (max upward v_y of node i, m/s)", "va_y",
                          lambda d: peak(d, "va_y", 1.0)),
                         ("the normal contact force (peak R without closure rows, N; IDA: its penalty spring's peak)", "R", lambda d: summary(d)["contacts"][0]["peak_R_excluding_closure"])):
        vals = {ang: per_method(f"s4_oblique_{ang}", f) for ang in angles}
        meas = {m: " / ".join(f"{vals[ang][m]:.3g}" for ang in angles) for m in METHODS
                if all(m in vals[ang] for ang in angles)}
        falls = lambda m: vals[90][m] > vals[60][m] > vals[45][m]  # noqa: E731
        out.append({"figure": "13-14", "claim": f"as alpha0 decreases (90 / 60 / 45 deg), {what} becomes smaller",
                    "measured": {m: v + (" (falls)" if falls(m) else " (does not fall)") for m, v in meas.items()},
                    "holds": falls("paper")})
    slip = {ang: summary(runs[(f"s4_oblique_{ang}", "paper")])["contacts"][0].get("slip_steps", 0) for ang in angles}
    out.append({"figure": "13", "claim": "beam A slides on B at 60 and 45 deg (cot alpha0 > mu = 0.3), "
                "sticks at 90 deg", "measured": {"paper": f"slip steps 90/60/45: {slip[90]} / {slip[60]} / {slip[45]}"},
                "holds": slip[90] == 0 and slip[60] > 0 and slip[45] > 0})
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", default="reports/paper_figures")
    p.add_argument("--runs", default="out/paper_figures")
    p.add_argument("--build", default=os.environ.get("BEAMIMPACT_BUILD_DIR", "build"))
    p.add_argument("--reuse", action="store_true", help="keep runs of --runs that completed (summary.json)")
    a = p.parse_args()
    a.exe = os.path.join(a.build, "beamimpact")
    if not os.access(a.exe, os.X_OK):
        fail(f"--build {a.build}: no beamimpact program there (build first: bash tools/build.sh)")
    os.makedirs(a.out, exist_ok=True)
    runs, notes = run_all(a)
    # The version of the runs the figures show (with --reuse they may be older than this build);
    # FEniCSx runs state theirs with dolfinx's, so beamimpact's comes from the others.
    version = ", ".join(sorted({summary(d).get("version", "?") for (_, m), d in runs.items() if d and m != "fenicsx"}))
    for s in SCENES:
        if not runs.get((s, "paper")):
            fail(f"{s}: the paper integrator's run failed: {notes.get((s, 'paper'))}")
    F = Figures(a, runs, notes, version)
    all_figures(F)
    cl = claims(runs)
    cmd = COMMAND
    write_json_atomic(os.path.join(a.out, "claims.json"), {"command": cmd, "version": version, "claims": cl})
    rows = [[c["figure"], c["claim"], "; ".join(f"{m}: {v}" for m, v in c["measured"].items()),
             "yes" if c["holds"] else "NO"] for c in cl]
    write_text_atomic(os.path.join(a.out, "claims.md"),
                      f"# The paper's claims against what the suite measures\n\nMade by `{cmd}`, beamimpact {version}; "
                      "runs at the paper's settings (scenes in verification/scenes/paper/). 'holds' judges the paper "
                      "integrator's run.\n\n| figure | paper's claim | measured | holds (paper integrator) |\n|---|---|---|---|\n"
                      + "".join("| " + " | ".join(r) + " |\n" for r in rows))
    write_manifest(os.path.join(a.out, "figures.json"), "The paper's Figures 6-14 and its claims", F.manifest,
                   about="Pu & Chi 2011, Figures 6-14: the paper integrator at the paper's settings with the "
                         "references that accept each scene overlaid.",
                   tables=[{"title": "claims", "columns": ["figure", "paper's claim", "measured",
                                                           "holds (paper integrator)"], "rows": rows}])
    print(open(os.path.join(a.out, "claims.md")).read())


if __name__ == "__main__":
    main()
