"""@brief The data of the report page (templates/report.html.j2), from one `beamimpact verify`
output (norms.json) and the committed figure sets: the verdict and what it promises, the weakest
regime (this run's tightest gates and the parameter study's breakdown), the cost grid, every gate by
scene, and which figures this run made."""
import os

import breakdown
import cost_grid
from figure_sets import InputProblem, figure_set, load_json, provenance

# Margin = a gate's value over its limit (norms.json "margin": 1 = at the limit); cell colours.
MARGIN_CLOSE, MARGIN_NEAR = 0.5, 0.9
TIGHTEST = 8  # gates listed under "where it fails" after the failing ones
WEAKEST_SCENES = 3  # scenes the verdict names, tightest first
# The parameter study whose breakdown the verdict summarises: its table, its two mapped
# parameters and the figure (reports/figures/figures.json) that maps it.
STUDY = ("figures", "study_s4_angle_friction.csv", "alpha0", "mu", "study_s4_angle_friction_stability.png")
NORMS_KEYS = ("command", "version", "tier", "verdict", "gates", "passed", "failed", "skipped", "items")


def load_norms(verify_dir):
    """@brief norms.json of a verify run, checked for the keys the page reads."""
    norms = load_json(os.path.join(verify_dir, "norms.json"), "the verification run's results")
    for k in NORMS_KEYS:
        if k not in norms:
            raise InputProblem(f"{verify_dir}/norms.json: key '{k}' missing (expected a `beamimpact verify` norms.json)")
    if not any(it.get("gates") for it in norms["items"]):
        raise InputProblem(f"{verify_dir}/norms.json: no gate in 'items' (an empty verification run)")
    for it in norms["items"]:
        for g in it.get("gates", []):
            if "passed" not in g or "margin" not in g:
                raise InputProblem(f"{verify_dir}/norms.json: a gate of '{it.get('name')}' lacks 'passed' or "
                                   "'margin' (written by `beamimpact verify` of this version)")
    return norms


def item_method(it):
    """@brief The method an item ran: the word after the scene in its name ("s1_central/paper" -> paper)."""
    name = it.get("name", "")
    if name.startswith(it.get("scene", "")):
        name = name[len(it.get("scene", "")):]
    words = name.replace("/", " ", 1).split()
    return words[0] if words else "?"


def run_labels(it):
    """@brief The run and reference cells of an item's gates: a ladder's run is its rungs and what
    they are judged against (its reference run, or each rung against the next finer:
    self-convergence), as report.md says it (verification/matrix/reports.cc, row_labels)."""
    ref = it.get("reference", "")
    if it.get("kind") != "convergence":
        return it.get("settings") or it["name"], ref
    rungs = it["name"][len(it.get("scene", "")):].strip()
    if not ref:
        return f"{rungs} (self-convergence: each rung against the next finer)", "-"
    return f"{rungs.removesuffix(' vs ' + ref)} (ladder: each rung against {ref})", ref


def gate_rows(norms):
    """@brief Every gate as a flat row (scene, method, run, against (the reference cell as shown),
    reference, metric, value, limit, margin, status, message, why)."""
    rows = []
    for it in norms["items"]:
        run, against = run_labels(it)
        for g in it.get("gates", []):
            rows.append({"scene": it["scene"], "method": item_method(it), "run": run, "against": against,
                         "name": it["name"], "reference": it.get("reference", ""), "metric": g["metric"],
                         "value": g.get("value"), "limit": g.get("limit", ""), "margin": g["margin"],
                         "passed": g["passed"], "status": g["status"], "message": g.get("message", ""),
                         "why": g.get("why", "")})
    return rows


def worst(gates):
    """@brief (css class, label, sort key) of a group of gates: failed first, then skipped, then by
    the share of the limit used (label "98 %": the worst gate is at 98 % of its limit)."""
    failed = [g for g in gates if not g["passed"]]
    if failed:
        m = [g["margin"] for g in failed if g["margin"] is not None]
        return "m-fail", ("FAIL " + share(max(m))) if m else "FAIL", (0, -max(m, default=0.0))
    if any(g["status"] == "skipped" for g in gates):
        return "m-skip", "skipped", (1, 0.0)
    m = [g["margin"] for g in gates if g["margin"] is not None]
    if not m:
        return "m-none", "pass", (3, 0.0)
    top = max(m)
    cls = "m-ok" if top < MARGIN_CLOSE else "m-close" if top < MARGIN_NEAR else "m-near"
    return cls, share(top), (2, -top)


def share(margin):
    """@brief A margin as the share of the limit used: 0.98 -> "98 %"."""
    return "∞" if margin == float("inf") else f"{100 * margin:.0f} %" if margin >= 0.01 else f"{100 * margin:.1g} %"


