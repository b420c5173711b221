#!/usr/bin/env python3
"""@brief Mutation testing of the paper's integrator: build each mutant (tools/mutation/mutants.py)
in a scratch copy of the source tree and run the quick verification tier against it.

Besides the quick tier, the real-gap tests (GEOMETRY_TESTS) run against each mutant.

Usage: tools/mutation-test.sh [--all] [--only NAME[,NAME]] [--out DIR] [--scratch DIR] [--jobs N] [--check]
  default: the fast CI subset (mutants marked ci); --all: every mutant; --check: only check that
  every mutant's text occurs exactly once in the source (no build; ctest mutants_apply).
Writes OUT/mutation.json: [{"mutant", "what", "killed_by": [gate ids "case:metric"], ...}] and
OUT/mutation.md; exits 1 when a mutant survives (no gate fails), 2 on a usage or build error of
the unmutated tree. The worktree is never modified: the copy lives in SCRATCH/tree (default
build-mutation/tree; its build directory SCRATCH/tree/build has the same relative layout as
build/, so ccache serves every unmutated object).
"""
import argparse
import json
import re
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(Path(__file__).resolve().parent))
from mutants import MUTANTS  # noqa: E402

# Test binaries (under build/solver/) run against each mutant besides the quick tier: the real-gap
# tests measure penetration from U and the target's own interpolation (solver/paper/hard_cases_test.cc),
# the sliding-gap test the gap of a closed sliding contact from the deformed node positions.
GEOMETRY_TESTS = ["hard_cases_test", "sliding_gap_test"]
# The Timoshenko element and the Hertz law are checked against theory by their own unit tests
# (no quick-tier gate runs them): those binaries run against each mutant too.
GEOMETRY_TESTS += ["timoshenko_element_test", "hertz_law_test", "hertz_contact_test"]


def sh(cmd, **kw):
    return subprocess.run(cmd, text=True, capture_output=True, **kw)


def sync_tree(tree: Path):
    """Copy the worktree's tracked and untracked (not ignored) files; unchanged files keep their mtime."""
    files = sh(["git", "-C", str(ROOT), "ls-files", "-z", "--cached", "--others", "--exclude-standard"]).stdout
    for rel in filter(None, files.split("\0")):
        src, dst = ROOT / rel, tree / rel
        if not src.is_file():
            continue
        data = src.read_bytes()
        if dst.is_file() and dst.read_bytes() == data:
            continue
        dst.parent.mkdir(parents=True, exist_ok=True)
        dst.write_bytes(data)
        shutil.copymode(src, dst)


def apply_edits(tree: Path, edits):
    """Apply (file, old, new) edits to the copy; return the pristine texts to restore."""
    saved = {}
    for rel, old, new in edits:
        f = tree / rel
        text = saved.get(rel) if rel in saved else f.read_text()
        saved.setdefault(rel, text)
        cur = f.read_text()
        if cur.count(old) != 1:
            raise RuntimeError(f"not applicable: {rel} holds the text {old!r} {cur.count(old)} times (expected once)")
        f.write_text(cur.replace(old, new))
    return saved


def check_applicable():
    """Every mutant's old text must occur exactly once in the source, or the mutant tests nothing."""
    bad = []
    for m in MUTANTS:
        for rel, old, _ in m["edits"]:
            n = (ROOT / rel).read_text().count(old)
            if n != 1:
                bad.append(f"{m['name']}: {rel} holds {old!r} {n} times (expected once)")
    for b in bad:
        print(f"mutation-test --check: {b}", file=sys.stderr)
    print(f"mutation-test --check: {len(MUTANTS) - len({b.split(':')[0] for b in bad})} / {len(MUTANTS)} mutants apply")
    return 1 if bad else 0


def build(build_dir: Path, tree: Path, log: Path):
    env = dict(os.environ)
    env.setdefault("CCACHE_BASEDIR", "/work")
    env.setdefault("CCACHE_DIR", "/work/.ccache")
    if not (build_dir / "build.ninja").exists():
        r = sh(["cmake", "-S", str(tree), "-B", str(build_dir), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DBEAMIMPACT_FENICSX_TESTS=OFF",
                "-DBEAMIMPACT_BENCHMARKS=OFF"], env=env)
        if r.returncode:
            log.write_text(r.stdout + r.stderr)
            return False
    r = sh(["cmake", "--build", str(build_dir), "-j2", "--target", "beamimpact", *GEOMETRY_TESTS], env=env)
    log.write_text(r.stdout + r.stderr)
    return r.returncode == 0


def geometry_tests(build_dir: Path, log: Path):
    """Run the tests that judge the integrator from the deformed geometry (the real gap), not from
    its own contact algebra; return the failed test names as "test:Suite.Name"."""
    failed, text = [], ""
    for t in GEOMETRY_TESTS:
        r = sh([str(build_dir / "solver" / t), "--gtest_brief=1"])
        text += r.stdout + r.stderr
        failed += sorted({"test:" + m.group(1) for m in re.finditer(r"^\[  FAILED  \] ([\w/]+\.[\w/]+)", r.stdout, re.M)})
    log.write_text(text)
    return failed


