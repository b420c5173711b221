#!/usr/bin/env python3
"""@brief Convergence of impulse and peak force under dt and mesh ladders, per beam theory and
contact law, on two problems: S2 (verification/scenes/paper/s2_transverse.toml) and Timoshenko's
ball on a beam (verification/scenes/extra/ball_on_beam.toml), each with Euler-Bernoulli + hard,
Timoshenko + hard, Euler-Bernoulli + Hertz and Timoshenko + Hertz contact.

Usage: beam_theories.py [--build build] [--runs out/beam_theories] [--out reports/beam_theories]
                        [--levels 6] [--replot]

Each point is `beamimpact run` (the paper method) as a child process. S2: the dt ladder keeps the
scene's mesh and halves dt from the paper's 0.01 s; the mesh ladder doubles every body's elements
with dt = "auto". Its Hertz stiffness comes from the scene's material: a sphere of radius 0.2 m
(half of the 0.4 m depth) on a flat of the same material, k = 4/3 E* sqrt(R),
E* = E / (2 (1 - nu^2)) with nu = 0.3. The ball on a beam (a rigid steel ball on a steel beam,
Hertz law in its scene): the dt ladder keeps the scene's 200 elements and halves the fraction of
the critical step from 0.8; the mesh ladder doubles the beam's elements from 50 at dt = "auto";
its hard-law variants run a copy of the scene without the Hertz keys (written into --runs); its
Euler-Bernoulli + Hertz variant is compared with the semi-analytic reference (--method exact).

For each quantity q (impulse, peak force) the observed order between rungs h, h/2, h/4 is
log2(|q_h - q_h/2| / |q_h/2 - q_h/4|); a peak force that grows without converging is fitted
instead as q ~ h^(-a) (the log-log slope over the last three rungs). Writes OUT/ladders.json (every
rung, the version and the command), OUT/ladders.md (the tables), OUT/ladders.png (S2),
OUT/ball_on_beam.png and OUT/figures.json (the figure set the HTML report reads), all atomically.
"""
import argparse
import json
import math
import os
import subprocess
import sys

from figure_sets import manifest_figure, write_manifest
from report_files import save_figure_atomic, write_json_atomic, write_text_atomic

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COMMAND = "/usr/bin/python3 reports/beam_theories.py"
S2_SCENE = "verification/scenes/paper/s2_transverse.toml"
BALL_SCENE = "verification/scenes/extra/ball_on_beam.toml"
NU = 0.3
E = 100.0  # N/m^2, S2's material
RADIUS = 0.2  # m
MODULUS = E / (2.0 * (1.0 - NU * NU))  # E*, N/m^2
HARD_BALL = "ball_on_beam_hard.toml"  # the ball scene without its Hertz keys, written into --runs


class Problem:
    """@brief One scene under its two ladders: `variants` maps a name to (scene file, overrides);
    `dt_rung(k)` and `mesh_rung(k)` give the overrides of rung k; `dt_of` reads a rung's step size
    (h of the dt ladder); `mesh_of(k)` is the refinement of mesh rung k (h = 1 / refinement)."""

    def __init__(self, name, title, scene, variants, dt_rung, mesh_rung, mesh_of, dt_label, mesh_label):
        self.name, self.title, self.scene, self.variants = name, title, scene, variants
        self.dt_rung, self.mesh_rung, self.mesh_of = dt_rung, mesh_rung, mesh_of
        self.dt_label, self.mesh_label = dt_label, mesh_label


def s2_problem():
    timo = ["bodies.A.theory=timoshenko", "bodies.B.theory=timoshenko"]
    hertz = ["contacts[0].law=hertz", f"contacts[0].radius={RADIUS}", f"contacts[0].modulus={MODULUS!r}"]
    variants = {"EB + hard": (S2_SCENE, []), "Timoshenko + hard": (S2_SCENE, timo),
                "EB + Hertz": (S2_SCENE, hertz), "Timoshenko + Hertz": (S2_SCENE, timo + hertz)}
    elements = {"A": 5, "B": 10}
    return Problem("s2", "S2 (transverse collision)", S2_SCENE, variants,
                   lambda k: [f"time.dt={0.01 / 2 ** k!r}"],
                   lambda k: [f"bodies.{b}.elements={n * 2 ** k}" for b, n in elements.items()] + ['time.dt="auto"'],
                   lambda k: 2 ** k, "dt = 0.01 / 2^k s, scene mesh", "elements x 2^k, dt auto")