def scorecard(rows):
    """@brief Scenes by methods, each cell the worst gate of that scene and method; failing scenes first."""
    methods, cells = [], {}
    for r in rows:
        if r["method"] not in methods:
            methods.append(r["method"])
        cells.setdefault(r["scene"], {}).setdefault(r["method"], []).append(r)
    out = []
    for scene, by in cells.items():
        every = [g for gs in by.values() for g in gs]
        tds = []
        for m in methods:
            cls, label, _ = worst(by[m]) if m in by else ("", "", None)
            tds.append({"cls": cls, "label": label, "n": len(by.get(m, []))})
        out.append({"scene": scene, "key": worst(every)[2], "failed": any(not g["passed"] for g in every),
                    "cells": tds})
    out.sort(key=lambda r: (r["key"], r["scene"]))
    return {"methods": methods, "rows": out}


def weakest(rows, study):
    """@brief The verdict's weakest regime: the scene with the tightest (or failing) gate and that
    gate; the study's breakdown range (None without the study)."""
    by_scene = {}
    for r in rows:
        by_scene.setdefault(r["scene"], []).append(r)
    order = sorted(by_scene, key=lambda s: (worst(by_scene[s])[2], s))
    gates = sorted((g for g in by_scene[order[0]] if g["margin"] is not None), key=lambda g: -g["margin"])
    return {"scene": order[0], "gate": gates[0] if gates else None, "label": worst(by_scene[order[0]])[1],
            "next": [(s, worst(by_scene[s])[1]) for s in order[1:WEAKEST_SCENES]], "study": study}


def where_it_fails(rows):
    """@brief The failing gates, then the TIGHTEST gates closest to their limits."""
    failed = [r for r in rows if not r["passed"]]
    passing = sorted((r for r in rows if r["passed"] and r["margin"] is not None), key=lambda r: -r["margin"])
    return failed, passing[:TIGHTEST]


def study_summary(set_dirs):
    """@brief The breakdown summary of STUDY when its set is among the page's, else None."""
    name, table, x, y, png = STUDY
    d = next((d for d in set_dirs if os.path.basename(os.path.normpath(d)) == name), None)
    path = os.path.join(d, table) if d else None
    if not path or not os.path.isfile(path):
        return None
    s = breakdown.summarize(path, x, y)
    return {**s, "table": f"reports/{name}/{table}", "anchor": f"fig-{name}-{os.path.splitext(png)[0]}"}


def cost(set_dirs):
    """@brief The cost grids of the work-precision set (None when it is not among the page's sets)."""
    d = next((d for d in set_dirs if os.path.basename(os.path.normpath(d)) == "work_precision"), None)
    if not d:
        return None
    grids = cost_grid.grids(d)
    for g in grids:
        g["flat"] = cost_grid.flat_ladders(load_json(os.path.join(d, g["name"], "work_precision.json"),
                                                     "a work-precision set"))
    methods = []
    for g in grids:
        methods += [m for m in g["methods"] if m not in methods]
    methods.sort(key=lambda m: (cost_grid.METHOD_ORDER + (m,)).index(m))
    return {"grids": grids, "methods": methods, "headline": cost_grid.headline(grids),
            "spread": {lv: cost_grid.ratio_spread(grids, lv) for lv in (0.01, 0.001)}}


def promise(norms, rows):
    """@brief What a pass promises, in one sentence (scenes, references and tier of this run)."""
    scenes = sorted({r["scene"] for r in rows})
    refs = sorted({r["reference"].split()[0] for r in rows if r["reference"]})  # the method, not its settings
    own = sum(not r["reference"] for r in rows)
    self_conv = f"{'; ' if refs else ''}its own finer runs for {own} convergence gates" if own else ""
    return (f"PASS promises that each of the {len(rows)} gated quantities of the {norms['tier']} tier, on these "
            f"{len(scenes)} scenes at the settings listed, lies within the tolerance written beside it "
            f"against its reference ({', '.join(refs)}{self_conv}); it promises nothing for other "
            "scenes, settings or quantities.")


def context(verify_dir, set_dirs, out_dir):
    """@brief Everything the report template reads. @param out_dir the page's folder (figures copied there)."""
    norms = load_norms(verify_dir)
    rows = gate_rows(norms)
    sets = [figure_set(d, norms["version"], out_dir) for d in set_dirs]
    failed, tightest = where_it_fails(rows)
    study = study_summary(set_dirs)
    by_scene = {}
    for r in rows:
        by_scene.setdefault(r["scene"], []).append(r)
    scenes = sorted(by_scene, key=lambda s: (worst(by_scene[s])[2], s))
    return {"norms": norms, "gates": rows, "failed": failed, "tightest": tightest,
            "weakest": weakest(rows, study), "study": study, "scorecard": scorecard(rows),
            "cost": cost(set_dirs), "sets": sets, "provenance": provenance(sets, norms["version"]),
            "promise": promise(norms, rows), "scenes": [(s, by_scene[s]) for s in scenes],
            "margins": (MARGIN_CLOSE, MARGIN_NEAR), "share": share, "ratio": cost_grid.ratio_text}
