#!/usr/bin/env python3
"""@brief Work-precision sets of the paper's scenes: every method that accepts a scene as its own
curve (the paper integrator over dt and mesh ladders, IDA over rtol, FEniCSx over meshes, Siconos over meshes, the exact
solution over its mode count), error against the best available reference vs the CPU time of the run.

Usage: work_precision.py [--scenes s1_central,...] [--sizes all|s1_central_x100,...] [--repeats 3]
                         [--out reports/work_precision] [--runs out/work_precision] [--build build]
                         [--quick] [--replot]

In-process methods (paper, ida, exact) run through the Python module of --build: each point is
beamimpact.run() called at least 3 times and until 0.2 s have passed (wp_timing.py), its CPU time
from time.process_time, wall from time.perf_counter, minimum and maximum kept with every
repetition and the load average. Their start-up is measured apart: the cheapest rung of each
run once more as a `beamimpact run` process. Outside methods (FEniCSx, Siconos) run as
`beamimpact run` child processes, `--repeats` times, CPU = user + system of the child and its
children (os.wait4), start-up included; `beamimpact --version`, `python3 -c pass` and each outside
method's check command (interpreter and library import) are timed and shown beside them, never
subtracted. The error: beamimpact.compare against the reference (impulse, and ub.rel_l2: the
struck point's displacement). --sizes: S1 and S2 with every body's elements multiplied (about
1e3 to 1e4 DOFs), paper vs IDA vs Siconos against the exact solution. Writes
OUT/<set>/work_precision.json and .png, OUT/figures.json (the manifest the HTML report reads) and
OUT/equal_error.md (ratios of CPU time at equal error with their range over the repeats, and the
start-ups). Progress goes to stderr: set, rung, elapsed and estimated time left. --quick: two
rungs per in-process method, one Siconos rung, no FEniCSx.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time
import tomllib

import wp_figures
import wp_timing
from report_files import write_json_atomic
from wp_figures import ERRORS

bi = None  # the beamimpact module of --build, imported in main()

PAPER = "verification/scenes/paper"
IN_PROCESS = ("paper", "ida", "exact")  # registry methods run through the Python module
OUTSIDE = ("fenicsx", "siconos")  # methods of verification/methods.toml on the diagrams (processes)
FENICSX_CMD = ["/usr/bin/python3", "references/fenicsx/run.py"]  # as verification/methods.toml runs it
EQUAL_ERROR_LEVELS = (3e-2, 1e-2, 1e-3)  # relative impulse error at which CPU times are compared


def fail(msg):
    print(f"work_precision: {msg}", file=sys.stderr)
    sys.exit(2)


class Rung:
    """One point of a curve: method label, setting label, registry method, scene overrides
    ({key: value} as --set key=value) and command-line options of outside methods (--mesh, --dt)."""

    def __init__(self, label, setting, method, overrides, cli=(), repeats=None):
        self.label, self.setting, self.method, self.overrides, self.cli = label, setting, method, overrides, list(cli)
        self.repeats = repeats  # process timings of this rung (None: --repeats)

    def in_process(self):
        return self.method in IN_PROCESS

    def args(self, base):
        """The `beamimpact run` options of this rung on a scene with overrides `base`."""
        sets = dict(base, **self.overrides)
        return (["--method", self.method] if self.method != "paper" else []) + sum(
            (["--set", f"{k}={toml_value(v)}"] for k, v in sets.items()), []) + self.cli


class Plan:
    """The rungs of one set: its name, the scene file and the overrides every rung shares."""

    def __init__(self, name, path, base, reference, rungs, reference_note, not_run=None):
        self.name, self.path, self.base, self.reference = name, path, base, reference
        self.rungs, self.reference_note = rungs, reference_note
        self.not_run = not_run or {}  # method -> why it has no rung in this set (said, not hidden)


def toml_value(v):
    return json.dumps(v) if isinstance(v, str) else repr(v)


def scene_info(path):
    with open(path, "rb") as f:
        sc = tomllib.load(f)
    return sc["time"]["dt"], {b["name"]: b["elements"] for b in sc["bodies"]}


def mesh_sets(elements, mult):
    return {f"bodies.{n}.elements": e * mult for n, e in elements.items()}


def plan_for(name, quick):
    path = f"{PAPER}/{name}.toml"
    dt, elements = scene_info(path)
    rungs = []
    # Paper integrator: a dt ladder at the scene's mesh, then a mesh ladder.
    if dt == "auto":
        for f in (0.5, 0.25, 0.125)[: 2 if quick else 3]:
            rungs.append(Rung("paper (dt ladder)", f"fraction {f}", "paper", {"time.fraction": f}))
        for m in (2, 4)[: 1 if quick else 2]:
            rungs.append(Rung("paper (mesh ladder)", f"mesh x{m}, fraction 0.5", "paper", mesh_sets(elements, m)))
    else:
        for k in (1, 2, 4)[: 2 if quick else 3]:
            rungs.append(Rung("paper (dt ladder)", f"dt {dt / k:g}", "paper", {"time.dt": dt / k}))
        for m in (2, 4, 8, 16, 32)[: 1 if quick else 5]:
            # Bending meshes shrink the stable step like h^2: the mesh rungs take half the critical step.
            sets = dict(mesh_sets(elements, m), **{"time.dt": "auto", "time.fraction": 0.5})
            rungs.append(Rung("paper (mesh ladder)", f"mesh x{m}, half critical dt", "paper", sets))
    # IDA: same beam model, rtol ladder at the scene's mesh.
    for r in (1e-4, 1e-6, 1e-8)[: 2 if quick else 3]:
        rungs.append(Rung("IDA (rtol ladder)", f"rtol {r:g}", "ida", {"ida.rtol": r}))
    if not quick:
        rungs.append(Rung("IDA (mesh x2)", "mesh x2, rtol 1e-6", "ida", dict(mesh_sets(elements, 2), **{"ida.rtol": 1e-6})))
    # FEniCSx: the 2D continuum over its mesh presets (an outside program: timed as a process).
    for m in ("coarse", "default", "fine")[: 0 if quick else 3]:
        rungs.append(Rung("FEniCSx (meshes)", f"mesh {m}", "fenicsx", {}, ["--mesh", m]))
    # Siconos (outside solver, verification/methods.toml): Moreau-Jean on the exported model, a mesh
    # ladder with the step scaled with the element. It refuses S4's corotational kinematics.
    if not name.startswith("s4"):
        for m in (1, 2, 4)[: 1 if quick else 3]:
            rungs.append(Rung("Siconos (mesh ladder)", f"mesh x{m}, dt {dt / m:g}", "siconos", {},
                              ["--mesh", str(m), "--dt", repr(dt / m)]))
    # The exact solution over its mode count (rod on beam only; S1's rods are exact at roundoff).
    if name.startswith(("s2", "s3")):
        for n in (8, 16, 32)[: 1 if quick else 3]:
            rungs.append(Rung("exact (modes)", f"{n} modes", "exact", {"exact.modes": n}))
    if name.startswith("s4"):
        # No exact solution accepts S4 (friction, oblique): the reference is a converged fine run of
        # the independent time integrator (IDA, same beam model) on a finer mesh.
        ref = Rung("reference", "", "ida", dict(mesh_sets(elements, 4), **{"ida.rtol": 1e-9}))
        note = "IDA, mesh x4, rtol 1e-9 (converged fine run; no exact solution for S4)"
    else:
        ref = Rung("reference", "", "exact", {})
        note = "exact (references/exact: " + ("d'Alembert rods" if name.startswith("s1") else "rod on beam, converged modes") + ")"
    return Plan(name, path, {}, ref, rungs, note)


def hours_at(base, mult, power):
    """Hours of CPU a run takes at mesh multiplier `mult`, from one measured at base = (CPU s,
    multiplier) and a cost that grows like the multiplier to `power`."""
    return base[0] * (mult / base[1]) ** power / 3600


def sized_plan(name, mult, quick):
    """S1 or S2 with every body's elements times `mult` (the sizes where cost matters): the paper
    integrator over fractions of the critical step, IDA over rtol, Siconos at the same mesh over
    its step; the exact solution (independent of the mesh) as the reference. Where a method's
    runs would take hours it has no rung, and the set says why (`not_run`)."""
    path = f"{PAPER}/{name}.toml"
    dt, elements = scene_info(path)
    base = mesh_sets(elements, mult)
    # The paper's cost grows like mult^2 (steps and DOFs both grow with the mesh): S1 x5000
    # (1e5 DOFs) is about 70 s of CPU at 0.9 of the critical step, so that size gets that rung only
    # (its error is already far below the levels of the equal-error table).
    # S2 x222 (1e4 DOFs) about 340 s: the bending limit falls like h^2, so S2's steps grow like
    # mult^2 and its cost like mult^3.
    one_rung = mult >= 1000 or (name.startswith("s2") and mult > 100)
    fractions = (0.9,) if one_rung else (0.9, 0.5, 0.25)[: 2 if quick else 3]
    rungs = [Rung("paper (dt ladder)", f"fraction {f}", "paper", dict(base, **{"time.dt": "auto", "time.fraction": f}))
             for f in fractions]
    not_run = {}
    # IDA at these sizes takes 10-50 s a run at x100 (S1 x100 at rtol 1e-6: 48,000 steps, 25 s; S2
    # x22 at rtol 1e-4: 46 s) and grows like mult^2: two rungs at x100, one up to x500 (S1), none
    # beyond. Every rung is timed MIN_REPEATS times at least, however long.
    ida_base = (11, 100) if name.startswith("s1") else (46, 22)  # (CPU s at rtol 1e-4, at multiplier)
    ida_hours = hours_at(ida_base, mult, 2)
    if mult <= 100 and ida_hours < 0.5:
        rungs += [Rung("IDA (rtol ladder)", f"rtol {r:g}", "ida", dict(base, **{"ida.rtol": r}))
                  for r in (1e-4, 1e-6)[: 1 if quick else 2]]
    elif ida_hours < 0.5:
        rungs.append(Rung("IDA (rtol ladder)", "rtol 0.0001", "ida", dict(base, **{"ida.rtol": 1e-4})))
    else:
        not_run["IDA"] = (f"not run: at x{ida_base[1]} a run at rtol 1e-4 takes about {ida_base[0]} s of CPU and "
                          f"the cost grows like the square of the mesh, so about {ida_hours:.1f} h a run here")
    # Moreau-Jean is implicit (stable above the explicit limit) and costs ~50 ms a step at 2000 DOFs
    # in this adapter (dense per-body matrices): one rung at 10x the scene's step per element, up to
    # a run of minutes. Its steps grow like mult and a step's dense work like mult^2 at least.
    k = mult / 10
    sic_base = (152, 100) if name.startswith("s1") else (6.8, 22)  # (CPU s of the rung, at multiplier)
    sic_hours = hours_at(sic_base, mult, 3)
    if sic_hours < 0.5:
        rungs.append(Rung("Siconos", f"dt {dt / k:g}", "siconos", base, ["--dt", repr(dt / k)]))
    else:
        eqs = 3 * (max(elements.values()) * mult + 1)  # the exported frame model: 3 equations a node
        not_run["Siconos"] = (f"not run: its Python interface takes dense per-body matrices; at x{sic_base[1]} "
                              f"a run took {sic_base[0]} s of CPU, and the steps grow like the mesh and a "
                              f"step's dense work like its square at least, so about {sic_hours:.0f} h a run "
                              f"at x{mult} ({eqs} equations a body, {8 * eqs ** 2 / 1e9:.1f} GB a dense matrix)")
    if name.startswith("s2"):
        rungs += [Rung("exact (modes)", f"{n} modes", "exact", {"exact.modes": n}) for n in (16, 32)[: 1 if quick else 2]]
    note = "exact (references/exact: " + ("d'Alembert rods" if name.startswith("s1") else "rod on beam, converged modes") + ")"
    return Plan(f"{name}_x{mult}", path, base, Rung("reference", "", "exact", {}), rungs, note, not_run)


class Progress:
    def __init__(self, total):
        self.total, self.done, self.t0 = total, 0, time.monotonic()

    def line(self, scene, rung):
        el = time.monotonic() - self.t0
        left = el / self.done * (self.total - self.done) if self.done else float("nan")
        print(f"[work-precision] {scene}: rung {self.done + 1}/{self.total} {rung} | elapsed {el:.0f} s, "
              f"~{left:.0f} s left", file=sys.stderr, flush=True)


def cost_of(summary):
    """The run's own cost figures from its summary.json: steps, DOFs, IDA's counters."""
    keys = ("steps", "dofs", "wall_seconds", "cost")
    out = {k: summary[k] for k in keys if k in summary}
    if "ida" in summary:
        out["ida"] = {k: summary["ida"].get(k) for k in ("steps", "residual_evals", "jacobian_evals",
                                                          "nonlinear_conv_fails", "unknowns")}
    return out


def measure_rung(a, plan, k, rung):
    """(timing summary or None, the run (Run or directory), failure note) of one rung."""
    if rung.in_process():
        try:
            scene = bi.load_scene(plan.path, dict(plan.base, **rung.overrides))  # parsed once, outside the timing
            timing, run = wp_timing.time_in_process(lambda: bi.run(scene, rung.method, progress=False),
                                                    min_repeats=rung.repeats or wp_timing.MIN_REPEATS)
            return timing, run, ""
        except bi.InputError as e:
            return None, None, str(e)
        except RuntimeError as e:
            return None, None, f"failed: {e}"
    out = os.path.join(a.runs, plan.name, f"rung{k:02d}")
    timing, note = wp_timing.time_process([a.exe, "run", plan.path, "--out", out, "--quiet"] + rung.args(plan.base),
                                          rung.repeats or a.repeats)
    return timing, out, note


def compare(run, ref):
    try:
        c = bi.compare(run, ref)
    except (RuntimeError, ValueError, bi.InputError) as e:
        return None, f"compare: {e}"
    return {k: bi.norm(c, k) for k in ERRORS}, ""


def measure_scene(a, plan, progress, version, startup):
    os.makedirs(os.path.join(a.runs, plan.name), exist_ok=True)
    progress.line(plan.name, "reference: " + plan.reference_note)
    ref = bi.run(bi.load_scene(plan.path, dict(plan.base, **plan.reference.overrides)), plan.reference.method,
                 progress=False)
    progress.done += 1
    points = []
    for k, rung in enumerate(plan.rungs):
        progress.line(plan.name, f"{rung.label}: {rung.setting}")
        timing, run, note = measure_rung(a, plan, k, rung)
        progress.done += 1
        p = {"method": rung.label, "method_name": rung.method, "setting": rung.setting, "args": rung.args(plan.base),
             "timed": "in process" if rung.in_process() else "as a process (`beamimpact run`, start-up included)"}
        errors = None
        if timing:
            errors, note = compare(run, ref)
            summary = run.summary if rung.in_process() else bi.read_run(run).summary
            p.update(timing, cost=cost_of(summary))
        p.update(status="ok" if errors else "failed", error=errors, note=note)
        if note:
            print(f"[work-precision]   {note}", file=sys.stderr)
        points.append(p)
    cmd = "/usr/bin/python3 reports/work_precision.py " + (f"--sizes {plan.name}" if plan.base else f"--scenes {plan.name}")
    return {"scene": plan.path, "overrides": plan.base, "dofs": ref_dofs(points), "reference": plan.reference_note,
            "reference_args": plan.reference.args(plan.base), "version": version, "command": cmd,
            "repeats": f"in process: at least {wp_timing.MIN_REPEATS} and until {wp_timing.MIN_SECONDS} s "
                       f"(at most {wp_timing.MAX_REPEATS}); processes: {a.repeats}",
            "points": points, "startup": startup_for(a, plan, points, startup),
            "cpu_time": "in process: time.process_time() around beamimpact.run() (the scene parsed before); "
                        "processes: user + system of the child and its children (os.wait4)",
            "not_run": plan.not_run, "equal_error": equal_error(points, plan.not_run)}


def ref_dofs(points):
    """The DOFs of the paper integrator's first run (its summary's count), or None."""
    for p in points:
        if p["status"] == "ok" and p["method"].startswith("paper") and "dofs" in p.get("cost", {}):
            return p["cost"]["dofs"]
    return None


# A method whose cheapest run takes longer than this (CPU s) gets no process re-run for its start-up:
# tens of milliseconds are noise next to it, and at 1e4-1e5 DOFs the re-runs would take minutes each.
STARTUP_RUN_LIMIT = 5.0


def startup_for(a, plan, points, startup):
    """Start-up per method, measured and kept apart: for an in-process method the CPU of its
    cheapest rung run as a `beamimpact run` process minus the same rung in process (the process
    also writes history.csv); for outside methods the process-wide figures of `startup`."""
    res = dict(startup)
    for method in sorted({r.method for r in plan.rungs if r.in_process()}):
        cands = [(p["cpu_seconds_min"], r) for p, r in zip(points, plan.rungs) if r.method == method and p["status"] == "ok"]
        if not cands:
            continue
        cpu, rung = min(cands, key=lambda c: c[0])
        if cpu > STARTUP_RUN_LIMIT:
            res[method] = {"rung": rung.setting, "in_process_cpu_seconds_min": cpu,
                           "note": f"not measured: its cheapest run takes {cpu:.3g} s of CPU, against a start-up "
                                   "of milliseconds (beamimpact --version, above)"}
            continue
        out = os.path.join(a.runs, plan.name, f"startup_{method}")
        timing, note = wp_timing.time_process([a.exe, "run", plan.path, "--out", out, "--quiet"] + rung.args(plan.base),
                                              a.repeats)
        if timing:
            res[method] = {"rung": rung.setting, "process_cpu_seconds_min": timing["cpu_seconds_min"],
                           "process_wall_seconds_min": timing["wall_seconds_min"], "in_process_cpu_seconds_min": cpu,
                           "startup_cpu_seconds": timing["cpu_seconds_min"] - cpu, "loadavg_1min": timing["loadavg_1min"]}
        else:
            res[method] = {"note": note}
    return res


def process_startup(a):
    """Start-up of the processes the outside methods pay on every run: the `beamimpact` program
    (`--version`), the Python interpreter (`python3 -c pass`) and each outside method's own check
    command (interpreter and its library's import, verification/methods.toml)."""
    cmds = {"beamimpact --version": [a.exe, "--version"], "python3 -c pass": ["/usr/bin/python3", "-c", "pass"]}
    with open("verification/methods.toml", "rb") as f:
        for m in tomllib.load(f)["method"]:
            if m["name"] in OUTSIDE:
                cmds[m["name"]] = m["check"]
    res = {}
    for name, cmd in cmds.items():
        timing, note = wp_timing.time_process(cmd, a.repeats)
        keep = ("cpu_seconds_min", "cpu_seconds_max", "wall_seconds_min", "wall_seconds_max", "loadavg_1min")
        res[name] = dict({k: timing[k] for k in keep} if timing else {"note": note}, command=" ".join(cmd))
    return res


def front(points, method, key, field="cpu_seconds_min"):
    """(cpu, error) pairs of one method, sorted by CPU time, only those that improve the error."""
    pts = sorted((p[field], p["error"][key]) for p in points
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


def equal_error(points, not_run=None):
    """Per impulse-error level: each method's CPU time to reach it (min of the repeats, and the
    same from the max of the repeats) and its ratio to the paper integrator's, with the range
    min/max .. max/min. "<=": below the level at its cheapest rung already (an upper bound)."""
    methods = ["paper"] + sorted({p["method"].split(" (")[0] for p in points} - {"paper"})
    res = []
    for level in EQUAL_ERROR_LEVELS:
        lo = {m: cpu_at(front(points, m, "impulse"), level) for m in methods}
        hi = {m: cpu_at(front(points, m, "impulse", "cpu_seconds_max"), level) for m in methods}
        paper, paper_hi = lo["paper"][0], hi["paper"][0]
        parts = []
        entry = {"impulse_error": level, "cpu_s": {}, "cpu_s_max": {}, "upper_bound": {}, "ratio_to_paper": {},
                 "ratio_range": {}}
        for m in methods:
            (c, bound), c_hi = lo[m], hi[m][0]
            entry["cpu_s"][m], entry["cpu_s_max"][m], entry["upper_bound"][m] = c, c_hi, bound
            if c is None:
                parts.append(f"{m} not reached")
                continue
            txt = f"{m} {'<=' if bound else ''}{c:.3g} s"
            if m != "paper" and paper:
                entry["ratio_to_paper"][m] = c / paper
                rng = [c / paper_hi, c_hi / paper] if c_hi and paper_hi else None
                entry["ratio_range"][m] = rng
                txt += f" ({c / paper:.3g} x the paper's" + (f", {rng[0]:.3g}-{rng[1]:.3g}" if rng else "") + ")"
            parts.append(txt)
        parts += [f"{m} {why}" for m, why in sorted((not_run or {}).items())]
        entry["text"] = f"at {level:.1%} impulse error, CPU time: " + "; ".join(parts)
        res.append(entry)
    return res


# Element multipliers of the sized sets: S1 x100, x500, x5000 = 1000, 5000, 50000 elements per body
# (2002, 10002, 100002 DOFs: axial rods); S2 x22, x222 = 110 + 220 and 1110 + 2220 frame elements
# (993 and 9993 DOFs). S2 x222 steps at 8.1e-7 s (the bending limit falls like h^2): 3.7e6 steps.
SIZES = {"s1_central": (100, 500, 5000), "s2_transverse": (22, 222)}


def sized_list(text):
    """--sizes: "all" (SIZES) or a list of SCENE_xMULT (e.g. s1_central_x100, s2_transverse_x50)."""
    if text == "all":
        return [(s, m) for s, ms in SIZES.items() for m in ms]
    out = []
    for item in text.split(","):
        name, _, mult = item.rpartition("_x")
        if name not in SIZES or not mult.isdigit() or int(mult) < 1:
            fail(f"--sizes: '{item}' is not SCENE_xMULT with SCENE one of {', '.join(SIZES)} (e.g. s1_central_x100)")
        out.append((name, int(mult)))
    return out


def replot(a):
    for s in a.scenes.split(","):
        js = os.path.join(a.out, s, "work_precision.json")
        if not os.path.isfile(js):
            fail(f"--replot: {js} not found (measure first)")
        with open(js) as f:
            res = json.load(f)
        res["equal_error"] = equal_error(res["points"], res.get("not_run"))
        write_json_atomic(js, res)
        wp_figures.plot(res, os.path.join(a.out, s, "work_precision.png"))
        if s == wp_figures.HERO:
            wp_figures.plot(res, os.path.join(a.out, s, "hero.png"), hero=True)
    wp_figures.write_manifest(a.out)


def parse_args():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scenes", default="s1_central,s2_transverse,s3_surface_10,s3_surface_20,"
                                       "s4_oblique_90,s4_oblique_60,s4_oblique_45",
                   help="paper scenes at their own sizes ('' for none)")
    p.add_argument("--sizes", default="", help="'all' or SCENE_xMULT,... : S1 / S2 with the elements times MULT")
    p.add_argument("--repeats", type=int, default=3, help="repetitions of each process-timed point")
    p.add_argument("--out", default="reports/work_precision")
    p.add_argument("--runs", default="out/work_precision")
    p.add_argument("--build", default=os.environ.get("BEAMIMPACT_BUILD_DIR", "build"))
    p.add_argument("--quick", action="store_true", help="two rungs per in-process method, no FEniCSx")
    p.add_argument("--replot", action="store_true", help="only redraw the PNGs and the manifest from the JSON in --out")
    a = p.parse_args()
    if a.repeats < 1:
        fail(f"--repeats {a.repeats}: expected an integer >= 1")
    return a


def main():
    global bi
    a = parse_args()
    if a.replot:
        return replot(a)
    a.exe = os.path.join(a.build, "beamimpact")
    if not os.access(a.exe, os.X_OK):
        fail(f"--build {a.build}: no beamimpact program there (build first: bash tools/build.sh)")
    sys.path.insert(0, os.path.join(a.build, "python"))
    try:
        import beamimpact as bi
    except ImportError as e:
        fail(f"--build {a.build}: the Python module does not import from {a.build}/python ({e})")
    version = subprocess.run([a.exe, "--version"], capture_output=True, text=True).stdout.strip()
    plans = []
    for s in filter(None, a.scenes.split(",")):
        if not os.path.isfile(f"{PAPER}/{s}.toml"):
            fail(f"--scenes: '{s}' is not a scene in {PAPER}/ (expected a file name without .toml)")
        plans.append(plan_for(s, a.quick))
    plans += [sized_plan(s, m, a.quick) for s, m in sized_list(a.sizes)] if a.sizes else []
    if not plans:
        fail("--scenes '' and no --sizes: nothing to measure")
    startup = process_startup(a)
    progress = Progress(sum(len(pl.rungs) + 1 for pl in plans))
    for pl in plans:
        res = measure_scene(a, pl, progress, version, startup)
        d = os.path.join(a.out, pl.name)
        os.makedirs(d, exist_ok=True)
        write_json_atomic(os.path.join(d, "work_precision.json"), res)
        wp_figures.plot(res, os.path.join(d, "work_precision.png"))
        if pl.name == wp_figures.HERO:
            wp_figures.plot(res, os.path.join(d, "hero.png"), hero=True)
        for e in res["equal_error"]:
            print(f"[work-precision] {pl.name}: {e['text']}", file=sys.stderr)
    wp_figures.write_manifest(a.out)


if __name__ == "__main__":
    main()
