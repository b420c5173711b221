"""@brief What accuracy costs, as numbers: from the work-precision sets (reports/work_precision/NAME/
work_precision.json, written by reports/work_precision.py), the CPU time each method needs to reach
an impulse error level and its ratio to the paper integrator's, one grid per set (rows: error levels,
columns: methods) with the model's size, and the headline set the verdict quotes."""
import glob
import os

from figure_sets import load_json

PAPER = "paper"  # the method every ratio is taken against (method names of work_precision.py)
METHOD_ORDER = ("paper", "exact", "IDA", "FEniCSx", "Siconos")


def seconds(v):
    """@brief CPU time in 3 significant digits with its unit (ms below 0.1 s)."""
    return f"{v:.3g} s" if v >= 0.1 else f"{v * 1e3:.3g} ms"


def ratio_text(r):
    """@brief A ratio in 3 significant digits without an exponent: 3521.5 -> "3,520×", 0.0255 -> "1/39.2×"."""
    if r < 1:
        return "1/" + ratio_text(1 / r)
    if r >= 1000:
        return f"{round(r, 2 - len(str(int(r))) + 1):,.0f}×"
    return f"{r:.3g}×"


def cell(entry, method):
    """@brief One grid cell: {"s": text of the CPU time, "ratio": text of the ratio to the paper's,
    "state": ok | bound | not_reached | not_run, "note": why not run}."""
    cpu = entry["cpu_s"].get(method)
    empty = {"ratio": "", "ratio_value": None, "range": "", "note": "", "cpu": None}
    if method not in entry["cpu_s"]:
        return {**empty, "s": "not run", "state": "not_run"}
    if cpu is None:
        return {**empty, "s": "not reached", "state": "not_reached"}
    bound = entry["upper_bound"].get(method, False)
    ratio = 1.0 if method == PAPER else entry["ratio_to_paper"].get(method)
    lo_hi = entry.get("ratio_range", {}).get(method)
    return {"s": ("≤ " if bound else "") + seconds(cpu), "cpu": cpu,
            "ratio": "" if ratio is None else ratio_text(ratio), "ratio_value": ratio,
            "range": "" if not lo_hi else f"{ratio_text(lo_hi[0])[:-1]}–{ratio_text(lo_hi[1])}",
            "state": "bound" if bound else "ok", "note": ""}


def set_grid(name, res):
    """@brief One set's grid. Methods in METHOD_ORDER, then any other; a method the set did not run
    (res["not_run"]) keeps its column with the reason."""
    methods = []
    for e in res["equal_error"]:
        methods += [m for m in e["cpu_s"] if m not in methods]
    not_run = res.get("not_run") or {}
    methods += [m for m in not_run if m not in methods]
    methods.sort(key=lambda m: (METHOD_ORDER.index(m) if m in METHOD_ORDER else len(METHOD_ORDER), m))
    rows = []
    for e in sorted(res["equal_error"], key=lambda e: -e["impulse_error"]):
        cells = [cell(e, m) for m in methods]
        for m, c in zip(methods, cells):
            if c["state"] == "not_run" and m in not_run:
                c["note"] = not_run[m]
        rows.append({"level": f"{100 * e['impulse_error']:.3g} %", "impulse_error": e["impulse_error"],
                     "cells": cells})
    over = res.get("overrides") or {}
    return {"name": name, "dofs": res.get("dofs"), "scene": res["scene"], "version": res["version"],
            "command": res["command"], "reference": res["reference"], "methods": methods, "rows": rows,
            "overrides": " ".join(f"{k}={v}" for k, v in over.items())}


def grids(wp_dir):
    """@brief Every set's grid, smallest model first (sets without work_precision.json left out)."""
    out = []
    for js in sorted(glob.glob(os.path.join(wp_dir, "*", "work_precision.json"))):
        name = os.path.basename(os.path.dirname(js))
        out.append(set_grid(name, load_json(js, "a work-precision set")))
    out.sort(key=lambda g: (g["dofs"] or 0, g["name"]))
    return out


def headline(all_grids, levels=(0.01, 0.001)):
    """@brief The set the verdict quotes: the one where most methods reach 1 % impulse error (ties:
    the larger model), with its rows at `levels` only. None without sets."""
    def reached(g):
        row = next((r for r in g["rows"] if abs(r["impulse_error"] - levels[0]) < 1e-12), None)
        return sum(c["state"] in ("ok", "bound") for c in row["cells"]) if row else -1
    if not all_grids:
        return None
    best = max(all_grids, key=lambda g: (reached(g), g["dofs"] or 0))
    rows = [r for r in best["rows"] if any(abs(r["impulse_error"] - lv) < 1e-12 for lv in levels)]
    return {**best, "rows": rows}


def ratio_spread(all_grids, level):
    """@brief Over every set that reached `level` with both the paper integrator and the method:
    {method: (lowest ratio, highest ratio, sets)} of CPU time to the paper's."""
    out = {}
    for g in all_grids:
        for r in g["rows"]:
            if abs(r["impulse_error"] - level) > 1e-12:
                continue
            for m, c in zip(g["methods"], r["cells"]):
                if m != PAPER and c.get("ratio_value") is not None:
                    lo, hi, n = out.get(m, (float("inf"), 0.0, 0))
                    out[m] = (min(lo, c["ratio_value"]), max(hi, c["ratio_value"]), n + 1)
    return dict(sorted(out.items(), key=lambda kv: METHOD_ORDER.index(kv[0]) if kv[0] in METHOD_ORDER else 99))


# Why a ladder's error does not fall, by what the ladder refines (work_precision.py's method labels).
LADDER_REASONS = (
    (("dt ladder", "rtol ladder"),
     "time integration is refined (dt or rtol) at a fixed mesh, so the mesh (spatial) error dominates and stays; a smaller step "
     "also resolves more of the contact force's oscillation on that mesh, so the error can even grow. "
     "The mesh ladder is the one that shows the method converging."),
    (("mesh ladder", "meshes", "mesh x"),
     "the mesh is refined but another error dominates: the time step or contact penalty held with it, or "
     "the reference's own error at this size."),
)
FALL = 0.8  # a ladder "falls" when its last rung's error is below 0.8 of its first's (a 20 % gain)


def flat_ladders(res):
    """@brief The ladders of one set whose impulse error does not fall from the first rung to the
    last: [{"method", "first", "last", "why"}] (a ladder: a method label with two or more ok points)."""
    by = {}
    for p in res["points"]:
        if p.get("status") == "ok" and (p.get("error") or {}).get("impulse"):
            by.setdefault(p["method"], []).append(p["error"]["impulse"])
    out = []
    for method, errs in by.items():
        if len(errs) < 2 or errs[-1] < FALL * errs[0]:
            continue
        why = next((text for keys, text in LADDER_REASONS if any(k in method for k in keys)),
                   "another error than the one this ladder refines dominates.")
        out.append({"method": method, "first": errs[0], "last": errs[-1], "why": why})
    return out
