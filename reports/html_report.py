#!/usr/bin/env python3
"""@brief Writes one self-contained report.html: the verdicts of a verification run plus the
committed figure sets (work-precision, the paper's figures, benchmarks), every figure embedded
as base64 with the command, scene and version that made it.

Usage: html_report.py --verify DIR [--committed] [--figures DIR ...] --out FILE

--verify DIR   a `beamimpact verify` output directory (its norms.json)
--committed    every committed set of FIGURE_SETS below (reports/NAME), after those of --figures
--figures DIR  a figure set: DIR/figures.json, the manifest its generator wrote:
               {"title", "about", "figures": [{"png", "title", "command", "scene", "version",
               "caption"}], "tables": [{"title", "columns", "rows"}]}
A figure set whose manifest is missing is reported as "not generated" with the command that makes
it, never left out silently. Exit 2 on bad input (a missing norms.json, a manifest without a key).
"""
import argparse
import base64
import html
import json
import os
import sys

# Each committed set, in report order, with the command that regenerates it.
FIGURE_SETS = {
    "work_precision": "/usr/bin/python3 reports/work_precision.py",
    "paper_figures": "/usr/bin/python3 reports/paper_figures.py",
    "benchmarks": "/usr/bin/python3 reports/plot_effects_benchmark.py --run",
    "figures": "build/beamimpact study verification/studies/s4_angle_friction.toml --out DIR; "
               "/usr/bin/python3 reports/study_maps.py DIR (see README)",
}
FIGURE_KEYS = ("png", "title", "command", "scene", "version")

# The browser marks every image it could not decode; the rendering test reads this back.
IMAGE_CHECK_SCRIPT = """
window.addEventListener('load', function () {
  var imgs = document.images, bad = 0;
  for (var i = 0; i < imgs.length; ++i) if (!imgs[i].complete || imgs[i].naturalWidth === 0) ++bad;
  document.body.setAttribute('data-images', String(imgs.length));
  document.body.setAttribute('data-broken-images', String(bad));
});
"""

STYLE = """
body { font-family: sans-serif; max-width: 1100px; margin: 1em auto; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1em; font-size: 0.85em; }
td, th { border: 1px solid #bbb; padding: 2px 6px; text-align: left; }
.pass { background: #dfd; } .fail { background: #fcc; } .skipped { background: #ffd; }
figure { margin: 1em 0; border-top: 1px solid #ddd; padding-top: 0.5em; }
figure img { max-width: 100%; }
figcaption { font-size: 0.85em; } code { font-size: 0.9em; }
.made { color: #555; font-family: monospace; font-size: 0.8em; }
"""


def fail(msg):
    print(f"html_report: {msg}", file=sys.stderr)
    sys.exit(2)


def esc(x):
    return html.escape(str(x))


def load_json(path, what):
    try:
        with open(path) as f:
            return json.load(f)
    except FileNotFoundError:
        fail(f"{path}: not found ({what})")
    except json.JSONDecodeError as e:
        fail(f"{path}: not valid JSON ({e})")


def table(columns, rows, row_class=None):
    out = ["<table><tr>" + "".join(f"<th>{esc(c)}</th>" for c in columns) + "</tr>"]
    for i, r in enumerate(rows):
        cls = f' class="{row_class[i]}"' if row_class else ""
        out.append(f"<tr{cls}>" + "".join(f"<td>{esc(v)}</td>" for v in r) + "</tr>")
    return "\n".join(out) + "</table>"


