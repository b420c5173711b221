#!/usr/bin/env python3
"""@brief Maps of one `beamimpact study` over two of its parameters: the error map (a norm of the
method against the study's reference, log colour scale) and the stability map (ok, energy created
above the bound, diverged, refused; cases above a `breaks` bound marked x), one panel per value of
a third parameter (e.g. the mesh).

Usage: study_maps.py STUDY_DIR --x alpha0 --y mu [--facet mesh] [--norm impulse] [--method paper]
                     [--command CMD] [--out PREFIX]
Writes PREFIX_error.png and PREFIX_stability.png (default STUDY_DIR/study) and their manifest
PREFIX_figures.json in the report's figure-set format (reports/figure_sets.py: png, title, command,
scene, version, made, caption): how the data was made (command, study, scene, reference, version
from study.json) is said there once, as each figure's caption, not drawn into the image.
Run with /usr/bin/python3 (matplotlib from Debian's python3-matplotlib).
"""
import argparse
import json
import math
import os
import sys

from figure_sets import made_now, manifest_figure, write_manifest
from report_files import save_figure_atomic

import matplotlib

matplotlib.use("Agg")
import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

STATUS = ["ok", "no_reference", "energy", "diverged", "error"]
COLOURS = ["#4c9a2a", "#bbbbbb", "#f0a500", "#c0392b", "#5b2c6f"]


def load(study_dir):
    path = os.path.join(study_dir, "study.json")
    try:
        meta = json.load(open(path))
    except (OSError, ValueError) as e:
        sys.exit(f"study_maps: {path}: cannot read ({e})")
    return meta


def provenance(args, meta):
    """@brief How the maps' data was made, in words (the figures' caption)."""
    ref = meta["reference"]
    return (f"Study {meta['file']}: scene {meta['scene']}, set {' '.join(meta['set'])}; reference "
            f"{ref['method']} {' '.join(ref['set'])}.")


def manifest(args, meta, titles):
    """@brief Writes PREFIX_figures.json: each map's PNG, title, command, scene, version, date and caption.
    @param titles {kind: the figure's title}"""
    made = made_now()
    write_manifest(f"{args.out}_figures.json", f"{meta['study']}: maps over {args.x} x {args.y}",
                   [manifest_figure(os.path.basename(f"{args.out}_{kind}.png"), title, args.command, meta["scene"],
                                    meta["version"], provenance(args, meta), made) for kind, title in titles.items()],
                   about=provenance(args, meta))


def panels(meta, args):
    cases = [c for c in meta["cases"] if c["method"] == args.method]
    for name in (args.x, args.y) + ((args.facet,) if args.facet else ()):
        if not cases or name not in cases[0]["parameters"]:
            sys.exit(f"study_maps: study has no parameter '{name}' (or no case of method '{args.method}')")
    facets = sorted({c["parameters"][args.facet] for c in cases}) if args.facet else [None]
    return cases, facets


def grid(cases, args, value):
    xs = sorted({c["parameters"][args.x] for c in cases})
    ys = sorted({c["parameters"][args.y] for c in cases})
    z = [[math.nan] * len(xs) for _ in ys]
    for c in cases:
        z[ys.index(c["parameters"][args.y])][xs.index(c["parameters"][args.x])] = value(c)
    return xs, ys, z


def edges(v):
    if len(v) == 1:
        return [v[0] - 0.5, v[0] + 0.5]
    mid = [(a + b) / 2 for a, b in zip(v, v[1:])]
    return [v[0] - (mid[0] - v[0])] + mid + [v[-1] + (v[-1] - mid[-1])]


def draw(meta, args, kind):
    cases, facets = panels(meta, args)
    # Constrained layout: every label and the colour bar inside the image, whatever the facets' count.
    fig, axes = plt.subplots(1, len(facets), figsize=(5.2 * len(facets) + 0.8, 4.6), squeeze=False, layout="constrained")
    mappable = None
    for ax, f in zip(axes[0], facets):
        sub = [c for c in cases if f is None or c["parameters"][args.facet] == f]
        if kind == "error":
            def value(c):
                v = c["norms"].get(args.norm)
                return math.log10(v) if v is not None and v > 0 and c["status"] in ("ok", "energy") else math.nan
        else:
            def value(c):
                return STATUS.index(c["status"]) if c["status"] in STATUS else len(STATUS) - 1
        xs, ys, z = grid(sub, args, value)
        if kind == "error":
            mappable = ax.pcolormesh(edges(xs), edges(ys), z, cmap="viridis", shading="flat")
        else:
            cmap = mcolors.ListedColormap(COLOURS)
            mappable = ax.pcolormesh(edges(xs), edges(ys), z, cmap=cmap, vmin=-0.5, vmax=len(STATUS) - 0.5, shading="flat")
            hit = [c for c in sub if c["broke"] and c["status"] == "ok"]
            ax.plot([c["parameters"][args.x] for c in hit], [c["parameters"][args.y] for c in hit], "kx", ms=4)
        ax.set_xlabel(args.x)
        ax.set_ylabel(args.y)
        ax.set_title(f"{args.facet} = {f:g}" if f is not None else meta["study"], fontsize=9)
    if kind == "error":
        fig.colorbar(mappable, ax=axes[0].tolist(), fraction=0.03, label=f"log10 {args.norm} ({args.method} vs {meta['reference']['method']})")
        title = f"{meta['study']}: {args.norm} error of {args.method} against {meta['reference']['method']} (white: no value)"
    else:
        cb = fig.colorbar(mappable, ax=axes[0].tolist(), fraction=0.03, ticks=range(len(STATUS)))
        cb.ax.set_yticklabels(STATUS, fontsize=7)
        rules = " or ".join(f"{r['metric']} > {r['above']:g}" for r in meta["breaks"])
        title = (f"{meta['study']}: stability of {args.method} (energy: created > "
                 f"{meta['energy_growth_bound']:g} E0); x: ok but {rules}")
    fig.suptitle(title, fontsize=10)
    out = f"{args.out}_{kind}.png"
    save_figure_atomic(fig, out, dpi=110)
    plt.close(fig)
    print(f"wrote {out}")
    return title


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("study_dir")
    p.add_argument("--x", required=True)
    p.add_argument("--y", required=True)
    p.add_argument("--facet", default="")
    p.add_argument("--norm", default="impulse")
    p.add_argument("--method", default="paper")
    p.add_argument("--command", default="beamimpact study ...")
    p.add_argument("--out", default="")
    args = p.parse_args()
    args.out = args.out or os.path.join(args.study_dir, "study")
    meta = load(args.study_dir)
    if meta.get("design") != "grid":
        sys.exit("study_maps: maps need a grid design (a Latin hypercube has no grid to colour)")
    if args.norm not in meta["norms"]:
        sys.exit(f"study_maps: '{args.norm}' is not a norm of this study ({', '.join(meta['norms'])})")
    titles = {kind: draw(meta, args, kind) for kind in ("error", "stability")}
    manifest(args, meta, titles)
    print(f"wrote {args.out}_figures.json (how the maps were made: their captions)")


if __name__ == "__main__":
    main()