def verify(tree: Path, binary: Path, out: Path, jobs: int):
    """Run the quick tier; return (failed gate ids, exit code, wall s)."""
    if out.exists():
        shutil.rmtree(out)
    t0 = time.time()
    r = sh([str(binary), "verify", str(tree / "verification/matrix.toml"), "--tier", "quick",
            "--out", str(out), "--jobs", str(jobs)])
    (out.parent / (out.name + ".log")).write_text(r.stdout + r.stderr)
    failed = []
    norms = out / "norms.json"
    if norms.exists():
        for item in json.loads(norms.read_text())["items"]:
            for g in item["gates"]:
                if g["status"] == "fail":
                    failed.append(f'{item["name"]}:{g["metric"]}')
    return failed, r.returncode, time.time() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--all", action="store_true", help="every mutant (default: the CI subset)")
    ap.add_argument("--only", default="", help="comma-separated mutant names")
    ap.add_argument("--out", default=str(ROOT / "out/mutation"))
    ap.add_argument("--scratch", default=str(ROOT / "build-mutation"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--check", action="store_true", help="only check that every mutant applies to the source")
    a = ap.parse_args()
    if a.check:
        return check_applicable()
    names = [m["name"] for m in MUTANTS]
    if a.only:
        chosen = a.only.split(",")
        unknown = [n for n in chosen if n not in names]
        if unknown:
            print(f"mutation-test: --only: unknown mutant(s) {unknown}; expected one of {names}", file=sys.stderr)
            return 2
        todo = [m for m in MUTANTS if m["name"] in chosen]
    else:
        todo = [m for m in MUTANTS if a.all or m["ci"]]
    out, scratch = Path(a.out), Path(a.scratch)
    tree, runs = scratch / "tree", scratch / "runs"
    out.mkdir(parents=True, exist_ok=True)
    runs.mkdir(parents=True, exist_ok=True)
    sync_tree(tree)
    build_dir, binary = tree / "build", tree / "build/beamimpact"

    # The unmutated tree must pass: otherwise a "kill" would mean nothing.
    if not build(build_dir, tree, runs / "baseline.build.log"):
        print(f"mutation-test: the unmutated tree does not build (see {runs / 'baseline.build.log'})", file=sys.stderr)
        return 2
    failed, rc, wall = verify(tree, binary, runs / "baseline", a.jobs)
    failed += geometry_tests(build_dir, runs / "baseline.tests.log")
    if rc != 0 or failed:
        print(f"mutation-test: the unmutated tree fails the quick tier ({failed}); see {runs / 'baseline.log'}", file=sys.stderr)
        return 2
    print(f"baseline: quick tier passes ({wall:.0f} s)", flush=True)

    results = []
    for m in todo:
        name = m["name"]
        entry = {"mutant": name, "what": m["what"], "killed_by": []}
        try:
            saved = apply_edits(tree, m["edits"])
        except RuntimeError as e:
            print(f"mutation-test: {name}: {e}", file=sys.stderr)
            return 2
        try:
            if not build(build_dir, tree, runs / f"{name}.build.log"):
                entry["killed_by"] = ["build"]  # does not compile: a broken mutant, reported as such
                entry["note"] = "mutant does not compile"
            else:
                failed, rc, wall = verify(tree, binary, runs / name, a.jobs)
                entry["killed_by"] = failed + geometry_tests(build_dir, runs / f"{name}.tests.log")
                if rc not in (0, 1):
                    entry["killed_by"].append(f"verify exited {rc}")
                entry["wall_seconds"] = round(wall, 1)
        finally:
            for rel, text in saved.items():
                (tree / rel).write_text(text)
        verdict = f"killed by {len(entry['killed_by'])} gate(s)" if entry["killed_by"] else "SURVIVED"
        print(f"{name}: {verdict} {entry['killed_by'][:4]}", flush=True)
        results.append(entry)

    (out / "mutation.json").write_text(json.dumps(results, indent=1) + "\n")
    killed = sum(1 for r in results if r["killed_by"])
    md = [f"# Mutation score: {killed} / {len(results)} killed (quick tier + geometry tests)\n",
          "| mutant | what | killed by (gates) |", "|---|---|---|"]
    for r in results:
        k = ", ".join(r["killed_by"][:6]) + (f" (+{len(r['killed_by']) - 6})" if len(r["killed_by"]) > 6 else "")
        md.append(f"| {r['mutant']} | {r['what']} | {k or '**SURVIVED**'} |")
    (out / "mutation.md").write_text("\n".join(md) + "\n")
    print(f"mutation score: {killed} / {len(results)}; {out / 'mutation.json'}")
    return 0 if killed == len(results) else 1


if __name__ == "__main__":
    sys.exit(main())
