#!/usr/bin/env python3
"""@brief Draws a scored method's runs on the committed work-precision diagrams: for each scene of the
scorecard with a work-precision set (reports/work_precision/<scene>/work_precision.json), the set's
curves (impulse error against CPU time of the paper integrator, IDA, FEniCSx, Siconos, exact) and
the scored run as one large marker (its impulse error against the scorecard's process seconds).

Usage: scorecard_figures.py SCORE_DIR [--sets reports/work_precision]

SCORE_DIR holds scorecard.json (`beamimpact score NAME --out SCORE_DIR`). Writes
SCORE_DIR/<scene>_work_precision.png and the manifest SCORE_DIR/figures.json (which diagram belongs
to which scene and how it was made: command, version, date), then renders SCORE_DIR/scorecard.html
again through reports/render.py, which embeds the diagrams with their captions. A second run
replaces the diagrams. Exit 2 with one line on bad input.
"""
import argparse
import json
import os
import sys

from figure_sets import made_now, manifest_figure, write_manifest
from report_files import save_figure_atomic

import matplotlib


matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def fail(msg):
    print(f"scorecard_figures: {msg}", file=sys.stderr)
    sys.exit(2)


def load_json(path, what):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail(f"{path}: expected {what} ({e})")


def impulse_error(scene):
    for q in scene.get("quantities", []):
        if q.get("metric") == "impulse" and q.get("error") is not None:
            return q["error"]
    return None


MARKERS = "*PDXsv^<>"
MARK_COLOURS = ("black", "gold", "white", "cyan", "magenta", "lime", "grey", "orange")  # apart from the curves' C0-C9


def figure(name, wp, marks, out_png):
    """One diagram of scene `name`: the set's curves and one large marker per scored run in
    `marks` ((method, scorecard scene entry) pairs); returns the caption."""
    fig, ax = plt.subplots(figsize=(8.4, 4.2))
    curves = {}
    for p in wp["points"]:
        if p.get("status") == "ok" and p["error"].get("impulse"):
            curves.setdefault(p["method"], []).append((p["cpu_seconds_min"], p["error"]["impulse"]))
    for i, (label, pts) in enumerate(sorted(curves.items())):
        pts.sort()
        ax.loglog([c for c, _ in pts], [e for _, e in pts], "o-", ms=4, color=f"C{i}", label=label, alpha=0.6)
    said = []
    for k, (method, scene) in enumerate(marks):
        err, secs = impulse_error(scene), scene.get("process_seconds")
        if err and secs:
            ax.loglog([secs], [err], MARKERS[k % len(MARKERS)], ms=13, color=MARK_COLOURS[k % len(MARK_COLOURS)],
                      markeredgecolor="k", label=f"{method} (scored: {scene['run']})")
            said.append(f"{method} {err:.3g}")
        else:
            said.append(f"{method}: {scene['status'] if scene['status'] != 'ok' else 'no impulse error'}")
    ax.set_xlabel("CPU time of the run (s); scored runs: process seconds")
    ax.set_ylabel("relative impulse error")
    ax.set_title(f"{name}: reference {wp['reference']}", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=6, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    save_figure_atomic(fig, out_png, dpi=110)
    plt.close(fig)
    return (f"Curves: {wp['command']} (version {wp['version']}); markers: the scored runs "
            f"(impulse error against the scorecard's reference: {'; '.join(said)}).")


def manifest(path, card, entries, argv):
    """@brief Writes figures.json of the score folder: each diagram's PNG, scene, caption and how it was
    made (this script's command, the scorecard's version, the date). @param entries (scene, png, caption)"""
    made = made_now()
    command = " ".join(["/usr/bin/python3 reports/scorecard_figures.py", *argv])
    write_manifest(path, "On the work-precision diagrams",
                   [manifest_figure(png, f"{scene}: {card['method']} on the work-precision diagram", command, scene,
                                    card.get("version", "?"), caption, made) for scene, png, caption in entries],
                   about=f"The scored runs of {card['method']} (markers) on the committed work-precision curves of "
                         "each scene that has a set (reports/work_precision).")


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("score_dir")
    ap.add_argument("--sets", default=os.path.join(HERE, "work_precision"), help="folder of the work-precision sets")
    args = ap.parse_args(argv)
    card = load_json(os.path.join(args.score_dir, "scorecard.json"), "a scorecard (beamimpact score)")
    entries = []
    for scene in card.get("scenes", []):
        wp_path = os.path.join(args.sets, scene["scene"], "work_precision.json")
        if not os.path.isfile(wp_path):
            continue  # only the paper's scenes have a work-precision set
        png = f"{scene['scene']}_work_precision.png"
        wp = load_json(wp_path, "a work-precision set")
        entries.append((scene["scene"], png, figure(scene["scene"], wp, [(card["method"], scene)],
                                                    os.path.join(args.score_dir, png))))
    manifest(os.path.join(args.score_dir, "figures.json"), card, entries, argv)
    print(f"scorecard_figures: {len(entries)} diagram(s) in {os.path.join(args.score_dir, 'figures.json')}")
    import render  # the page, with the diagrams, from the one page generator
    render.main(["scorecard", args.score_dir])


if __name__ == "__main__":
    main(sys.argv[1:])
