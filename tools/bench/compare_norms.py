#!/usr/bin/env python3
"""Largest change of any verification norm between two `beamimpact verify` outputs.

Usage: compare_norms.py BEFORE/norms.json AFTER/norms.json [--values]
--values: only the norm values (comparisons[].norms[].value), not gates, orders or estimates.
Walks both JSON trees item by item (every number except timings) and reports the largest
absolute and relative change overall, with its path, and each item whose numbers moved or whose
shape differs (a norm present on one side only).
"""
import json
import re
import sys


def leaves(node, path=""):
    if isinstance(node, dict):
        for k, v in node.items():
            if k in ("command", "wall_seconds", "seconds", "solver_seconds"):  # timings
                continue
            yield from leaves(v, f"{path}/{k}")
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from leaves(v, f"{path}[{i}]")
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        yield path, float(node)


def main():
    args = [a for a in sys.argv[1:] if a != "--values"]
    values_only = "--values" in sys.argv[1:]
    if len(args) != 2:
        sys.exit("usage: compare_norms.py BEFORE/norms.json AFTER/norms.json [--values]")
    before, after = json.load(open(args[0])), json.load(open(args[1]))
    worst = (0.0, 0.0, "", 0.0, 0.0)  # relative, absolute, path, before, after
    count = changed = 0
    for i, (x, y) in enumerate(zip(before["items"], after["items"])):
        a, b = dict(leaves(x)), dict(leaves(y))
        item = (0.0, "")
        for k in a.keys() & b.keys():
            if values_only and not re.search(r"/norms\[\d+\]/value$", k):
                continue
            count += 1
            d = abs(a[k] - b[k])
            r = d / max(abs(a[k]), abs(b[k]), 1e-300)
            changed += d > 0
            item = max(item, (r, k))
            if r > worst[0]:
                worst = (r, d, f"items[{i}]{k}", a[k], b[k])
        if item[0] > 0 or (a.keys() != b.keys() and not values_only):
            print(f"items[{i}] {x.get('name', '')}: largest relative change {item[0]:.3g} at {item[1]}"
                  + ("; shape differs" if a.keys() != b.keys() else ""))
    print(f"{count} numbers compared, {changed} changed; largest relative change {worst[0]:.3g} "
          f"(absolute {worst[1]:.3g}) at {worst[2]}: {worst[3]!r} -> {worst[4]!r}")

if __name__ == "__main__":
    main()
