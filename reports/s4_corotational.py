#!/usr/bin/env python3
"""@brief S4's corotational striker checked by an independent reference: the impulse difference
corotational minus linear kinematics, from the paper integrator and from the IDA reference (its own
corotational elements, references/ida/ElasticForce.hpp), each at its converged settings.

Ladders on the scene's own mesh (the settings of reports/s4_settled.py):
- paper: the automatic step at fractions 1/2 ... 1/64 of the critical step, corotational (as
  shipped) and linear;
- ida: penalty 1e2, 1e3, 1e4, 1e5 EA/le, rtol 1e-10, atol 1e-13, friction regularised at 1e-5 m/s,
  corotational and linear.
For each rung the relative difference (I_corotational - I_linear) / I_linear of the total normal
impulse; each ladder of differences is read in its asymptotic range by s4_settled.ladder_limit
(step ladder from the fine end, penalty ladder from the soft end). The two methods agree when their
limits differ by less than the sum of their uncertainties (plus a roundoff floor of 1e-6).
IDA's penalty ladder is read from its soft end while each rung moves the difference by less than
the one before: on S4 at 45 and 60 degrees the rungs from 1e4 EA/le on chatter (their impulse moves
by tenths of a percent under roundoff-level changes), so the limit is the last rung before them.

The settled corotational impulse (what the scorecard holds the shipped, corotational S4 scenes to:
verification/cards.toml): the linear settled impulse of OUT/settled.json (s4_settled.py, run first)
times (1 + IDA's limit of the difference), the uncertainty the sum of the two,
U_linear (1 + c) + |I_linear| U_c. IDA's limit, not the paper integrator's: the paper integrator
is what the scorecard scores, never a part of its reference.

Usage: s4_corotational.py [--build build] [--out reports/s4] [--runs DIR] [--jobs 2] [--angles 45,60,90]
Writes OUT/corotational.json. Exit 2 on bad input, 1 when a run fails.
"""
import concurrent.futures
import datetime
import json
import os
import sys

from report_files import write_json_atomic
from s4_settled import (IDA_TIGHT, LINEAR, PENALTY_MIN_ORDER, ROOT, STEP_MIN_ORDER, fail, ladder_limit, options,
                        run, scene_path, version)

PAPER_FRACTIONS = [1 / 2 ** k for k in range(1, 7)]  # 1/2 ... 1/64 of the critical step
IDA_PENALTIES = [1e2, 1e3, 1e4, 1e5]                 # EA/le
ROUNDOFF = 1e-6  # relative: two runs of one model with no rotation (S4-90) differ by 7e-9


def ladders(exe, angle, runs, pool):
    """Every run of one angle, submitted to the pool: {(method, kinematics): [futures]}."""
    scene = scene_path(angle)
    d = os.path.join(runs, f"s4_{angle}")
    jobs = {}
    for kin, sets in (("corotational", []), ("linear", [LINEAR])):
        jobs[("paper", kin)] = [pool.submit(run, exe, scene, "paper", f"{d}/paper_{kin}_{f:g}",
                                            sets + [f"time.fraction={f!r}"]) for f in PAPER_FRACTIONS]
        jobs[("ida", kin)] = [pool.submit(run, exe, scene, "ida", f"{d}/ida_{kin}_{k:g}",
                                          sets + [f"ida.kn_factor={k:g}"] + IDA_TIGHT) for k in IDA_PENALTIES]
    return jobs


