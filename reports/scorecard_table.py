#!/usr/bin/env python3
"""@brief Several scorecards (`beamimpact score NAME --out DIR`) side by side: per method the
count of each status, and per scene its impulse error and verdict for each method.

Usage: scorecard_table.py DIR [DIR ...] [--set OUT]
Prints the tables as Markdown. With --set OUT, also writes OUT/scorecards.md, the figure set the
HTML report reads (OUT/figures.json: both tables, and for each scene with a work-precision set
one diagram with every method's scored run on it, OUT/<scene>.png) and each scorecard.json under
OUT/<method>/. Exit 2 with one line when a DIR holds no scorecard.json.
"""
import argparse
import json
import os
import sys

from figure_sets import manifest_figure, write_manifest
from report_files import write_json_atomic, write_text_atomic


from scorecard_figures import figure

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
HEADER = """# Scorecards of the shipped methods

Each method run by `beamimpact score` on the benchmark set (the paper's scenes, the hard scenes and
every scene with an exact answer), each scene judged under its benchmark card
([docs/benchmark-cards.md](../../docs/benchmark-cards.md)): one reference and one tolerance per
quantity, the same for every method, whoever runs it. Quantities are computed from each run's own
`history.csv` (summary.json only for what a history cannot show). Where the scene has an exact
answer the method runs a ladder of three resolutions (mesh and step halved a rung) and the
quantity's Richardson limit is judged against the exact value (`limit`: pass within 1.25 x the
limit's uncertainty + tol / 10), so a bias cannot hide in the discretisation error; a ladder whose
differences do not shrink (observed order below 0.5) is `not converged`. Elsewhere the reference
is IDA converged beyond its defaults (rtol 1e-10, atol 1e-13, friction regularised at 1e-5 m/s,
penalty 1e4 EA/le), with its own uncertainty (`± spread`: its difference from the same IDA run at
the penalty of 1e3 EA/le); a verdict the spread could reverse is `reference uncertain`. Where a
card carries a settled value (S4's impulse: [docs/s4.md](../../docs/s4.md)), the quantity is judged
against it and its uncertainty takes the place of the spread. IDA is
never its own reference: on the scenes without an exact answer its row shows how far its defaults
are from converged. `not applicable`: the method refused the scene (exit 2 with its reason);
`skipped`: the run or its reference did not finish within `--timeout`. The rules are in
[docs/protocol.md](../../docs/protocol.md). Made with (about an hour on two cores, most of it
IDA's converged references and FEniCSx):

```sh
build/beamimpact score paper ida fenicsx siconos example getfem --out out/scores --cache out/ref-cache --jobs 2 --timeout 3600
for m in paper ida fenicsx siconos example getfem; do
  /usr/bin/python3 reports/scorecard_figures.py out/scores/$m     # the diagrams, figures.json, scorecard.html again
done
/usr/bin/python3 reports/scorecard_table.py out/scores/{paper,ida,fenicsx,siconos,example,getfem} --set reports/scorecards
```

"""
COMMAND = "/usr/bin/python3 reports/scorecard_table.py DIR... --set reports/scorecards (docs/protocol.md)"


def load(d):
    path = os.path.join(d, "scorecard.json")
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        print(f"scorecard_table: {path}: expected a scorecard (beamimpact score) ({e})", file=sys.stderr)
        sys.exit(2)


def cell(scene):
    """The scene's impulse error and verdict, and how many of its other quantities fail."""
    if scene["status"] != "ok":
        return scene["status"]
    qs = scene["quantities"]
    bad = [q for q in qs if q["status"] not in ("pass", "not applicable")]
    text = "no impulse on its card"
    for q in qs:
        if q["metric"] == "impulse":
            err = "n/a" if q["error"] is None else f"{q['error']:.2g}"
            unc = q.get("uncertainty")
            err += "" if not unc else f" ± {unc:.2g}"
            how = "limit " if q.get("judged") == "limit" else ""
            text = f"{how}{err} ({q['status']})"
    others = [q for q in bad if q["metric"] != "impulse"]
    if others:
        text += f"; {len(others)} of {len(qs) - 1} other(s) " + ", ".join(sorted({q['status'] for q in others}))
    return text


def reference(card, scene):
    """The scene's reference kind, and for IDA whether it was converged (`score --references`)."""
    kind = scene.get("reference_kind", scene["reference"])
    if kind == "ida" and card.get("references", "matrix") == "converged":
        return "ida, converged"
    return kind


