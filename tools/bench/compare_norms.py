#!/usr/bin/env python3
"""Largest change of any verification norm between two `beamimpact verify` outputs.

Usage: compare_norms.py BEFORE/norms.json AFTER/norms.json
Walks both JSON trees in parallel and reports, over every numeric leaf named "value" (and every
other number), the largest absolute and relative change, with its path. Exit 2 when the trees
differ in shape (a norm missing on one side).
"""
import json
import sys


def leaves(node, path=""):
    if isinstance(node, dict):
        for k, v in node.items():
            if k in ("command", "wall_seconds", "seconds"):
                continue
            yield from leaves(v, f"{path}/{k}")
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from leaves(v, f"{path}[{i}]")
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        yield path, float(node)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: compare_norms.py BEFORE/norms.json AFTER/norms.json")
    a = dict(leaves(json.load(open(sys.argv[1]))))
    b = dict(leaves(json.load(open(sys.argv[2]))))
    if a.keys() != b.keys():
        print("different shapes:", sorted(a.keys() ^ b.keys())[:10])
        sys.exit(2)
    worst_abs = max(a, key=lambda k: abs(a[k] - b[k]))
    rel = lambda k: abs(a[k] - b[k]) / max(abs(a[k]), abs(b[k]), 1e-300)
    worst_rel = max(a, key=rel)
    changed = sum(1 for k in a if a[k] != b[k])
    print(f"{len(a)} numbers, {changed} changed")
    print(f"largest absolute change {abs(a[worst_abs] - b[worst_abs]):.3g} at {worst_abs}: "
          f"{a[worst_abs]!r} -> {b[worst_abs]!r}")
    print(f"largest relative change {rel(worst_rel):.3g} at {worst_rel}: {a[worst_rel]!r} -> {b[worst_rel]!r}")


if __name__ == "__main__":
    main()
