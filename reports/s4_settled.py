#!/usr/bin/env python3
"""@brief The paper's oblique impact with friction (S4 at 45, 60 and 90 degrees) settled: every
reference run to its converged limit, and the value each well-conditioned quantity converges to,
with an uncertainty from the spread of the independent references.

Ladders, all on the scene's own mesh with linear kinematics (the formulation every reference can
run; the shipped corotational striker is measured against it by the paper integrator's own ladder):
- paper: the automatic step at fractions 1/2 ... 1/128 of the critical step;
- siconos (Moreau-Jean, Coulomb friction, on the exported model): the same steps, 1/2 ... 1/64;
- ida (penalty contact, adaptive BDF): penalty 1e3 ... 1e6 EA/le, rtol 1e-10, atol 1e-13,
  friction regularised at 1e-5 m/s; converged at an observed order in kn of 0.25 or more (half the
  penalty's order 1/2: its error follows the contact's time scale sqrt(m_red / kn));
- fenicsx (the 2D plane-stress continuum, the continuum's view): Q2 elements through the depth
  1, 2, 4, 8 (square elements, so each rung halves the element), its own stable step. A different
  model (the beam's depth, shear and local indentation resolved), so its limit is shown beside the
  settled value and is never a part of it.
Each ladder is read in its asymptotic range (ladder_limit): an observed order and a Richardson limit
of its last three rungs with 1.25 times that correction as its uncertainty, or, where the rungs do
not converge monotonically, the last rung with the larger of the last two differences.
The settled value of a quantity is the midpoint of the independent references' limits (siconos,
ida), its uncertainty the largest of their half-spread and their own uncertainties; the paper
integrator's limit is a check against it, never a part of it. Quantities whose ladders do not
converge (the count of chatter bounces) are reported and not gated.

Usage: s4_settled.py [--build build] [--out reports/s4] [--runs DIR] [--jobs 2] [--angles 45,60,90]
Writes OUT/settled.json and OUT/s4_<angle>.png. Exit 2 on bad input, 1 when a run fails.
"""
import argparse
import concurrent.futures
import csv
import datetime
import json
import math
import os
import subprocess
import sys

from report_files import save_figure_atomic, write_json_atomic

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAPER_FRACTIONS = [1 / 2 ** k for k in range(1, 8)]    # 1/2 ... 1/128 of the critical step
SICONOS_FRACTIONS = [1 / 2 ** k for k in range(1, 7)]  # 1/2 ... 1/64
IDA_PENALTIES = [1e3, 1e4, 1e5, 1e6]                   # EA/le
FENICSX_DEPTHS = [1, 2, 4, 8]                          # Q2 elements through the depth
IDA_TIGHT = ["ida.rtol=1e-10", "ida.atol=1e-13", "ida.friction_velocity=1e-5"]
LINEAR = 'model.kinematics="linear"'
# The least observed order of a converged ladder: half the order the ladder's error is expected to
# have. A step ladder's error is first order or better in the step (0.5); a penalty ladder's is
# of the order of the contact's time scale sqrt(m_red / kn), order 1/2 in kn (0.25; measured on S4
# 0.43-0.70 per decade of kn).
STEP_MIN_ORDER = 0.5
PENALTY_MIN_ORDER = 0.25
# name: (unit, gated, what)
QUANTITIES = {
    "impulse_normal": ("N s", True, "total normal impulse (summary.json contacts[0].impulse_normal)"),
    "impulse_tangential": ("N s", True, "total tangential impulse (contacts[0].impulse_tangential)"),
    "ub_max": ("m", True, "largest displacement of the struck point over the window, |ub| (history.csv)"),
    "energy_final": ("J", True, "kinetic + strain energy at the end of the window (history.csv)"),
    "impacts": ("count", False, "contact intervals (chatter bounces): not gated, see the ladders"),
}


def fail(msg, code=2):
    print(f"s4_settled: {msg}", file=sys.stderr)
    sys.exit(code)


def scene_path(angle):
    return os.path.join(ROOT, "verification", "scenes", "paper", f"s4_oblique_{angle}.toml")


