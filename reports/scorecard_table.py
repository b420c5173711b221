#!/usr/bin/env python3
"""@brief One Markdown table from several scorecards (`beamimpact score NAME --out DIR`): per
method, the count of each status, and per scene its impulse error and verdict for each method.

Usage: scorecard_table.py DIR [DIR ...] > scorecards.md
Exit 2 with one line when a DIR holds no scorecard.json.
"""
import json
import os
import sys


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
            return f"{err} ({q['status']})"
    return "no impulse gate"


def main(dirs):
    if not dirs:
        print("scorecard_table: expected one or more scorecard folders", file=sys.stderr)
        sys.exit(2)
    cards = [load(d) for d in dirs]
    names = [c["method"] for c in cards]
    print(f"Scorecards of version {cards[0]['version']}, made {cards[0]['made']} UTC "
          f"(`beamimpact score NAME`; command of the first: `{cards[0]['command']}`).\n")
    statuses = sorted({s for c in cards for s in c["counts"]})
    print("| method | " + " | ".join(statuses) + " |")
    print("|---|" + "---|" * len(statuses))
    for c in cards:
        print(f"| {c['method']} | " + " | ".join(str(c["counts"].get(s, 0)) for s in statuses) + " |")
    print("\nRelative impulse error against the scene's best reference (verdict under the matrix's "
          "tolerance for that scene):\n")
    print("| scene | reference | " + " | ".join(names) + " |")
    print("|---|---|" + "---|" * len(names))
    by_scene = [{s["scene"]: s for s in c["scenes"]} for c in cards]
    for s in cards[0]["scenes"]:
        row = [cell(m[s["scene"]]) if s["scene"] in m else "-" for m in by_scene]
        print(f"| {s['scene']} | {s['reference']} | " + " | ".join(row) + " |")


if __name__ == "__main__":
    main(sys.argv[1:])
