#!/usr/bin/env python3
"""Runs every shipped scene with two `beamimpact` binaries and compares what they write.

Usage: compare_scene_histories.py OLD_BINARY NEW_BINARY OUT_DIR [--mult 1 4]

Each scene of verification/scenes/*/*.toml runs with `time.dt = "auto"` at its mesh and at each
multiple of its bodies' elements given after --mult (default 1 and 4), once per binary, into
OUT_DIR/{old,new}/SCENE_xMULT. One line per run: the critical step's bound in each version, the
relative change of `critical_dt`, and whether history.csv is byte-identical; if not, the largest
difference of any column relative to that column's largest magnitude. A run that fails in either
version prints both exit codes. Exit status 0 unless a binary is missing.
"""
import csv
import json
import pathlib
import subprocess
import sys
import tomllib

ROOT = pathlib.Path(__file__).resolve().parents[2]


def run(binary, scene, sets, out):
    cmd = [binary, "run", str(scene), "--out", str(out), "--quiet", "--allow-long"]
    for s in sets:
        cmd += ["--set", s]
    return subprocess.run(cmd, capture_output=True, text=True).returncode


def column_difference(a_rows, b_rows):
    """Largest |a - b| / max|a| over the numeric columns (time excluded)."""
    worst = 0.0
    for c in range(1, len(a_rows[0])):
        try:
            a = [float(r[c]) for r in a_rows[1:]]
            b = [float(r[c]) for r in b_rows[1:]]
        except ValueError:
            continue
        scale = max(max((abs(x) for x in a), default=0.0), 1e-300)
        worst = max(worst, max((abs(x - y) for x, y in zip(a, b)), default=0.0) / scale)
    return worst


def main():
    args = sys.argv[1:]
    mults = [1, 4]
    if "--mult" in args:
        i = args.index("--mult")
        mults = [int(m) for m in args[i + 1:]]
        args = args[:i]
    if len(args) != 3:
        sys.exit(__doc__)
    old, new, out = args[0], args[1], pathlib.Path(args[2])
    for b in (old, new):
        if not pathlib.Path(b).is_file():
            sys.exit(f"compare_scene_histories: no binary {b}")
    for scene in sorted((ROOT / "verification/scenes").glob("*/*.toml")):
        bodies = tomllib.loads(scene.read_text()).get("bodies", [])
        for mult in mults:
            sets = ['time.dt="auto"']
            if mult != 1:
                sets += [f"bodies.{b['name']}.elements={b['elements'] * mult}" for b in bodies if "elements" in b]
            dirs = {tag: out / tag / f"{scene.stem}_x{mult}" for tag in ("old", "new")}
            rc = {tag: run(binary, scene, sets, dirs[tag]) for tag, binary in (("old", old), ("new", new))}
            if rc["old"] or rc["new"]:
                print(f"{scene.stem} x{mult}: exit {rc['old']} (old) {rc['new']} (new)")
                continue
            a, b = (json.loads((dirs[t] / "summary.json").read_text()) for t in ("old", "new"))
            dt_change = abs(b["critical_dt"] / a["critical_dt"] - 1) if a.get("critical_dt") else 0.0
            ha, hb = ((dirs[t] / "history.csv").read_bytes() for t in ("old", "new"))
            if ha == hb:
                hist = "history identical"
            else:
                ra, rb = (list(csv.reader(x.decode().splitlines())) for x in (ha, hb))
                hist = (f"rows {len(ra)} vs {len(rb)}" if len(ra) != len(rb)
                        else f"history differs, largest {column_difference(ra, rb):.2e} of a column's magnitude")
            bounds = f"{a.get('critical_step', {}).get('bound')} -> {b.get('critical_step', {}).get('bound')}"
            print(f"{scene.stem} x{mult}: bound {bounds}, critical_dt change {dt_change:.2e}, {hist}")


if __name__ == "__main__":
    main()
