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
import shutil
import sys

from report_files import write_json_atomic, write_text_atomic


from scorecard_figures import figure

HERE = os.path.dirname(os.path.abspath(__file__))
HEADER = """# Scorecards of the shipped methods

Each method run on the benchmark set (the paper's scenes, the hard scenes and every scene with an
exact answer) and compared with the best reference of each scene under the verification
matrix's tolerance for that scene (docs/protocol.md, `beamimpact score`). `fail` means an error
above the tolerance the matrix holds for that scene's reference (the tolerances are the paper
integrator's unless the method has its own case: a 2D continuum or a penalty code is judged by
the beam model's bounds, which is the point of a common scorecard); `no tolerance`: the matrix
has no case for the scene, the error is reported; `not applicable`: the method refused the
scene (exit 2 with its reason). Where a scene has no exact answer the reference is IDA
converged beyond its defaults (rtol 1e-10, atol 1e-13, friction regularised at 1e-5 m/s, penalty
1e4 EA/le, added to the matrix case's own IDA settings; `ida, converged` in the table): IDA is
never scored against its own run, and IDA's row shows how far its defaults are from converged.
Such a reference carries its own uncertainty, `± spread`: its difference from the same run at
the case's penalty (1e3 EA/le). A verdict that the spread could reverse (|error - tol| below the
spread) is `reference uncertain`: the reference cannot decide at that tolerance; `skipped`: the
reference did not finish within `--timeout` (its reason in scorecard.json). Made with:

```sh
build/beamimpact score paper ida fenicsx siconos example --out /tmp/scores --jobs 2 --timeout 3600
for m in paper ida fenicsx siconos example; do
  /usr/bin/python3 reports/scorecard_figures.py /tmp/scores/$m     # the diagrams, figures.json, scorecard.html again
done
/usr/bin/python3 reports/scorecard_table.py /tmp/scores/{paper,ida,fenicsx,siconos,example} --set reports/scorecards
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
    if scene["status"] != "ok":
        return scene["status"]
    for q in scene["quantities"]:
        if q["metric"] == "impulse":
            err = "n/a" if q["error"] is None else f"{q['error']:.2g}"
            spread = q.get("reference_spread")
            err += "" if spread is None else f" ± {spread:.2g}"
            return f"{err} ({q['status']})"
    return "no impulse gate"


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


def write_set(out, dirs, cards, text):
    os.makedirs(out, exist_ok=True)
    for d, c in zip(dirs, cards):
        os.makedirs(os.path.join(out, c["method"]), exist_ok=True)
        shutil.copyfile(os.path.join(d, "scorecard.json"), os.path.join(out, c["method"], "scorecard.json"))
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
        figures.append({"png": png, "title": f"{s['scene']}: every scored method on the work-precision diagram",
                        "caption": caption, "command": COMMAND, "scene": s["file"], "version": cards[0]["version"]})
    (cols1, rows1), (cols2, rows2) = tables(cards)
    manifest = {"title": "Scorecards: every method on the benchmark set",
                "about": "Each method run on the paper's scenes, the hard scenes and every scene with an exact "
                         "answer, compared with the best reference of each scene under the verification matrix's "
                         "tolerance (beamimpact score; docs/protocol.md).",
                "tables": [{"title": "Verdicts per method", "columns": cols1, "rows": rows1},
                           {"title": "Relative impulse error (verdict)", "columns": cols2, "rows": rows2}],
                "figures": figures}
    write_json_atomic(os.path.join(out, "figures.json"), manifest)
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
    text = (provenance(cards) + "\n\n" + markdown(cols1, rows1) + "\n\nRelative impulse error against the scene's best reference "
            "(verdict under the matrix's tolerance for that scene):\n\n" + markdown(cols2, rows2) + "\n")
    print(text, end="")
    if args.set:
        write_set(args.set, args.dirs, cards, text)


if __name__ == "__main__":
    main(sys.argv[1:])
