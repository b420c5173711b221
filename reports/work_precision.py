#!/usr/bin/env python3
"""@brief Work-precision sets of the paper's scenes: every method that accepts a scene as its own
curve (the paper integrator over dt and mesh ladders, IDA over rtol, FEniCSx over meshes, Siconos over meshes, the exact
solution over its mode count), error against the best available reference vs the CPU time of the run.

Usage: work_precision.py [--scenes s1_central,...] [--repeats 3] [--out reports/work_precision]
                         [--runs out/work_precision] [--build build] [--quick] [--replot]

Each point is `beamimpact run` as a child process, run `--repeats` times one after another
(`--jobs 1`: nothing else of ours runs meanwhile); its CPU time is the child's user + system time
from os.wait4 (its own children, the FEniCSx Python process, included). The error comes from
`beamimpact compare RUN REFERENCE --json` (impulse, and ub.rel_l2: the struck point's
displacement). Writes OUT/<scene>/work_precision.json and .png, OUT/figures.json (the manifest the
HTML report reads) and OUT/equal_error.md (ratios of CPU time at equal error). Progress goes to
stderr: scene, rung, elapsed and estimated time left. --quick: one scene, two rungs per method.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import textwrap
import time
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PAPER = "verification/scenes/paper"
ERRORS = ("impulse", "ub.rel_l2")  # norm names owned by verification/compare (compare_runs.cc)
ERROR_LABEL = {"impulse": "relative impulse error", "ub.rel_l2": "rel. L2 error of the struck point's displacement"}
EQUAL_ERROR_LEVELS = (3e-2, 1e-2, 3e-3)  # relative impulse error at which CPU times are compared


def fail(msg):
    print(f"work_precision: {msg}", file=sys.stderr)
    sys.exit(2)


class Plan:
    """The rungs of one scene: (method label, setting label, beamimpact run arguments)."""

    def __init__(self, name, reference, rungs, reference_note):
        self.name, self.reference, self.rungs, self.reference_note = name, reference, rungs, reference_note


def scene_info(path):
    with open(path, "rb") as f:
        sc = tomllib.load(f)
    return sc["time"]["dt"], {b["name"]: b["elements"] for b in sc["bodies"]}


def mesh_sets(elements, mult):
    return [f"bodies.{n}.elements={e * mult}" for n, e in elements.items()]


def plan_for(name, quick):
    path = f"{PAPER}/{name}.toml"
    dt, elements = scene_info(path)
    rungs = []
    # Paper integrator: a dt ladder at the scene's mesh, then a mesh ladder.
    if dt == "auto":
        for f in (0.5, 0.25, 0.125)[: 2 if quick else 3]:
            rungs.append(("paper (dt ladder)", f"fraction {f}", ["--set", f"time.fraction={f}"]))
        for m in (2, 4)[: 1 if quick else 2]:
            rungs.append(("paper (mesh ladder)", f"mesh x{m}, fraction 0.5",
                          sum((["--set", s] for s in mesh_sets(elements, m)), [])))
    else:
        for k in (1, 2, 4)[: 2 if quick else 3]:
            rungs.append(("paper (dt ladder)", f"dt {dt / k:g}", ["--set", f"time.dt={dt / k!r}"]))
        for m in (2, 4, 8, 16, 32)[: 1 if quick else 5]:
            # Bending meshes shrink the stable step like h^2: the mesh rungs take half the critical step.
            sets = mesh_sets(elements, m) + ['time.dt="auto"', "time.fraction=0.5"]
            rungs.append(("paper (mesh ladder)", f"mesh x{m}, half critical dt", sum((["--set", s] for s in sets), [])))
    # IDA: same beam model, rtol ladder at the scene's mesh.
    for r in (1e-4, 1e-6, 1e-8)[: 2 if quick else 3]:
        rungs.append(("IDA (rtol ladder)", f"rtol {r:g}", ["--method", "ida", "--set", f"ida.rtol={r:g}"]))
    if not quick:
        rungs.append(("IDA (mesh x2)", "mesh x2, rtol 1e-6", ["--method", "ida", "--set", "ida.rtol=1e-6"]
                      + sum((["--set", s] for s in mesh_sets(elements, 2)), [])))
    # FEniCSx: the 2D continuum over its mesh presets.
    for m in ("coarse", "default", "fine")[: 1 if quick else 3]:
        rungs.append(("FEniCSx (meshes)", f"mesh {m}", ["--method", "fenicsx", "--mesh", m]))
    # Siconos (outside solver, verification/methods.toml): Moreau-Jean on the exported model, a mesh
    # ladder with the step scaled with the element. It refuses S4's corotational kinematics.
    if not name.startswith("s4"):
        for m in (1, 2, 4)[: 1 if quick else 3]:
            rungs.append(("Siconos (mesh ladder)", f"mesh x{m}, dt {dt / m:g}",
                          ["--method", "siconos", "--mesh", str(m), "--dt", repr(dt / m)]))
    # The exact solution over its mode count (rod on beam only; S1's rods are exact at roundoff).
    if name.startswith(("s2", "s3")):
        for n in (8, 16, 32)[: 1 if quick else 3]:
            rungs.append(("exact (modes)", f"{n} modes", ["--method", "exact", "--set", f"exact.modes={n}"]))
    if name.startswith("s4"):
        # No exact solution accepts S4 (friction, oblique): the reference is a converged fine run of
        # the independent time integrator (IDA, same beam model) on a finer mesh.
        ref = ["--method", "ida", "--set", "ida.rtol=1e-9"] + sum((["--set", s] for s in mesh_sets(elements, 4)), [])
        note = "IDA, mesh x4, rtol 1e-9 (converged fine run; no exact solution for S4)"
    else:
        ref = ["--method", "exact"]
        note = "exact (references/exact: " + ("d'Alembert rods" if name.startswith("s1") else "rod on beam, converged modes") + ")"
    return Plan(name, ref, rungs, note)


def run_timed(exe, scene, args, out):
    """One `beamimpact run`: (exit code, CPU s of the child and its waited-for children, wall s).
    External methods (FEniCSx) run through it too, as their methods file says."""
    cmd = [exe, "run", scene, "--out", out, "--quiet"] + args
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = p.stderr.read().decode(errors="replace")
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    p.returncode = os.waitstatus_to_exitcode(status)
    return p.returncode, ru.ru_utime + ru.ru_stime, wall, err.strip()[-400:]


def compare(exe, run_dir, ref_dir):
    js = os.path.join(run_dir, "compare.json")
    r = subprocess.run([exe, "compare", run_dir, ref_dir, "--json", js], capture_output=True, text=True)
    if r.returncode not in (0, 1):
        return None, r.stderr.strip()[-300:]
    with open(js) as f:
        norms = {n["name"]: n.get("value") for n in json.load(f)["norms"]}
    return {k: norms.get(k) for k in ERRORS}, ""


class Progress:
    def __init__(self, total):
        self.total, self.done, self.t0 = total, 0, time.monotonic()

    def line(self, scene, rung):
        el = time.monotonic() - self.t0
        left = el / self.done * (self.total - self.done) if self.done else float("nan")
        print(f"[work-precision] {scene}: rung {self.done + 1}/{self.total} {rung} | elapsed {el:.0f} s, "
              f"~{left:.0f} s left", file=sys.stderr, flush=True)


def measure_scene(a, plan, progress, version):
    scene = f"{PAPER}/{plan.name}.toml"
    runs = os.path.join(a.runs, plan.name)
    os.makedirs(runs, exist_ok=True)
    ref_dir = os.path.join(runs, "reference")
    progress.line(plan.name, "reference: " + plan.reference_note)
    code, cpu, wall, err = run_timed(a.exe, scene, plan.reference, ref_dir)
    progress.done += 1
    if code != 0:
        fail(f"{plan.name}: the reference run failed (exit {code}): {err}")
    points = []
    for k, (method, setting, args) in enumerate(plan.rungs):
        progress.line(plan.name, f"{method}: {setting}")
        out = os.path.join(runs, f"rung{k:02d}")
        cpus, walls, load, note = [], [], [], ""
        for rep in range(a.repeats):
            load.append(os.getloadavg()[0])
            code, cpu, wall, err = run_timed(a.exe, scene, args, out)
            if code != 0:
                note = f"exit {code}: {err}"
                break
            cpus.append(cpu)
            walls.append(wall)
        progress.done += 1
        p = {"method": method, "setting": setting, "args": args, "loadavg_1min": load}
        if note:
            p.update(status="failed", note=note)
            print(f"[work-precision]   {note}", file=sys.stderr)
        else:
            errors, why = compare(a.exe, out, ref_dir)
            p.update(status="ok" if errors else "failed", error=errors, note=why, cpu_seconds_min=min(cpus),
                     cpu_seconds_all=cpus, wall=min(walls), wall_all=walls)
        points.append(p)
    cmd = f"/usr/bin/python3 reports/work_precision.py --scenes {plan.name} --repeats {a.repeats}"
    return {"scene": scene, "reference": plan.reference_note, "reference_args": plan.reference, "version": version,
            "command": cmd, "repeats": a.repeats, "jobs": 1, "points": points, "cpu_time": "user + system of the "
            "child (os.wait4), FEniCSx's Python included", "equal_error": equal_error(points)}


def front(points, method, key):
    """(cpu, error) pairs of one method, sorted by CPU time, only those that improve the error."""
    pts = sorted((p["cpu_seconds_min"], p["error"][key]) for p in points
                 if p["status"] == "ok" and p["method"].split(" (")[0] == method and p["error"][key])
    out = []
    for c, e in pts:
        if not out or e < out[-1][1]:
            out.append((c, e))
    return out


def cpu_at(fr, level):
    """(CPU time at which the front first reaches `level` by log-log interpolation, bounded) or
    (None, False). bounded: already reached at the cheapest rung, whose cost is then an upper bound."""
    if fr and fr[0][1] <= level:
        return fr[0][0], True
    for (c0, e0), (c1, e1) in zip(fr, fr[1:]):
        if e0 >= level >= e1:
            w = math.log(e0 / level) / math.log(e0 / e1) if e0 != e1 else 0.0
            return math.exp(math.log(c0) + w * (math.log(c1) - math.log(c0))), False
    return None, False


def equal_error(points):
    """Per impulse-error level: each method's CPU time to reach it and its ratio to the paper integrator's.
    "<=": the method is below the level at its cheapest rung already, so that rung's cost bounds it."""
    methods = ["paper"] + sorted({p["method"].split(" (")[0] for p in points} - {"paper"})
    res = []
    for level in EQUAL_ERROR_LEVELS:
        cpu = {m: cpu_at(front(points, m, "impulse"), level) for m in methods}
        paper = cpu["paper"][0]
        parts = []
        entry = {"impulse_error": level, "cpu_s": {}, "upper_bound": {}, "ratio_to_paper": {}}
        for m in methods:
            c, bound = cpu[m]
            entry["cpu_s"][m], entry["upper_bound"][m] = c, bound
            if c is None:
                parts.append(f"{m} not reached")
                continue
            txt = f"{m} {'<=' if bound else ''}{c:.3g} s"
            if m != "paper" and paper:
                entry["ratio_to_paper"][m] = c / paper
                txt += f" ({c / paper:.3g} x the paper's)"
            parts.append(txt)
        entry["text"] = f"at {level:.1%} impulse error, CPU time: " + "; ".join(parts)
        res.append(entry)
    return res