def run(exe, scene, method, out, sets, extra=()):
    """One `beamimpact run`, reused when its summary is there (a complete run: written last)."""
    if not os.path.exists(os.path.join(out, "summary.json")):
        cmd = [exe, "run", scene, "--method", method, "--out", out, "--quiet"] + list(extra)
        for s in sets:
            cmd += ["--set", s]
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            fail(f"{' '.join(cmd)} exited {r.returncode}: {(r.stderr or r.stdout).strip()[-300:]}", 1)
    return quantities(out)


def quantities(out):
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    with open(os.path.join(out, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    c = s["contacts"][0]
    last = rows[-1]
    return {
        "dt": s["dt"],
        "impulse_normal": c["impulse_normal"],
        "impulse_tangential": abs(c.get("impulse_tangential", 0.0)),
        "ub_max": max(math.hypot(float(r["ub_x"]), float(r["ub_y"])) for r in rows),
        "energy_final": float(last["kinetic"]) + float(last["strain"]),
        "impacts": len(c["intervals"]),
        "wall_seconds": s.get("wall_seconds"),
    }


def extrapolate(q1, q2, q3, ratio):
    """Observed order and Richardson limit of three rungs, each `ratio` times finer than the one
    before; None unless they converge monotonically (differences of one sign, shrinking)."""
    d1, d2 = q2 - q1, q3 - q2
    if d2 == 0.0:
        return None
    if d1 == 0.0 or d1 * d2 < 0.0 or abs(d2) >= abs(d1):
        return None
    p = math.log(abs(d1 / d2)) / math.log(ratio)
    return p, q3 + d2 / (ratio ** p - 1.0)


def contracting(values, from_fine_end):
    """The rungs in the ladder's asymptotic range: where each difference is smaller than the one
    before. A step ladder is read back from its finest rung (the asymptotic range is at the fine
    end); a penalty ladder from its softest rung up, until a rung moves more than the one before
    (the stiffer penalty is no longer resolved by the integration's tolerances)."""
    d = [b - a for a, b in zip(values, values[1:])]
    if from_fine_end:
        i = len(d) - 1
        while i > 0 and abs(d[i]) < abs(d[i - 1]):
            i -= 1
        return values[i:]
    i = 1
    while i < len(d) and abs(d[i]) < abs(d[i - 1]):
        i += 1
    return values[:i + 1]


def ladder_limit(values, ratio, from_fine_end=True, min_order=STEP_MIN_ORDER):
    """The limit of a ladder and its uncertainty. With three or more rungs converging monotonically
    in the asymptotic range: the Richardson limit of the last three, the uncertainty 1.25 times its
    last correction (Roache's grid convergence index for three rungs); else the
    last rung, the uncertainty the larger of the last two differences. `converged` is true only
    when the asymptotic range has three rungs or more (two differences or more, each smaller in
    size than the one before: one difference shows no contraction, so a ladder that wanders
    converges nowhere) and, where three rungs give an observed order, it is above `min_order`
    (STEP_MIN_ORDER for a step ladder, PENALTY_MIN_ORDER for a penalty ladder)."""
    rungs = contracting(values, from_fine_end)
    if len(rungs) < 2:
        return {"order": None, "limit": None, "uncertainty": None, "converged": False, "rungs_used": len(rungs)}
    diffs = [abs(b - a) for a, b in zip(rungs, rungs[1:])]
    out = {"order": None, "limit": rungs[-1], "uncertainty": max(diffs[-2:]), "converged": len(rungs) >= 3,
           "rungs_used": len(rungs)}
    last = extrapolate(*rungs[-3:], ratio) if len(rungs) >= 3 else None
    if last is not None:
        p, limit = last
        # Roache's grid convergence index: the last correction times a safety factor of 1.25.
        out.update(order=p, limit=limit, uncertainty=1.25 * abs(limit - rungs[-1]), converged=p > min_order)
    return out


def ladders(exe, angle, runs, pool):
    """Every run of one angle, submitted to the pool; returns {reference: [futures]}."""
    scene = scene_path(angle)
    d = os.path.join(runs, f"s4_{angle}")
    jobs = {"paper": [], "paper_corotational": [], "siconos": [], "ida": [], "fenicsx": []}
    for f in PAPER_FRACTIONS:
        jobs["paper"].append(pool.submit(run, exe, scene, "paper", f"{d}/paper_{f:g}",
                                         [LINEAR, f"time.fraction={f!r}"]))
        jobs["paper_corotational"].append(pool.submit(run, exe, scene, "paper", f"{d}/corot_{f:g}",
                                                      [f"time.fraction={f!r}"]))
    for f in SICONOS_FRACTIONS:
        jobs["siconos"].append(pool.submit(run, exe, scene, "siconos", f"{d}/siconos_{f:g}",
                                           [LINEAR, f"time.fraction={f!r}"]))
    for k in IDA_PENALTIES:
        jobs["ida"].append(pool.submit(run, exe, scene, "ida", f"{d}/ida_{k:g}",
                                       [LINEAR, f"ida.kn_factor={k:g}"] + IDA_TIGHT))
    for n in FENICSX_DEPTHS:
        jobs["fenicsx"].append(pool.submit(run, exe, scene, "fenicsx", f"{d}/fenicsx_{n}",
                                           [LINEAR, f"fenicsx.elements_depth={n}"]))
    return jobs


def settle(ladder_values):
    """The settled value of each quantity from the independent references' limits."""
    out = {}
    for q, (unit, gated, what) in QUANTITIES.items():
        entry = {"unit": unit, "what": what, "references": {}}
        for ref, rows in ladder_values.items():
            vals = [r[q] for r in rows]
            limit = (ladder_limit(vals, 10.0, from_fine_end=False, min_order=PENALTY_MIN_ORDER) if ref == "ida"
                     else ladder_limit(vals, 2.0))
            entry["references"][ref] = {"ladder": vals, **limit}
        ind = [entry["references"][r] for r in ("siconos", "ida")]
        ok = gated and all(r.get("converged") for r in ind)
        if ok:
            a, b = ind[0]["limit"], ind[1]["limit"]
            entry["value"] = 0.5 * (a + b)
            entry["uncertainty"] = max(0.5 * abs(a - b), ind[0]["uncertainty"], ind[1]["uncertainty"])
            paper = entry["references"]["paper"]
            if paper.get("converged"):
                entry["paper_within"] = abs(paper["limit"] - entry["value"]) <= (
                    entry["uncertainty"] + paper["uncertainty"])
            # The continuum's view: how far its finest mesh lies from the beam model's settled value.
            finest = entry["references"]["fenicsx"]["ladder"][-1]
            if entry["value"] != 0.0:
                entry["continuum_finest_offset"] = (finest - entry["value"]) / abs(entry["value"])
        entry["gated"] = ok
        if not ok:
            entry["why_not_gated"] = ("a count of chatter bounces: it changes with every step and penalty"
                                      if not gated else "an independent reference's ladder does not converge")
        out[q] = entry
    return out


def figure(angle, ladder_values, settled, out):
    """Top row: the step ladders against the step (a fraction of the critical step); middle row:
    IDA's penalty ladder; bottom row: the continuum's mesh ladder. The grey band is the settled
    value with its uncertainty."""
    quantities = ("impulse_normal", "impulse_tangential", "ub_max", "energy_final")
    fig, axes = plt.subplots(3, 4, figsize=(15, 9), constrained_layout=True)
    for col, q in enumerate(quantities):
        top, bottom, continuum = axes[0][col], axes[1][col], axes[2][col]
        for ref, xs in (("paper", PAPER_FRACTIONS), ("paper_corotational", PAPER_FRACTIONS),
                        ("siconos", SICONOS_FRACTIONS)):
            top.semilogx(xs, [r[q] for r in ladder_values[ref]], "o-", label=ref)
        bottom.semilogx(IDA_PENALTIES, [r[q] for r in ladder_values["ida"]], "k^-", label="ida")
        continuum.semilogx(FENICSX_DEPTHS, [r[q] for r in ladder_values["fenicsx"]], "rs-",
                           label="fenicsx (2D continuum)")
        s = settled[q]
        for ax in (top, bottom, continuum):
            if "value" in s:
                ax.axhspan(s["value"] - s["uncertainty"], s["value"] + s["uncertainty"], color="0.85")
                ax.axhline(s["value"], color="0.4", lw=0.8)
            ax.set_ylabel(f"{q} ({QUANTITIES[q][0]})")
        top.set_xlabel("step / critical step")
        top.invert_xaxis()
        bottom.set_xlabel("IDA penalty (EA/le)")
        continuum.set_xlabel("FEniCSx Q2 elements through the depth")
        continuum.set_xticks(FENICSX_DEPTHS, [str(n) for n in FENICSX_DEPTHS])
        continuum.minorticks_off()
    for row in axes:
        row[0].legend(fontsize=7)
    fig.suptitle(f"S4 at {angle} deg, linear kinematics (paper_corotational: as shipped): "
                 "ladders and the settled value (grey band)")
    save_figure_atomic(fig, os.path.join(out, f"s4_{angle}.png"), dpi=80)
    plt.close(fig)


def version(exe):
    r = subprocess.run([exe, "--version"], capture_output=True, text=True)
    return r.stdout.strip().split()[-1] if r.returncode == 0 and r.stdout.strip() else "unknown"


def options(doc):
    """@brief The S4 scripts' command line (--build, --out, --runs, --jobs, --angles), checked:
    (arguments, the beamimpact program, the angles, the runs folder). @param doc the script's docstring"""
    p = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--out", default=os.path.join(ROOT, "reports", "s4"))
    p.add_argument("--runs", default=None, help="run folders (default OUT/runs, not committed)")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--angles", default="45,60,90")
    a = p.parse_args()
    exe = os.path.join(a.build, "beamimpact")
    if not os.access(exe, os.X_OK):
        fail(f"{exe}: no beamimpact program (build it: bash tools/build.sh beamimpact)")
    if a.jobs < 1:
        fail(f"--jobs: expected 1 or more, got {a.jobs}")
    angles = [x.strip() for x in a.angles.split(",")]
    for x in angles:
        if x not in ("45", "60", "90"):
            fail(f"--angles: expected 45, 60 or 90, got '{x}'")
    runs = a.runs or os.path.join(a.out, "runs")
    return a, exe, angles, runs


def main():
    a, exe, angles, runs = options(__doc__)
    started = datetime.datetime.now(datetime.timezone.utc)
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        submitted = {x: ladders(exe, x, runs, pool) for x in angles}
        values = {x: {ref: [f.result() for f in fs] for ref, fs in j.items()} for x, j in submitted.items()}
    command = "/usr/bin/python3 reports/s4_settled.py " + " ".join(sys.argv[1:])
    made = started.strftime("%Y-%m-%dT%H:%M:%SZ")
    ver = version(exe)
    doc = {"command": command.strip(), "version": ver, "made": made,
           "scenes": {x: os.path.relpath(scene_path(x), ROOT) for x in angles},
           "kinematics": "linear (every ladder); paper_corotational: the shipped kinematics",
           "ladders": {"paper": PAPER_FRACTIONS, "paper_corotational": PAPER_FRACTIONS,
                       "siconos": SICONOS_FRACTIONS, "ida_penalty_EA_per_le": IDA_PENALTIES,
                       "fenicsx_elements_depth": FENICSX_DEPTHS,
                       "ida_settings": IDA_TIGHT},
           "rule": ("value = midpoint of the siconos and ida limits; uncertainty = max(half their spread, "
                    "their own Richardson uncertainties); paper's limit is a check; fenicsx (a 2D continuum, "
                    "a different model) is shown beside it as continuum_finest_offset"),
           "angles": {}}
    for x in angles:
        settled = settle(values[x])
        corot = values[x]["paper_corotational"][-1]["impulse_normal"]
        linear = values[x]["paper"][-1]["impulse_normal"]
        doc["angles"][x] = {"quantities": settled,
                            "corotational_minus_linear_impulse": (corot - linear) / linear,
                            "dt": {ref: [r["dt"] for r in rows] for ref, rows in values[x].items()}}
        figure(x, values[x], settled, a.out)
    write_json_atomic(os.path.join(a.out, "settled.json"), doc)
    for x in angles:
        for q, s in doc["angles"][x]["quantities"].items():
            if "value" in s:
                print(f"S4-{x} {q}: {s['value']:.6g} +- {s['uncertainty']:.3g} {s['unit']}"
                      f" (paper's limit within: {s.get('paper_within')};"
                      f" continuum's finest mesh {100 * s.get('continuum_finest_offset', 0.0):+.1f} %)")
            else:
                print(f"S4-{x} {q}: not gated ({s['why_not_gated']})")


if __name__ == "__main__":
    main()
