#!/usr/bin/env python3
"""Broken copies of the shipped outside solver (examples/external_solver/penalty_central.py) for
the protocol's negative controls: each MODE breaks ONE output rule of docs/protocol.md and keeps
every other, so that `beamimpact conform` must name that rule.

Usage: broken_copy.py MODE SCENE --out DIR [the example's other options]
MODE:
  honest        the example as shipped
  r-x1.5        history.csv's R columns x 1.5, summary.json untouched      (consistency)
  impulse+10    summary.json contacts[].impulse_normal + 10 %              (consistency)
  times         one row's t equal to the row before                        (times)
  nan           one value of history.csv NaN                               (finite)
  incomplete    summary.json "complete": false                             (complete)
  sha           a wrong scene_sha256                                       (scene sha256)
  ms            every time in milliseconds (history and summary), units still saying s (units)
  rod-only      refuses a scene with bending (exit 2, one line), runs the rest as the example
Exit codes are the example's."""
import csv
import io
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "..", "..", "examples", "external_solver", "penalty_central.py")
TIME_KEYS = ("dt", "end_time")  # summary.json's top-level times (s)


def option(args, name):
    return args[args.index(name) + 1] if name in args else ""


def read_history(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in r] for r in rows[1:] if r]


def write_history(path, names, rows):
    out = io.StringIO()
    out.write(",".join(names) + "\n")
    for r in rows:
        out.write(",".join(repr(x) for x in r) + "\n")
    with open(path, "w") as f:
        f.write(out.getvalue())


def edit_summary(path, change):
    with open(path) as f:
        s = json.load(f)
    change(s)
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(s, f, indent=1)
    os.replace(tmp, path)


def needs_bending(args):
    """The model export's effects (what `beamimpact model` builds): 'bending' for frames."""
    with tempfile.TemporaryDirectory() as folder:
        r = subprocess.run([option(args, "--beamimpact"), "model", args[0], "--out", folder, "--quiet"],
                           capture_output=True, text=True)
        if r.returncode != 0:
            return False  # the example itself refuses it with its reason
        with open(os.path.join(folder, "model.json")) as f:
            return "bending" in json.load(f)["effects"]


def to_ms(s):
    for k in TIME_KEYS:
        s[k] *= 1000.0
    for c in s["contacts"]:
        c["intervals"] = [[a * 1000.0, b * 1000.0] for a, b in c["intervals"]]
        c["impulse_normal"] *= 1000.0  # N ms: the same integral over times in ms
        for k in ("interval_impulses",):
            if k in c:
                c[k] = [j * 1000.0 for j in c[k]]


def main():
    mode, args = sys.argv[1], sys.argv[2:]
    if mode == "rod-only" and needs_bending(args):
        print(f"rod-only: {args[0]}: the scene has bending; this method models rods only", file=sys.stderr)
        return 2
    code = subprocess.run([sys.executable, EXAMPLE] + args).returncode
    if code != 0 or mode in ("honest", "rod-only"):
        return code
    out = option(args, "--out")
    hist, summ = os.path.join(out, "history.csv"), os.path.join(out, "summary.json")
    names, rows = read_history(hist)
    if mode == "r-x1.5":
        cols = [i for i, n in enumerate(names) if n == "R" or n.startswith("R_")]
        rows = [[x * 1.5 if i in cols else x for i, x in enumerate(r)] for r in rows]
    elif mode == "times":
        rows[5][0] = rows[4][0]
    elif mode == "nan":
        rows[3][names.index("kinetic")] = math.nan
    elif mode == "ms":
        rows = [[r[0] * 1000.0] + r[1:] for r in rows]
    write_history(hist, names, rows)
    changes = {
        "impulse+10": lambda s: [c.update(impulse_normal=c["impulse_normal"] * 1.1) for c in s["contacts"]],
        "incomplete": lambda s: s.update(complete=False),
        "sha": lambda s: s.update(scene_sha256="0" * 64),
        "ms": to_ms,
    }
    if mode in changes:
        edit_summary(summ, changes[mode])
    elif mode not in ("r-x1.5", "times", "nan"):
        print(f"broken_copy: unknown MODE '{mode}'", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
