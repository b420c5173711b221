#!/usr/bin/env python3
"""Writes docs/benchmark-cards.md from verification/cards.toml (the one table of every benchmark
card), or with --check exits 1 when the page and the file disagree.

Usage: docs/benchmark_cards.py [--check] [--root DIR]
"""
import argparse
import pathlib
import sys
import tomllib

HEAD = """# Benchmark cards

Generated from `verification/cards.toml` by `docs/benchmark_cards.py` (the test
`docs_benchmark_cards` fails when this page and the file disagree: run
`/usr/bin/python3 docs/benchmark_cards.py` after editing the cards).

`beamimpact score` judges every method by the same card on each scene: one reference and one
tolerance per quantity, whatever the method's name (docs/protocol.md, "Verdict, exit code and
ratchet"). The tolerances are the verification matrix's rows of the paper integrator (the
project's reference tolerances, `verification/matrix.toml`) at the scene's own settings against
the scene's best reference; each reason names its row. A scene with no such row has tolerances
derived from a sibling row and a stated bound ("derived"). On a scene with an exact answer a
method that accepts a time step or a mesh factor runs a resolution ladder and the extrapolated
limit of each scalar (impulse, peak force, final energy) must lie within 1.25 x its uncertainty +
tol / 10 of the exact value; the other quantities (fields, counts, contact times) are judged on
the finest rung under the tolerance. With `--no-ladder`, or against IDA, the one run's error is judged under it.

Units: relative (1) unless the quantity is a time (contact_start, contact_end: s) or a count
(impacts). Reference `ida` is converged further by `score` (rtol 1e-10, atol 1e-13, penalty
1e4 EA/le, friction regularised at 1e-5 m/s) unless `--references matrix`. A quantity with a
settled value (S4's impulse: docs/s4.md) is judged against that value, its uncertainty in place of
the reference's spread; the reference column then says so.

| scene | set | reference | quantity | tolerance | unit | reason |
|---|---|---|---|---|---|---|
"""


def unit(metric):
    base = metric.split(".")[0]
    if base.startswith(("contact_start", "contact_end")):
        return "s"
    if base.startswith("impacts"):
        return "count"
    return "1"


def cell(text):
    return str(text).replace("|", "\\|").replace("\n", " ")


def page(cards):
    rows = []
    for c in cards:
        name = pathlib.PurePosixPath(c["scene"]).stem
        ref = c["reference"]["method"] + "".join(" " + s for s in c["reference"].get("set", []))
        settled = {v["metric"]: v for v in c.get("settled", [])}
        for q in c["quantities"]:
            v = settled.get(q["metric"])
            r = f"settled {v['value']:g} +- {v['uncertainty']:g} ({v['why']})" if v else ref
            rows.append("| " + " | ".join(cell(x) for x in (name, c["set"], r, q["metric"], f"{q['tol']:g}",
                                                            unit(q["metric"]), q["why"])) + " |")
    notes = [f"- **{pathlib.PurePosixPath(c['scene']).stem}**: {c['note']}" for c in cards if c.get("note")]
    tail = "\n\nQuantities of a scene left off its card, and why:\n\n" + "\n".join(notes) if notes else ""
    return HEAD + "\n".join(rows) + tail + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="exit 1 when the page is not the file's")
    ap.add_argument("--root", default=str(pathlib.Path(__file__).resolve().parent.parent))
    a = ap.parse_args()
    root = pathlib.Path(a.root)
    with open(root / "verification/cards.toml", "rb") as f:
        text = page(tomllib.load(f)["card"])
    target = root / "docs/benchmark-cards.md"
    if a.check:
        if not target.exists() or target.read_text() != text:
            print(f"{target} disagrees with verification/cards.toml: run /usr/bin/python3 docs/benchmark_cards.py",
                  file=sys.stderr)
            return 1
        print("docs/benchmark-cards.md agrees with verification/cards.toml")
        return 0
    target.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