def ball_problem(runs):
    hard = os.path.join(runs, HARD_BALL)
    timo = ["bodies.B.theory=timoshenko"]  # the ball is rigid: only the beam has a theory
    variants = {"EB + hard": (hard, []), "Timoshenko + hard": (hard, timo),
                "EB + Hertz": (BALL_SCENE, []), "Timoshenko + Hertz": (BALL_SCENE, timo)}
    return Problem("ball_on_beam", "Ball on a beam (rigid ball, Hertz or hard contact)", BALL_SCENE, variants,
                   lambda k: [f"time.fraction={0.8 / 2 ** k!r}"],
                   lambda k: [f"bodies.B.elements={50 * 2 ** k}"],
                   lambda k: 2 ** k, "fraction 0.8 / 2^k of the critical step, 200 elements",
                   "50 x 2^k elements, dt auto")


def write_hard_ball(runs):
    """The ball scene with law = "hard" (the default): its contact's law, radius and modulus lines
    dropped, every other line as committed."""
    os.makedirs(runs, exist_ok=True)
    with open(BALL_SCENE) as f:
        lines = f.readlines()
    keep = [ln for ln in lines if ln.split("=")[0].strip() not in ("law", "radius", "modulus")]
    if len(lines) - len(keep) != 3:
        sys.exit(f"beam_theories: {BALL_SCENE}: expected one law, radius and modulus line each in [[contacts]]")
    write_text_atomic(os.path.join(runs, HARD_BALL), "".join(keep))


def run(exe, scene, out, sets, method="paper"):
    """Runs `method` on `scene` with the overrides; returns its summary.json."""
    if not os.path.exists(os.path.join(out, "summary.json")):
        cmd = [exe, "run", scene, "--out", out, "--quiet", "--allow-long", "--method", method]
        for s in sets + ["output.history=false"]:
            cmd += ["--set", s]
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"beam_theories: {' '.join(cmd)} failed: {r.stderr.strip()}")
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def quantities(summary, hertz):
    c = summary["contacts"][0]
    # The hard law's closure step carries the impact impulse m v / dt as a "force": its peak is
    # taken without the closure steps; the Hertz law has no closure impulse.
    peak = c["peak_R"] if hertz else c["peak_R_excluding_closure"]
    return {"impulse": c["impulse_normal"], "peak": peak, "intervals": len(c["intervals"]),
            "durations": [b - a for a, b in c["intervals"]], "dt": summary.get("dt")}


def orders(values):
    """Observed orders log2(|q_h - q_h/2| / |q_h/2 - q_h/4|) along a halving ladder."""
    out = []
    for a, b, c in zip(values, values[1:], values[2:]):
        d1, d2 = abs(a - b), abs(b - c)
        out.append(math.log2(d1 / d2) if d1 > 0 and d2 > 0 else None)
    return out


def growth_exponent(steps, values):
    """a in q ~ step^(-a) from the last three rungs (least squares in log-log)."""
    xs = [math.log(s) for s in steps[-3:]]
    ys = [math.log(v) for v in values[-3:]]
    mx, my = sum(xs) / 3, sum(ys) / 3
    return -sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def variant_ladders(exe, runs, prob, name, levels):
    scene, sets = prob.variants[name]
    hertz = "Hertz" in name
    tag = os.path.join(runs, prob.name, name.replace(" + ", "_").replace(" ", "").lower())
    dt_rungs = [quantities(run(exe, scene, os.path.join(tag, f"dt{k}"), sets + prob.dt_rung(k)), hertz)
                for k in range(levels)]
    mesh_rungs = [dict(refinement=prob.mesh_of(k), **quantities(
        run(exe, scene, os.path.join(tag, f"mesh{k}"), sets + prob.mesh_rung(k)), hertz)) for k in range(min(levels, 5))]
    entry = {"scene": scene, "sets": sets, "dt_ladder": dt_rungs, "mesh_ladder": mesh_rungs}
    for lad in ("dt_ladder", "mesh_ladder"):
        rungs = entry[lad]
        for q in ("impulse", "peak"):
            entry[f"{lad}.{q}.orders"] = orders([r[q] for r in rungs])
        steps = [r["dt"] if lad == "dt_ladder" else 1.0 / r["refinement"] for r in rungs]
        entry[f"{lad}.peak.growth_exponent"] = growth_exponent(steps, [r["peak"] for r in rungs])
    return entry


