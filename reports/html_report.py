#!/usr/bin/env python3
"""@brief Writes one self-contained report.html that answers at a glance: first a scorecard of the
verification run (scenes by methods, each cell coloured by its worst gate's margin, failures
first), then every gate grouped by scene (collapsible; failing groups open and first), then the
committed figure sets (work-precision, the paper's figures, benchmarks), every figure embedded as
base64 with the command, scene and version that made it.

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

from report_files import write_text_atomic

# Each committed set, in report order, with the command that regenerates it.
FIGURE_SETS = {
    "work_precision": "/usr/bin/python3 reports/work_precision.py",
    "paper_figures": "/usr/bin/python3 reports/paper_figures.py",
    "scorecards": "build/beamimpact score NAME --out /tmp/scores/NAME for each method; "
                  "/usr/bin/python3 reports/scorecard_table.py /tmp/scores/* --set reports/scorecards",
    "classical_benchmarks": "/usr/bin/python3 reports/classical_benchmarks.py",
    "beam_theories": "/usr/bin/python3 reports/beam_theories.py",
    "benchmarks": "/usr/bin/python3 reports/plot_effects_benchmark.py --run",
    "setup": "/usr/bin/python3 reports/plot_setup_benchmark.py --run",
    "figures": "build/beamimpact study verification/studies/s4_angle_friction.toml --out DIR; "
               "/usr/bin/python3 reports/study_maps.py DIR (see README)",
}
FIGURE_KEYS = ("png", "title", "command", "scene", "version")

# The browser marks every image it could not decode, and where the scorecard and its first row
# are on the first screen; the rendering test (check_report.py) reads these back.
IMAGE_CHECK_SCRIPT = """
window.addEventListener('load', function () {
  var imgs = document.images, bad = 0;
  for (var i = 0; i < imgs.length; ++i) if (!imgs[i].complete || imgs[i].naturalWidth === 0) ++bad;
  document.body.setAttribute('data-images', String(imgs.length));
  document.body.setAttribute('data-broken-images', String(bad));
  var card = document.getElementById('scorecard');
  var row = card ? card.querySelector('tbody tr') : null;
  document.body.setAttribute('data-scorecard-top', card ? String(Math.round(card.getBoundingClientRect().top)) : 'none');
  document.body.setAttribute('data-first-row', row ? row.getAttribute('data-status') : 'none');
});
"""
# Margin = a gate's value over its limit (1 = at the limit); cell colours by the worst margin.
MARGIN_CLOSE, MARGIN_NEAR = 0.5, 0.9

STYLE = """
body { font-family: sans-serif; max-width: 1100px; margin: 1em auto; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1em; font-size: 0.85em; }
td, th { border: 1px solid #bbb; padding: 2px 6px; text-align: left; }
.pass { background: #dfd; } .fail { background: #fcc; } .skipped { background: #ffd; }
.m-ok { background: #9d9; } .m-close { background: #dfa; } .m-near { background: #fc7; }
.m-fail { background: #f77; font-weight: bold; } .m-skip { background: #ffd; } .m-none { background: #eee; }
table.scorecard td { text-align: center; min-width: 5em; } table.scorecard a { color: inherit; } table.scorecard td.scene { text-align: left; }
.nav { font-size: 0.85em; } .legend span { padding: 1px 6px; margin-right: 4px; font-size: 0.85em; }
details { margin: 0.2em 0; } summary { cursor: pointer; padding: 2px 4px; }
summary.fail { background: #fcc; font-weight: bold; } summary.pass { background: #efe; }
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


def gate_margin(g):
    """A gate's value over its limit (<= 1 passes; None when the gate gives no number): the
    `margin` verify wrote (the library's rule), else, for an older norms.json, the same rule
    from the gate's kind: a tolerance (value / tol), a minimum observed order (min_order / order)
    or a Richardson check (value in units of E_R over the allowed multiple)."""
    if "margin" in g:
        return g["margin"]
    v = g.get("value")
    if v is None:
        return None
    if g.get("richardson") is not None:
        return v / g["richardson"] if g["richardson"] > 0 else None
    if g.get("min_order") is not None:
        return g["min_order"] / v if v > 0 else float("inf")
    if g.get("tol") is not None:
        return v / g["tol"] if g["tol"] > 0 else (0.0 if v == 0 else float("inf"))
    return None


def gate_failed(g):
    """The run's own verdict: `passed` when it wrote one, else the gate's status."""
    return not g["passed"] if "passed" in g else g["status"] == "fail"


def item_method(it):
    """The method an item ran: the word after the scene in its name ("s1_central paper dt=0.01 vs
    exact" -> paper; "s1_central/paper" -> paper)."""
    name = it.get("name", "")
    if name.startswith(it.get("scene", "")):
        name = name[len(it.get("scene", "")):]
    words = name.replace("/", " ", 1).split()
    return words[0] if words else "?"


def worst(gates):
    """(css class, label, sort key) of a group of gates: failed first, then skipped, then by margin."""
    if any(gate_failed(g) for g in gates):
        bad = [m for m in (gate_margin(g) for g in gates if gate_failed(g)) if m is not None]
        label = f"FAIL {max(bad):.3g}" if bad and max(bad) != float("inf") else "FAIL"
        return "m-fail", label, (0, -max(bad, default=0.0))
    if any(g["status"] == "skipped" for g in gates):
        return "m-skip", "skipped", (1, 0.0)
    margins = [m for m in (gate_margin(g) for g in gates) if m is not None]
    if not margins:
        return "m-none", "pass", (3, 0.0)
    m = max(margins)
    cls = "m-ok" if m < MARGIN_CLOSE else "m-close" if m < MARGIN_NEAR else "m-near"
    return cls, f"{m:.2f}", (2, -m)


def scorecard(norms):
    """Scenes by methods; each cell the worst gate margin of that scene's items with that method."""
    cells, methods = {}, []
    for it in norms["items"]:
        method = item_method(it)
        if method not in methods:
            methods.append(method)
        cells.setdefault(it["scene"], {}).setdefault(method, []).extend(it.get("gates", []))
    rows = []
    for scene, by_method in cells.items():
        every = [g for gs in by_method.values() for g in gs]
        if every:
            rows.append((worst(every)[2], scene, by_method))
    rows.sort(key=lambda r: (r[0], r[1]))
    failed = sum(gate_failed(g) for it in norms["items"] for g in it.get("gates", []))
    out = [f"<table class=scorecard id=scorecard data-failed={failed}><thead><tr><th>scene</th>"
           + "".join(f"<th>{esc(m)}</th>" for m in methods) + "</tr></thead><tbody>"]
    for _, scene, by_method in rows:
        status = "fail" if any(gate_failed(g) for gs in by_method.values() for g in gs) else "pass"
        tds = []
        for m in methods:
            gates = by_method.get(m, [])
            if not gates:
                tds.append("<td></td>")
                continue
            cls, label, _ = worst(gates)
            tds.append(f"<td class={cls} title=\"{len(gates)} gates\"><a href=\"#scene-{esc(scene)}\">{esc(label)}</a></td>")
        out.append(f"<tr data-status={status}><td class=scene>{esc(scene)}</td>{''.join(tds)}</tr>")
    out.append("</tbody></table>")
    legend = ("<p class=legend>worst gate margin (value / limit): "
              f"<span class=m-ok>&lt; {MARGIN_CLOSE}</span><span class=m-close>&lt; {MARGIN_NEAR}</span>"
              "<span class=m-near>&le; 1</span><span class=m-fail>failed</span><span class=m-skip>skipped</span>"
              "<span class=m-none>pass, no number</span></p>")
    return "".join(out) + legend


def load_norms(verify_dir):
    norms = load_json(os.path.join(verify_dir, "norms.json"), "the verification run's results")
    for k in ("command", "version", "tier", "verdict", "gates", "passed", "failed", "skipped", "items"):
        if k not in norms:
            fail(f"{verify_dir}/norms.json: key '{k}' missing (expected a `beamimpact verify` norms.json)")
    if not any(it.get("gates") for it in norms["items"]):
        fail(f"{verify_dir}/norms.json: no gate in 'items' (an empty verification run)")
    return norms


def scorecard_section(verify_dir, norms):
    verdict = norms["verdict"]  # the library's one pass rule (verification_passed), not decided here
    parts = [f"<p><b>{verdict}</b>: {norms['gates']} gates, {norms['passed']} passed, "
             f"{norms['failed']} failed, {norms['skipped']} skipped"
             + ("" if norms.get("complete", True) else f" (INCOMPLETE: {esc(norms.get('incomplete', ''))})")
             + "</p>", scorecard(norms),
             f"<p class=made>command: {esc(norms['command'])}<br>tier: {esc(norms['tier'])}, "
             f"version: {esc(norms['version'])}, started {esc(norms.get('started_utc', '?'))} UTC, "
             f"wall {norms.get('wall_seconds', 0):.1f} s</p>"]
    return "Scorecard", "".join(parts)


def gates_section(norms):
    """Every gate, grouped by scene (failing scenes first and open), each with value, limit, margin."""
    groups = {}
    for it in norms["items"]:
        for g in it.get("gates", []):
            groups.setdefault(it["scene"], []).append((it, g))
    order = sorted(groups, key=lambda sc: (worst([g for _, g in groups[sc]])[2], sc))
    parts = []
    for scene in order:
        rows, classes = [], []
        for it, g in groups[scene]:
            v, m = g.get("value"), gate_margin(g)
            rows.append([it["settings"] or it["name"], it.get("reference", ""), g["metric"],
                         "n/a" if v is None else f"{v:.4g}", g.get("limit", ""),
                         "" if m is None else f"{m:.3g}", g["status"]
                         + (f": {g['message']}" if g["status"] != "pass" and g.get("message") else "")])
            classes.append(g["status"] if g["status"] in ("pass", "fail", "skipped") else "")
        failed = sum(gate_failed(g) for _, g in groups[scene])
        cls = "fail" if failed else "pass"
        head = f"{esc(scene)}: {len(rows)} gates" + (f", {failed} failed" if failed else "")
        parts.append(f"<details id=\"scene-{esc(scene)}\"{' open' if failed else ''}><summary class={cls}>{head}"
                     f"</summary>{table(['run', 'reference', 'norm', 'value', 'limit', 'margin', 'verdict'], rows, classes)}"
                     "</details>")
    return "Gates by scene", "".join(parts)


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
    norms = load_norms(args.verify)
    sections = ([scorecard_section(args.verify, norms), gates_section(norms)]
                + [figure_set_section(d) for d in args.figures])
    body = "".join(f"<section id=\"s{i}\"><h2>{esc(t)}</h2>{c}</section>\n" for i, (t, c) in enumerate(sections))
    toc = " | ".join(f"<a href=\"#s{i}\">{esc(t)}</a>" for i, (t, _) in enumerate(sections))
    page = (f"<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>beamimpact report</title>"
            f"<style>{STYLE}</style><script>{IMAGE_CHECK_SCRIPT}</script></head><body>"
            f"<h1>beamimpact: verification and what accuracy costs</h1><p class=nav>{toc}</p>\n{body}"
            "</body></html>\n")
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    write_text_atomic(args.out, page)  # never a half-written report
    print(f"report: {args.out}")


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--verify", required=True)
    p.add_argument("--figures", action="append", default=[])
    p.add_argument("--committed", action="store_true",
                   help="add every committed set of FIGURE_SETS (reports/NAME), in report order")
    p.add_argument("--out", required=True)
    write(p.parse_args())
