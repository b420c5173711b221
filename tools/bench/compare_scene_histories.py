#!/usr/bin/env python3
"""Runs every shipped scene with two `beamimpact` binaries and compares what they write.

Usage: compare_scene_histories.py OLD_BINARY NEW_BINARY OUT_DIR [--mult 1 4]

Each scene of verification/scenes/*/*.toml runs with `time.dt = "auto"` at its mesh and at each
multiple of its bodies' elements given after --mult (default 1 and 4), once per binary, into
OUT_DIR/{old,new}/SCENE_xMULT. One line per run: the critical step's bound in each version, the
relative change of `critical_dt`, and whether history.csv is byte-identical; if not, the largest
`*.rel_linf` norm of `NEW_BINARY compare` (new run against old, on a common time grid, so runs
whose steps differ compare too) and the largest relative change of a summary.json number
(`compare_norms.leaves`, timings left out). A run that fails in either version prints both exit
codes. Exit status 0 unless a binary is missing.
"""
import json
import pathlib
import subprocess
import sys
import tomllib

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from compare_norms import leaves  # noqa: E402  (every number of a JSON tree, timings left out)


def run(binary, scene, sets, out):
    cmd = [binary, "run", str(scene), "--out", str(out), "--quiet", "--allow-long"]
    for s in sets:
        cmd += ["--set", s]
    return subprocess.run(cmd, capture_output=True, text=True).returncode


def largest_rel_linf(binary, run_dir, reference_dir):
    """The largest max_t |a-b| / max_t |b| norm of `beamimpact compare` (None when it fails)."""
    out = run_dir / "compare_old.json"
    r = subprocess.run([binary, "compare", str(run_dir), str(reference_dir), "--json", str(out)],
                       capture_output=True, text=True)
    if r.returncode != 0:
        return None
    norms = json.loads(out.read_text())["norms"]
    # A norm compare cannot form (a reference column of zeros) is null: left out.
    return max((n["value"] for n in norms if n["name"].endswith(".rel_linf") and n["value"] is not None),
               default=0.0)


def largest_summary_change(a, b):
    """Largest relative change of a number present in both summary.json trees, and its path."""
    old = dict(leaves(a))
    worst = (0.0, "")
    for path, v in leaves(b):
        if path in old and v != old[path]:
            worst = max(worst, (abs(v - old[path]) / max(abs(old[path]), 1e-300), path))
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
            if (dirs["old"] / "history.csv").read_bytes() == (dirs["new"] / "history.csv").read_bytes():
                hist = "history identical"
            else:
                linf = largest_rel_linf(new, dirs["new"], dirs["old"])
                hist = "history differs, " + ("compare failed" if linf is None else f"largest rel_linf {linf:.2e}")
            change, path = largest_summary_change(a, b)
            hist += f"; summary: largest change {change:.2e}" + (f" at {path}" if path else "")
            bounds = f"{a.get('critical_step', {}).get('bound')} -> {b.get('critical_step', {}).get('bound')}"
            print(f"{scene.stem} x{mult}: bound {bounds}, critical_dt change {dt_change:.2e}, {hist}")


if __name__ == "__main__":
    main()
