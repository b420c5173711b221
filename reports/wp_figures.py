"""@brief The figures and tables of the work-precision sets (reports/work_precision.py): one diagram
per set (impulse error and struck-point displacement error against CPU time, every method on it;
filled markers timed in process, open markers as processes), figures.json for the HTML report and
equal_error.md (CPU time at equal impulse error, with the ratios' range over the repeats, and
the start-up of each method measured apart)."""
import json
import os

from figure_sets import manifest_figure, write_manifest as write_set_manifest
from report_files import save_figure_atomic, write_text_atomic

import cost_grid
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ERRORS = ("impulse", "ub.rel_l2")  # norm names owned by verification/compare (compare_runs.cc)
ERROR_LABEL = {"impulse": "relative impulse error", "ub.rel_l2": "rel. L2 error of the struck point's displacement"}


def startup_text(res, per_set=None):
    """One line per start-up entry: CPU (and wall) minimum in ms. per_set True: only the in-process
    methods' (measured per set); False: only the processes' (measured once per invocation)."""
    out = []
    for name, s in res.get("startup", {}).items():
        if per_set is not None and per_set == ("command" in s):
            continue
        if "note" in s:
            out.append(f"{name}: {s['note']}")
        elif "startup_cpu_seconds" in s:
            out.append(f"{name}: process {1e3 * s['process_cpu_seconds_min']:.1f} ms CPU vs in process "
                       f"{1e3 * s['in_process_cpu_seconds_min']:.1f} ms ({s['rung']}): start-up "
                       f"{1e3 * s['startup_cpu_seconds']:.1f} ms")
        else:
            out.append(f"{name} (`{s['command']}`): {1e3 * s['cpu_seconds_min']:.1f} ms CPU, "
                       f"{1e3 * s['wall_seconds_min']:.0f} ms wall")
    return out


def curves(res, key):
    """(label, xs, ys, spread, process-timed) of every method with ok points on the `key` error."""
    methods = []
    for p in res["points"]:
        if p["method"] not in methods:
            methods.append(p["method"])
    out = []
    for m in methods:
        pts = [p for p in res["points"] if p["method"] == m and p["status"] == "ok" and p["error"][key]]
        if pts:
            out.append((m, [p["cpu_seconds_min"] for p in pts], [p["error"][key] for p in pts],
                        [p["cpu_seconds_max"] - p["cpu_seconds_min"] for p in pts],
                        not pts[0]["timed"].startswith("in process"), methods.index(m)))
    return out


def flat_note(method, flat):
    """The legend's note for a ladder whose impulse error does not fall (cost_grid.flat_ladders)."""
    f = next((f for f in flat if f["method"] == method), None)
    if not f:
        return ""
    return ": error does not fall (mesh error dominates)" if "mesh (spatial)" in f["why"] else ": error does not fall (another error dominates)"