def plot(res, png):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.8))
    fig.subplots_adjust(left=0.07, right=0.98, bottom=0.27, top=0.9, wspace=0.25)
    methods = []
    for p in res["points"]:
        if p["method"] not in methods:
            methods.append(p["method"])
    for ax, key in zip(axes, ERRORS):
        for i, m in enumerate(methods):
            pts = [p for p in res["points"] if p["method"] == m and p["status"] == "ok" and p["error"][key]]
            if not pts:
                continue
            xs = [p["cpu_seconds_min"] for p in pts]
            ys = [p["error"][key] for p in pts]
            lo = [x - x for x in xs]
            hi = [max(p["cpu_seconds_all"]) - p["cpu_seconds_min"] for p in pts]
            ax.errorbar(xs, ys, xerr=[lo, hi], fmt="o-" if "ladder" in m or "modes" in m else "s--",
                        ms=4, capsize=2, label=m, color=f"C{i}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("CPU time of the run (s, min of repeats; bar to max)")
        ax.set_ylabel(ERROR_LABEL[key])
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle(f"{os.path.basename(res['scene'])}: work-precision against {res['reference']}", fontsize=9)
    loads = [x for p in res["points"] for x in p["loadavg_1min"]]
    foot = textwrap.wrap(res["command"], 150) + textwrap.wrap(
        f"scene {res['scene']} | reference {res['reference']} | beamimpact {res['version']} | "
        f"{res['repeats']} timings per point, --jobs 1 | load average during timing {min(loads):.1f}-{max(loads):.1f}", 150)
    fig.text(0.01, 0.01, "\n".join(foot), fontsize=6.5, family="monospace", va="bottom")
    fig.savefig(png, dpi=100)
    plt.close(fig)


def write_manifest(out, version):
    figs, rows = [], []
    for name in sorted(os.listdir(out)):
        js = os.path.join(out, name, "work_precision.json")
        if not os.path.isfile(js):
            continue
        with open(js) as f:
            res = json.load(f)
        figs.append({"png": f"{name}/work_precision.png", "title": f"{name}: work-precision",
                     "command": res["command"], "scene": res["scene"], "version": res["version"],
                     "caption": f"Reference: {res['reference']}. Left: impulse, right: struck-point displacement."})
        rows += [[name, e["text"]] for e in res["equal_error"]]
    with open(os.path.join(out, "figures.json"), "w") as f:
        json.dump({"title": "Work-precision sets (what accuracy costs in CPU time)",
                   "about": "Each point: one `beamimpact run`, timed 3 times one after another (CPU time of the "
                            "child process from wait4, minimum and spread); error against the reference named "
                            "on each figure. Ratios at equal impulse error below (log-log interpolation along "
                            "each method's front).",
                   "tables": [{"title": "CPU time at equal impulse error", "columns": ["scene", "finding"],
                               "rows": rows}],
                   "figures": figs}, f, indent=1)
    with open(os.path.join(out, "equal_error.md"), "w") as f:
        f.write("# CPU time at equal impulse error\n\nMade by `reports/work_precision.py` (beamimpact "
                f"{version}); per-scene commands in each work_precision.json.\n\n| scene | finding |\n|---|---|\n")
        f.writelines(f"| {r[0]} | {r[1]} |\n" for r in rows)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scenes", default="s1_central,s2_transverse,s3_surface_10,s3_surface_20,"
                                       "s4_oblique_90,s4_oblique_60,s4_oblique_45")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--out", default="reports/work_precision")
    p.add_argument("--runs", default="out/work_precision")
    p.add_argument("--build", default=os.environ.get("BEAMIMPACT_BUILD_DIR", "build"))
    p.add_argument("--quick", action="store_true")
    p.add_argument("--replot", action="store_true", help="only redraw the PNGs and the manifest from the JSON in --out")
    a = p.parse_args()
    if a.replot:
        for s in a.scenes.split(","):
            js = os.path.join(a.out, s, "work_precision.json")
            if not os.path.isfile(js):
                fail(f"--replot: {js} not found (measure first)")
            with open(js) as f:
                res = json.load(f)
            res["equal_error"] = equal_error(res["points"])
            with open(js, "w") as f:
                json.dump(res, f, indent=1)
            plot(res, os.path.join(a.out, s, "work_precision.png"))
            version = res["version"]
        write_manifest(a.out, version)
        return
    if a.repeats < 1:
        fail(f"--repeats {a.repeats}: expected an integer >= 1")
    a.exe = os.path.join(a.build, "beamimpact")
    if not os.access(a.exe, os.X_OK):
        fail(f"--build {a.build}: no beamimpact program there (build first: bash tools/build.sh)")
    version = subprocess.run([a.exe, "--version"], capture_output=True, text=True).stdout.strip()
    plans = []
    for s in a.scenes.split(","):
        if not os.path.isfile(f"{PAPER}/{s}.toml"):
            fail(f"--scenes: '{s}' is not a scene in {PAPER}/ (expected a file name without .toml)")
        plans.append(plan_for(s, a.quick))
    progress = Progress(sum(len(pl.rungs) + 1 for pl in plans))
    for pl in plans:
        res = measure_scene(a, pl, progress, version)
        d = os.path.join(a.out, pl.name)
        os.makedirs(d, exist_ok=True)
        tmp = os.path.join(d, "work_precision.json.tmp")
        with open(tmp, "w") as f:
            json.dump(res, f, indent=1)
        os.replace(tmp, os.path.join(d, "work_precision.json"))
        plot(res, os.path.join(d, "work_precision.png"))
        for e in res["equal_error"]:
            print(f"[work-precision] {pl.name}: {e['text']}", file=sys.stderr)
    write_manifest(a.out, version)


if __name__ == "__main__":
    main()
