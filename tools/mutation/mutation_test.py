#!/usr/bin/env python3
"""@brief Mutation testing in every layer: build each mutant (tools/mutation/mutants.py) in a
scratch copy of the source tree and run against it the tests of the test command that judge it.

A mutant of the paper's code (verify = True, the default) meets the quick verification tier and
the real-gap tests (GEOMETRY_TESTS); every mutant also meets its own `tests` (ctest names from
the test command, built from its `targets`). The unmutated tree must pass all of them first.

Usage: tools/mutation-test.sh [--all] [--only NAME[,NAME]] [--out DIR] [--scratch DIR] [--jobs N] [--check]
  default: the fast CI subset (mutants marked ci); --all: every mutant; --check: only check that
  every mutant's text occurs exactly once in the source and every test it names exists (no build;
  ctest mutants_apply).
Writes OUT/mutation.json: [{"mutant", "layer", "what", "killed_by": [gate ids "case:metric",
"test:Suite.Name", "ctest:NAME"], ...}] and OUT/mutation.md (a table per layer); exits 1 when a mutant survives (no gate fails), 2 on a usage or build error of
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


def declared_tests(listed, cmake_text):
    """The test names the source declares: Suite.Name of every TEST, TEST_F and TEST_P in a
    *_test.cc (gtest's names, as ctest lists them), and every word of the CMakeLists.txt files
    (the names of tests added there by hand)."""
    names = set(re.findall(r"[\w.:/-]+", cmake_text))
    for f in listed:
        if f.endswith("_test.cc") and (ROOT / f).is_file():
            for m in re.finditer(r"^\s*TEST(?:_F|_P)?\(\s*(\w+)\s*,\s*(\w+)\s*\)", (ROOT / f).read_text(), re.M):
                names.add(f"{m.group(1)}.{m.group(2)}")
    return names


def check_applicable():
    """Every mutant's old text must occur exactly once in the source, or the mutant tests nothing;
    every mutant has a layer and something that judges it."""
    bad = []
    listed = sh(["git", "-C", str(ROOT), "ls-files", "--cached", "--others", "--exclude-standard"]).stdout.split("\n")
    cmake_text = "".join((ROOT / f).read_text() for f in listed if f.endswith("CMakeLists.txt") and (ROOT / f).is_file())
    test_names = declared_tests(listed, cmake_text)
    for m in MUTANTS:
        for rel, old, _ in m["edits"]:
            n = (ROOT / rel).read_text().count(old)
            if n != 1:
                bad.append(f"{m['name']}: {rel} holds {old!r} {n} times (expected once)")
        for t in m.get("targets", []):
            if not re.search(rf"\b{re.escape(t)}\b", cmake_text):
                bad.append(f"{m['name']}: no CMakeLists.txt names the target {t}")
        for t in m.get("tests", []):
            if not any(re.fullmatch(t, n) for n in test_names):
                bad.append(f"{m['name']}: no test is named {t!r} (a renamed or removed test judges nothing)")
        if not m.get("layer"):
            bad.append(f"{m['name']}: no layer")
        if not m.get("verify", True) and not m.get("tests"):
            bad.append(f"{m['name']}: verify = False and no tests: nothing would judge it")
    for b in bad:
        print(f"mutation-test --check: {b}", file=sys.stderr)
    print(f"mutation-test --check: {len(MUTANTS) - len({b.split(':')[0] for b in bad})} / {len(MUTANTS)} mutants apply")
    return 1 if bad else 0


def build(build_dir: Path, tree: Path, log: Path, targets):
    # The compile lines of tools/build.sh (Ninja, Release, ccache with the repository as its base
    # folder): the copy's objects have the same relative paths, so ccache serves every unmutated one.
    env = dict(os.environ)
    env.setdefault("CCACHE_BASEDIR", str(ROOT))
    launcher = ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"] if shutil.which("ccache") else []
    if not (build_dir / "build.ninja").exists():
        r = sh(["cmake", "-S", str(tree), "-B", str(build_dir), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                *launcher, "-DBEAMIMPACT_FENICSX_TESTS=OFF", "-DBEAMIMPACT_BENCHMARKS=OFF"], env=env)
        if r.returncode:
            log.write_text(r.stdout + r.stderr)
            return False
    r = sh(["cmake", "--build", str(build_dir), "-j2", "--target", *targets], env=env)
    log.write_text(r.stdout + r.stderr)
    return r.returncode == 0


def targets_of(mutants, verify):
    """The build targets: the program, the geometry tests when the quick tier runs, each mutant's own."""
    t = ["beamimpact"] + (GEOMETRY_TESTS if verify else [])
    for m in mutants:
        t += [x for x in m.get("targets", []) if x not in t]
    return t


def ctests(build_dir: Path, patterns, log: Path):
    """Run the tests of the test command whose ctest names match a pattern (a regular expression
    matched whole, e.g. "CompareRuns\\..*"); return the failed ones as "ctest:NAME". A pattern no
    test matches counts as failed ("ctest:PATTERN not found"): the mutant list is stale."""
    if not patterns:
        return []
    r = sh(["ctest", "--test-dir", str(build_dir), "-R", "^(" + "|".join(patterns) + ")$", "-j2", "--timeout", "600",
            "--output-on-failure"])
    log.write_text(r.stdout + r.stderr)
    failed = ["ctest:" + m.group(1) for m in re.finditer(r"^\s*\d+ - (\S+) \(", r.stdout, re.M)]
    ran = re.findall(r"Test\s+#\d+: (\S+) ", r.stdout)
    failed += [f"ctest:{p} not found" for p in patterns if not any(re.fullmatch(p, n) for n in ran)]
    return failed


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
    any_verify = any(m.get("verify", True) for m in todo)

    # The unmutated tree must pass everything the mutants meet: otherwise a "kill" would mean nothing.
    if not build(build_dir, tree, runs / "baseline.build.log", targets_of(todo, any_verify)):
        print(f"mutation-test: the unmutated tree does not build (see {runs / 'baseline.build.log'})", file=sys.stderr)
        return 2
    failed, rc, wall = verify(tree, binary, runs / "baseline", a.jobs) if any_verify else ([], 0, 0.0)
    if any_verify:
        failed += geometry_tests(build_dir, runs / "baseline.tests.log")
    all_tests = sorted({t for m in todo for t in m.get("tests", [])})
    failed += ctests(build_dir, all_tests, runs / "baseline.ctest.log")
    if rc != 0 or failed:
        print(f"mutation-test: the unmutated tree fails ({failed}); see {runs}/baseline*.log", file=sys.stderr)
        return 2
    print(f"baseline: quick tier and {len(all_tests)} test(s) pass ({wall:.0f} s quick tier)", flush=True)

    results = []
    for m in todo:
        name, check_tier = m["name"], m.get("verify", True)
        entry = {"mutant": name, "layer": m["layer"], "what": m["what"], "killed_by": []}
        try:
            saved = apply_edits(tree, m["edits"])
        except RuntimeError as e:
            print(f"mutation-test: {name}: {e}", file=sys.stderr)
            return 2
        t0 = time.time()
        try:
            if not build(build_dir, tree, runs / f"{name}.build.log", targets_of([m], check_tier)):
                entry["killed_by"] = ["build"]  # does not compile: a broken mutant, reported as such
                entry["note"] = "mutant does not compile"
            else:
                if check_tier:
                    failed, rc, _ = verify(tree, binary, runs / name, a.jobs)
                    entry["killed_by"] = failed + geometry_tests(build_dir, runs / f"{name}.tests.log")
                    if rc not in (0, 1):
                        entry["killed_by"].append(f"verify exited {rc}")
                entry["killed_by"] += ctests(build_dir, m.get("tests", []), runs / f"{name}.ctest.log")
        finally:
            for rel, text in saved.items():
                (tree / rel).write_text(text)
        entry["wall_seconds"] = round(time.time() - t0, 1)
        verdict = f"killed by {len(entry['killed_by'])}" if entry["killed_by"] else "SURVIVED"
        print(f"{name} [{m['layer']}]: {verdict} {entry['killed_by'][:4]}", flush=True)
        results.append(entry)

    (out / "mutation.json").write_text(json.dumps(results, indent=1) + "\n")
    (out / "mutation.md").write_text(report(results))
    killed = sum(1 for r in results if r["killed_by"])
    print(f"mutation score: {killed} / {len(results)}; {out / 'mutation.md'}")
    return 0 if killed == len(results) else 1


def report(results):
    """Markdown: the score, then one table per layer (mutant, what, killed by)."""
    killed = sum(1 for r in results if r["killed_by"])
    md = [f"# Mutation score: {killed} / {len(results)} killed\n",
          "Killed by: `case:metric` a gate of the quick verification tier, `test:Suite.Name` a real-gap "
          "test, `ctest:NAME` a test of the test command.\n",
          "| layer | mutants | killed |", "|---|---|---|"]
    layers = list(dict.fromkeys(r["layer"] for r in results))
    for layer in layers:
        rs = [r for r in results if r["layer"] == layer]
        md.append(f"| {layer} | {len(rs)} | {sum(1 for r in rs if r['killed_by'])} |")
    for layer in layers:
        md += ["", f"## {layer}", "", "| mutant | what | killed by |", "|---|---|---|"]
        for r in (r for r in results if r["layer"] == layer):
            k = ", ".join(r["killed_by"][:6]) + (f" (+{len(r['killed_by']) - 6})" if len(r["killed_by"]) > 6 else "")
            md.append(f"| {r['mutant']} | {r['what']} | {k or '**SURVIVED**'} |")
    return "\n".join(md) + "\n"


if __name__ == "__main__":
    sys.exit(main())