def measure(exe, runs, levels):
    write_hard_ball(runs)
    data = {}
    for prob in (s2_problem(), ball_problem(runs)):
        data[prob.name] = {"title": prob.title, "dt_ladder": prob.dt_label, "mesh_ladder": prob.mesh_label,
                           "variants": {n: variant_ladders(exe, runs, prob, n, levels) for n in prob.variants}}
        print(f"beam_theories: {prob.name} done", file=sys.stderr, flush=True)
    ref = run(exe, BALL_SCENE, os.path.join(runs, "ball_on_beam", "exact"), [], method="exact")
    data["ball_on_beam"]["exact"] = dict(quantities(ref, True), modes=ref["contacts"][0]["modes"])
    return data


def fmt(x, spec=".3g"):
    return "-" if x is None else format(x, spec)


def table_rows(prob):
    rows = []
    for name, e in prob["variants"].items():
        for lad in ("dt_ladder", "mesh_ladder"):
            r = e[lad][-1]
            rows.append([name, lad.split("_")[0], f"{r['impulse']:.6g}", ", ".join(fmt(o, ".2f") for o in e[f"{lad}.impulse.orders"]),
                         f"{r['peak']:.4g}", ", ".join(fmt(o, ".2f") for o in e[f"{lad}.peak.orders"]),
                         f"{e[f'{lad}.peak.growth_exponent']:.2f}", str(r["intervals"])])
    if "exact" in prob:
        x = prob["exact"]
        rows.append([f"exact (EB + Hertz, {x['modes']} modes)", "-", f"{x['impulse']:.6g}", "-", f"{x['peak']:.4g}",
                     "-", "-", str(x["intervals"])])
    return rows


COLUMNS = ["variant", "ladder", "impulse, finest (N s)", "impulse orders", "peak, finest (N)", "peak orders",
           "peak ~ h^-a, a", "contacts, finest"]


EXACT_COLUMNS = ["run", "contacts", "contact durations (us)", "impulse (N s)", "impulse error", "peak (N)",
                 "peak error"]


def exact_rows(prob):
    """The ball on a beam, Euler-Bernoulli + Hertz, against the semi-analytic reference: every mesh
    rung and the dt ladder's finest, with the contacts, their durations and the relative errors."""
    x, e = prob["exact"], prob["variants"]["EB + Hertz"]
    runs = [(f"{50 * r['refinement']} elements, dt auto", r) for r in e["mesh_ladder"]]
    runs.append((f"200 elements, dt {e['dt_ladder'][-1]['dt']:.3g} s", e["dt_ladder"][-1]))
    rows = [[label, str(r["intervals"]), ", ".join(f"{d * 1e6:.2f}" for d in r["durations"]), f"{r['impulse']:.6g}",
             f"{r['impulse'] / x['impulse'] - 1:+.1e}", f"{r['peak']:.6g}", f"{r['peak'] / x['peak'] - 1:+.1e}"]
            for label, r in runs]
    rows.append([f"exact ({x['modes']} modes)", str(x["intervals"]), ", ".join(f"{d * 1e6:.2f}" for d in x["durations"]),
                 f"{x['impulse']:.6g}", "", f"{x['peak']:.6g}", ""])
    return rows


def md_table(columns, rows):
    return "".join(["| " + " | ".join(columns) + " |\n", "|" + "---|" * len(columns) + "\n"]
                   + ["| " + " | ".join(r) + " |\n" for r in rows])


def markdown(data, version):
    out = [f"Made by `{COMMAND}`, beamimpact {version}.\n"]
    for prob in data["problems"].values():
        out += [f"\n## {prob['title']}\n\ndt ladder: {prob['dt_ladder']}; mesh ladder: {prob['mesh_ladder']}.\n\n",
                md_table(COLUMNS, table_rows(prob))]
        if "exact" in prob:
            out += ["\nEuler-Bernoulli + Hertz against the semi-analytic reference:\n\n",
                    md_table(EXACT_COLUMNS, exact_rows(prob))]
    return "".join(out)