def verify_section(verify_dir):
    norms = load_json(os.path.join(verify_dir, "norms.json"), "the verification run's results")
    for k in ("command", "version", "tier", "verdict", "gates", "passed", "failed", "skipped", "items"):
        if k not in norms:
            fail(f"{verify_dir}/norms.json: key '{k}' missing (expected a `beamimpact verify` norms.json)")
    verdict = norms["verdict"]  # the library's one pass rule (verification_passed), not decided here
    parts = [f"<p><b>{verdict}</b>: {norms['gates']} gates, {norms['passed']} passed, "
             f"{norms['failed']} failed, {norms['skipped']} skipped"
             + ("" if norms.get("complete", True) else f" (INCOMPLETE: {esc(norms.get('incomplete', ''))})")
             + "</p>",
             f"<p class=made>command: {esc(norms['command'])}<br>tier: {esc(norms['tier'])}, "
             f"version: {esc(norms['version'])}, started {esc(norms.get('started_utc', '?'))} UTC, "
             f"wall {norms.get('wall_seconds', 0):.1f} s</p>"]
    rows, classes = [], []
    for it in norms["items"]:
        for g in it.get("gates", []):
            v = g.get("value")
            rows.append([it["scene"], it["settings"] or it["name"], it.get("reference", ""), g["metric"],
                         "n/a" if v is None else f"{v:.4g}", g.get("limit", ""), g["status"]
                         + (f": {g['message']}" if g["status"] != "pass" and g.get("message") else "")])
            classes.append(g["status"] if g["status"] in ("pass", "fail", "skipped") else "")
    if not rows:
        fail(f"{verify_dir}/norms.json: no gate in 'items' (an empty verification run)")
    parts.append(table(["scene", "run", "reference", "norm", "value", "limit", "verdict"], rows, classes))
    return "Verification matrix", "".join(parts)


def figure_html(set_dir, fig):
    for k in FIGURE_KEYS:
        if k not in fig:
            fail(f"{set_dir}/figures.json: a figure lacks '{k}' (each figure needs {', '.join(FIGURE_KEYS)})")
    path = os.path.join(set_dir, fig["png"])
    try:
        with open(path, "rb") as f:
            data = base64.b64encode(f.read()).decode("ascii")
    except FileNotFoundError:
        fail(f"{set_dir}/figures.json: figure '{fig['png']}' not found")
    return (f"<figure><h3>{esc(fig['title'])}</h3><img alt=\"{esc(fig['title'])}\" "
            f"src=\"data:image/png;base64,{data}\"><figcaption>{esc(fig.get('caption', ''))}"
            f"<div class=made>command: {esc(fig['command'])}<br>scene: {esc(fig['scene'])}<br>"
            f"version: beamimpact {esc(fig['version'])}</div></figcaption></figure>")


def figure_set_section(set_dir):
    name = os.path.basename(os.path.normpath(set_dir))
    manifest = os.path.join(set_dir, "figures.json")
    if not os.path.exists(manifest):
        cmd = FIGURE_SETS.get(name, "its generator")
        return name, f"<p>Not generated in this checkout: run <code>{esc(cmd)}</code>.</p>"
    m = load_json(manifest, "a figure set's manifest")
    for k in ("title", "figures"):
        if k not in m:
            fail(f"{manifest}: key '{k}' missing")
    parts = [f"<p>{esc(m.get('about', ''))}</p>"]
    for t in m.get("tables", []):
        parts.append(f"<h3>{esc(t['title'])}</h3>" + table(t["columns"], t["rows"]))
    parts += [figure_html(set_dir, f) for f in m["figures"]]
    return m["title"], "".join(parts)


def write(args):
    here = os.path.dirname(os.path.abspath(__file__))
    if args.committed:
        args.figures += [os.path.join(here, name) for name in FIGURE_SETS]
    sections = [verify_section(args.verify)] + [figure_set_section(d) for d in args.figures]
    body = "".join(f"<section id=\"s{i}\"><h2>{esc(t)}</h2>{c}</section>\n" for i, (t, c) in enumerate(sections))
    toc = "".join(f"<li><a href=\"#s{i}\">{esc(t)}</a></li>" for i, (t, _) in enumerate(sections))
    page = (f"<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>beamimpact report</title>"
            f"<style>{STYLE}</style><script>{IMAGE_CHECK_SCRIPT}</script></head><body>"
            f"<h1>beamimpact: verification and what accuracy costs</h1><ul>{toc}</ul>\n{body}</body></html>\n")
    tmp = args.out + ".tmp"
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(tmp, "w") as f:
        f.write(page)
    os.replace(tmp, args.out)  # never a half-written report
    print(f"report: {args.out}")


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--verify", required=True)
    p.add_argument("--figures", action="append", default=[])
    p.add_argument("--committed", action="store_true",
                   help="add every committed set of FIGURE_SETS (reports/NAME), in report order")
    p.add_argument("--out", required=True)
    write(p.parse_args())