def tables(cards):
    """(columns, rows) of the counts and of the per-scene impulse errors."""
    statuses = sorted({s for c in cards for s in c["counts"]})
    counts = (["method"] + statuses, [[c["method"]] + [c["counts"].get(s, 0) for s in statuses] for c in cards])
    by_scene = [{s["scene"]: s for s in c["scenes"]} for c in cards]
    rows = [[s["scene"], reference(cards[0], s)] + [cell(m[s["scene"]]) if s["scene"] in m else "-" for m in by_scene]
            for s in cards[0]["scenes"]]
    return counts, (["scene", "reference"] + [c["method"] for c in cards], rows)


def markdown(columns, rows):
    lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    return "\n".join(lines + ["| " + " | ".join(str(x) for x in r) + " |" for r in rows])


def relative(obj, root):
    """@brief `obj` with every absolute path under `root` written relative to it (the messages of
    refused runs name the scene file as the program saw it): a committed scorecard names no folder
    of the machine that made it (tools/check-paths.sh)."""
    if isinstance(obj, str):
        return obj.replace(root + os.sep, "")
    if isinstance(obj, list):
        return [relative(x, root) for x in obj]
    if isinstance(obj, dict):
        return {k: relative(v, root) for k, v in obj.items()}
    return obj


def write_set(out, dirs, cards, text):
    os.makedirs(out, exist_ok=True)
    for d, c in zip(dirs, cards):
        os.makedirs(os.path.join(out, c["method"]), exist_ok=True)
        write_json_atomic(os.path.join(out, c["method"], "scorecard.json"), relative(c, ROOT))
    figures = []
    for s in cards[0]["scenes"]:
        wp_path = os.path.join(HERE, "work_precision", s["scene"], "work_precision.json")
        if not os.path.isfile(wp_path):
            continue
        with open(wp_path) as f:
            wp = json.load(f)
        marks = [(c["method"], e) for c in cards for e in c["scenes"] if e["scene"] == s["scene"]]
        png = f"{s['scene']}.png"
        caption = figure(s["scene"], wp, marks, os.path.join(out, png))
        figures.append(manifest_figure(png, f"{s['scene']}: every scored method on the work-precision diagram",
                                       COMMAND, s["file"], cards[0]["version"], caption))
    (cols1, rows1), (cols2, rows2) = tables(cards)
    write_manifest(os.path.join(out, "figures.json"), "Scorecards: every method on the benchmark set", figures,
                   about="Each method run on the paper's scenes, the hard scenes and every scene with an exact "
                         "answer, each scene judged under its benchmark card: one reference and one tolerance per "
                         "quantity for every method, ladders and Richardson limits where the answer is exact "
                         "(beamimpact score; docs/benchmark-cards.md, docs/protocol.md).",
                   tables=[{"title": "Verdicts per method", "columns": cols1, "rows": rows1},
                           {"title": "Relative impulse error (verdict)", "columns": cols2, "rows": rows2}])
    write_text_atomic(os.path.join(out, "scorecards.md"), HEADER + text)


def provenance(cards):
    """One line saying how the scorecards were made: one version, or each method's own."""
    if len({c["version"] for c in cards}) == 1:
        return (f"Scorecards of version {cards[0]['version']}, made {cards[0]['made']} UTC "
                f"(`beamimpact score NAME`; command of the first: `{cards[0]['command']}`).")
    each = "; ".join(f"{c['method']}: {c['version']}, made {c['made']} UTC" for c in cards)
    return f"Scorecards made with `beamimpact score NAME` by different versions ({each})."


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dirs", nargs="+", help="scorecard folders (beamimpact score --out DIR)")
    ap.add_argument("--set", help="write the figure set (scorecards.md, figures.json, diagrams) here")
    args = ap.parse_args(argv)
    cards = [load(d) for d in args.dirs]
    (cols1, rows1), (cols2, rows2) = tables(cards)
    text = (provenance(cards) + "\n\nQuantities of each status, per method:\n\n" + markdown(cols1, rows1)
            + "\n\nRelative impulse error against the scene's card reference (`limit`: the ladder's Richardson "
            "limit against the exact value, ± its uncertainty; otherwise the run against converged IDA, ± the "
            "reference's spread), its verdict, and the scene's other quantities that do not pass:\n\n"
            + markdown(cols2, rows2) + "\n")
    print(text, end="")
    if args.set:
        write_set(args.set, args.dirs, cards, text)


if __name__ == "__main__":
    main(sys.argv[1:])