def draw(prob):
    """@brief The peak force of every variant under the dt ladder (left) and the mesh ladder (right),
    every label inside the image (constrained layout); how it was made is the manifest's caption.
    @return the matplotlib figure"""
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4), layout="constrained")
    for name, e in prob["variants"].items():
        axes[0].loglog([r["dt"] for r in e["dt_ladder"]], [r["peak"] for r in e["dt_ladder"]], "o-", label=name)
        axes[1].loglog([r["refinement"] for r in e["mesh_ladder"]], [r["peak"] for r in e["mesh_ladder"]], "o-",
                       label=name)
    if "exact" in prob:
        for ax in axes:
            ax.axhline(prob["exact"]["peak"], color="k", ls=":", lw=1, label="exact (EB + Hertz)")
    axes[0].set_xlabel(f"dt (s): {prob['dt_ladder']}")
    axes[0].invert_xaxis()
    axes[1].set_xlabel(f"mesh refinement: {prob['mesh_ladder']}")
    for ax, what in zip(axes, ("dt", "mesh")):
        ax.set_ylabel("peak contact force (N)")
        ax.set_title(f"{prob['title']}: peak force vs {what}", fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    return fig


def plot(prob, path):
    """@brief draw() saved to `path`."""
    fig = draw(prob)
    save_figure_atomic(fig, path, dpi=110)
    plt.close(fig)


PNG = {"s2": "ladders.png", "ball_on_beam": "ball_on_beam.png"}
SCENES = {"s2": S2_SCENE, "ball_on_beam": BALL_SCENE + " (hard variants: its Hertz keys removed)"}


def write_figures_json(path, data):
    """@brief The figure set's manifest (figures.json): the tables, and per figure its command, scene,
    version, date and caption (the two ladders)."""
    probs = data["problems"]
    write_manifest(
        path, "Beam theories and contact laws: do impulse and peak force converge?",
        [manifest_figure(PNG[n], f"{probs[n]['title']}: peak force under dt and mesh ladders", COMMAND, SCENES[n],
                         data["version"], f"dt ladder: {probs[n]['dt_ladder']}; mesh ladder: {probs[n]['mesh_ladder']}.")
         for n in probs],
        about="The paper integrator under dt and mesh ladders with Euler-Bernoulli or Timoshenko beams and the "
              "hard (paper's) or Hertz contact law. With the hard law the peak force excludes the closure "
              "steps (their force is the impact impulse over one step). Observed orders "
              "log2(|q_h - q_h/2| / |q_h/2 - q_h/4|) along each ladder; a, the exponent of a fit peak ~ h^-a "
              "over the last three rungs (h = dt or 1 / refinement).",
        tables=[{"title": probs[n]["title"], "columns": COLUMNS, "rows": table_rows(probs[n])} for n in probs]
        + [{"title": "Ball on a beam, Euler-Bernoulli + Hertz, against the semi-analytic reference "
                     "(references/exact/BallOnBeam.hpp)", "columns": EXACT_COLUMNS,
            "rows": exact_rows(probs["ball_on_beam"])}])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--runs", default="out/beam_theories")
    ap.add_argument("--out", default="reports/beam_theories")
    ap.add_argument("--levels", type=int, default=6)
    ap.add_argument("--replot", action="store_true", help="re-plot OUT/ladders.json without running")
    a = ap.parse_args()
    if a.levels < 3:
        sys.exit(f"beam_theories: --levels {a.levels}: expected an integer >= 3 (an order needs three rungs)")
    os.makedirs(a.out, exist_ok=True)
    js = os.path.join(a.out, "ladders.json")
    if a.replot:
        with open(js) as f:
            data = json.load(f)
    else:
        exe = os.path.join(a.build, "beamimpact")
        if not os.access(exe, os.X_OK):
            sys.exit(f"beam_theories: no {exe}; build first (tools/build.sh)")
        version = subprocess.run([exe, "--version"], capture_output=True, text=True).stdout.strip()
        data = {"command": COMMAND, "version": version, "problems": measure(exe, a.runs, a.levels)}
        write_json_atomic(js, data)
    write_text_atomic(os.path.join(a.out, "ladders.md"), markdown(data, data["version"]))
    for n, prob in data["problems"].items():
        plot(prob, os.path.join(a.out, PNG[n]))
    write_figures_json(os.path.join(a.out, "figures.json"), data)
    print(markdown(data, data["version"]))


if __name__ == "__main__":
    main()