def compare(values):
    """Per method the ladders of impulse and of the relative corotational-minus-linear difference,
    each with its limit; then whether the two methods' limits of the difference agree."""
    out = {}
    for method, ratio, fine_end, order in (("paper", 2.0, True, STEP_MIN_ORDER),
                                           ("ida", 10.0, False, PENALTY_MIN_ORDER)):
        corot = [r["impulse_normal"] for r in values[(method, "corotational")]]
        linear = [r["impulse_normal"] for r in values[(method, "linear")]]
        rel = [(c - l) / l for c, l in zip(corot, linear)]
        out[method] = {"impulse_corotational": corot, "impulse_linear": linear,
                       "impacts_corotational": [r["impacts"] for r in values[(method, "corotational")]],
                       "wall_seconds_corotational": [r["wall_seconds"] for r in values[(method, "corotational")]],
                       "relative_difference": rel,
                       "limit": ladder_limit(rel, ratio, from_fine_end=fine_end, min_order=order)}
    p, i = out["paper"]["limit"], out["ida"]["limit"]
    if p["limit"] is not None and i["limit"] is not None:
        out["paper_minus_ida"] = p["limit"] - i["limit"]
        out["bound"] = p["uncertainty"] + i["uncertainty"] + ROUNDOFF
        out["agree"] = abs(out["paper_minus_ida"]) <= out["bound"]
    else:
        out["agree"] = None
    return out


def settled_corotational(out, angle, difference):
    """The corotational settled impulse of one angle from the linear one (OUT/settled.json) and IDA's
    limit of the corotational difference; None when either is missing or not converged."""
    path = os.path.join(out, "settled.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        q = json.load(f)["angles"].get(angle, {}).get("quantities", {}).get("impulse_normal", {})
    c = difference["ida"]["limit"]
    if "value" not in q or c["limit"] is None or not c["converged"]:
        return None
    value = q["value"] * (1.0 + c["limit"])
    uncertainty = q["uncertainty"] * (1.0 + c["limit"]) + abs(q["value"]) * c["uncertainty"]
    return {"impulse_normal": {"value": value, "uncertainty": uncertainty, "unit": "N s",
                               "linear": q["value"], "linear_uncertainty": q["uncertainty"],
                               "ida_difference": c["limit"], "ida_difference_uncertainty": c["uncertainty"]}}


def main():
    a, exe, angles, runs = options(__doc__)
    started = datetime.datetime.now(datetime.timezone.utc)
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        submitted = {x: ladders(exe, x, runs, pool) for x in angles}
        values = {x: {k: [f.result() for f in fs] for k, fs in j.items()} for x, j in submitted.items()}
    doc = {"command": ("/usr/bin/python3 reports/s4_corotational.py " + " ".join(sys.argv[1:])).strip(),
           "version": version(exe), "made": started.strftime("%Y-%m-%dT%H:%M:%SZ"),
           "scenes": {x: os.path.relpath(scene_path(x), ROOT) for x in angles},
           "quantity": "(I_corotational - I_linear) / I_linear, I the total normal impulse (N s)",
           "ladders": {"paper_fractions": PAPER_FRACTIONS, "ida_penalty_EA_per_le": IDA_PENALTIES,
                       "ida_settings": IDA_TIGHT},
           "rule": "agree: |paper limit - ida limit| <= the sum of their uncertainties (s4_settled.ladder_limit)",
           "angles": {x: compare(values[x]) for x in angles}}
    doc["settled_rule"] = ("settled corotational impulse = settled linear impulse (settled.json) x (1 + ida's limit); "
                           "uncertainty = U_linear (1 + c) + |I_linear| U_c")
    for x in angles:
        doc["angles"][x]["settled_corotational"] = settled_corotational(a.out, x, doc["angles"][x])
    write_json_atomic(os.path.join(a.out, "corotational.json"), doc)
    for x in angles:
        c = doc["angles"][x]
        line = []
        for m in ("paper", "ida"):
            lim = c[m]["limit"]
            line.append(f"{m} {lim['limit']:+.4%} +- {lim['uncertainty']:.2%}" if lim["limit"] is not None
                        else f"{m} (no limit)")
        print(f"S4-{x} corotational - linear impulse: " + ", ".join(line) + f"; agree: {c['agree']}")
        if c["settled_corotational"]:
            s = c["settled_corotational"]["impulse_normal"]
            print(f"S4-{x} settled corotational impulse: {s['value']:.6g} +- {s['uncertainty']:.3g} N s")


if __name__ == "__main__":
    main()