def draw(res, panels=ERRORS, hero=False):
    """@brief The work-precision figure of one set (one panel per error of `panels`), every label
    inside the figure (constrained layout). Provenance is not drawn: the caption carries it
    (figures.json). hero: larger type and lines, for a thumbnail (the README).
    @return the matplotlib figure"""
    flat = cost_grid.flat_ladders(res)
    size = (7.0, 6.0) if hero else (5.6 * len(panels), 5.0)
    fig, axes = plt.subplots(1, len(panels), figsize=size, squeeze=False, layout="constrained")
    for ax, key in zip(axes[0], panels):
        for m, xs, ys, hi, proc, i in curves(res, key):
            ax.errorbar(xs, ys, xerr=[[0.0] * len(xs), hi], fmt="o-" if "ladder" in m or "modes" in m else "s--",
                        ms=7 if hero else 4, lw=2.5 if hero else 1.5, capsize=2, color=f"C{i}",
                        label=None if key != "impulse" else m if hero else m + (" [process]" if proc else "") + flat_note(m, flat),
                        mfc="none" if proc else f"C{i}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("CPU time of a run (s)" if hero else "CPU time of the run (s, min of repeats; bar to max)")
        ax.set_ylabel(ERROR_LABEL[key])
        ax.grid(True, which="both", alpha=0.3)
    if hero:
        axes[0][0].tick_params(labelsize=12)
        axes[0][0].xaxis.label.set_size(13)
        axes[0][0].yaxis.label.set_size(13)
        axes[0][0].legend(fontsize=11, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, frameon=False)
    else:
        axes[0][0].legend(fontsize=7)
    dofs = f" ({res['dofs']} DOFs)" if res.get("dofs") else ""
    name = os.path.splitext(os.path.basename(res["scene"]))[0]
    fig.suptitle(f"{name}{dofs}: error against CPU time" if hero else
                 f"{name}{dofs}: work-precision against {res['reference']}", fontsize=13 if hero else 9)
    return fig


HERO = "s2_transverse"  # the set whose impulse panel is the README's figure (hero.png beside it)


def plot(res, png, hero=False):
    """@brief draw() saved to `png` (hero: the impulse panel alone, for a thumbnail)."""
    fig = draw(res, ("impulse",) if hero else ERRORS, hero)
    save_figure_atomic(fig, png, dpi=100)
    plt.close(fig)


def caption(res):
    """@brief How the figure was made, as its caption: scene, overrides,
    reference, timings, load, start-up (the version is the manifest's own field; the report says
    beside the figure which ladders' errors do not fall, the legend marks them)."""
    loads = [x for p in res["points"] if "loadavg_1min" in p for x in p["loadavg_1min"]]
    over = " ".join(f"{k}={v}" for k, v in res.get("overrides", {}).items())
    load = f"; load average during timing {min(loads):.1f}-{max(loads):.1f}" if loads else ""
    return (f"Reference: {res['reference']}. Left: impulse, right: struck-point displacement. "
            f"Scene {' '.join(filter(None, [res['scene'], over]))}; timings per point: {res['repeats']}{load}. Start-up (not "
            f"subtracted): {'; '.join(startup_text(res))}.")


def write_manifest(out):
    figs, rows, starts, once = [], [], [], {}
    for name in sorted(os.listdir(out)):
        js = os.path.join(out, name, "work_precision.json")
        if not os.path.isfile(js):
            continue
        with open(js) as f:
            res = json.load(f)
        figs.append(manifest_figure(f"{name}/work_precision.png", f"{name}: work-precision", res["command"],
                                    res["scene"], res["version"], caption(res)))
        rows += [[name, e["text"]] for e in res["equal_error"]]
        starts += [[name, s] for s in startup_text(res, per_set=True)]
        once.update({s.split(" (")[0]: s for s in startup_text(res, per_set=False)})
    write_set_manifest(
        os.path.join(out, "figures.json"), "Work-precision sets (what accuracy costs in CPU time)",
        figs, about="In-process methods (paper, IDA, exact): each point is beamimpact.run() called repeatedly in one "
              "process (at least 3 times and until 0.2 s have passed), CPU time from time.process_time, minimum "
              "and spread kept. Outside methods (FEniCSx, Siconos): `beamimpact run` as a child process, 3 "
              "times, CPU from wait4, start-up included and shown apart. Ratios at equal impulse error below "
              "(log-log interpolation along each method's front; range from the repeats' min and max).",
        tables=[{"title": "CPU time at equal impulse error", "columns": ["set", "finding"], "rows": rows},
                {"title": "Start-up per method (measured apart, not subtracted)", "columns": ["set", "start-up"],
                 "rows": [["every set", s] for s in once.values()] + starts}])
    versions = ", ".join(sorted({fg["version"] for fg in figs}))
    write_text_atomic(os.path.join(out, "equal_error.md"), "".join(
        ["# CPU time at equal impulse error\n\nMade by `reports/work_precision.py` (beamimpact "
         f"{versions}: each set's version and command in its work_precision.json)."
         "\n\n| set | finding |\n|---|---|\n"]
        + [f"| {r[0]} | {r[1]} |\n" for r in rows]
        + ["\n## Start-up per method (measured apart, not subtracted)\n\n| set | start-up |\n|---|---|\n"]
        + [f"| {r[0]} | {r[1]} |\n" for r in [["every set", s] for s in once.values()] + starts]))
