"""@brief The figures and tables of the work-precision sets (reports/work_precision.py): one diagram
per set (impulse error and struck-point displacement error against CPU time, every method on it;
filled markers timed in process, open markers as processes), figures.json for the HTML report and
equal_error.md (CPU time at equal impulse error, with the ratios' range over the repeats, and
the start-up of each method measured apart)."""
import json
import os
import textwrap

from report_files import save_figure_atomic, write_json_atomic, write_text_atomic

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


def plot(res, png):
    fig, axes = plt.subplots(1, 2, figsize=(11, 5.4))
    fig.subplots_adjust(left=0.07, right=0.98, bottom=0.33, top=0.9, wspace=0.25)
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
            hi = [p["cpu_seconds_max"] - p["cpu_seconds_min"] for p in pts]
            proc = not pts[0]["timed"].startswith("in process")
            ax.errorbar(xs, ys, xerr=[[0.0] * len(xs), hi], fmt="o-" if "ladder" in m or "modes" in m else "s--",
                        ms=4, capsize=2, label=m + (" [process]" if proc else ""), color=f"C{i}",
                        mfc="none" if proc else f"C{i}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("CPU time of the run (s, min of repeats; bar to max)")
        ax.set_ylabel(ERROR_LABEL[key])
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    size = f" ({res['dofs']} DOFs)" if res.get("dofs") else ""
    fig.suptitle(f"{os.path.basename(res['scene'])}{size}: work-precision against {res['reference']}", fontsize=9)
    loads = [x for p in res["points"] if "loadavg_1min" in p for x in p["loadavg_1min"]]
    over = " ".join(f"{k}={v}" for k, v in res.get("overrides", {}).items())
    foot = textwrap.wrap(res["command"], 150) + textwrap.wrap(
        f"scene {res['scene']} {over} | reference {res['reference']} | beamimpact {res['version']} | "
        f"timings per point: {res['repeats']} | load average during timing {min(loads):.1f}-{max(loads):.1f}", 150)
    foot += textwrap.wrap("start-up (not subtracted): " + "; ".join(startup_text(res)), 150)
    fig.text(0.01, 0.01, "\n".join(foot), fontsize=6.5, family="monospace", va="bottom")
    save_figure_atomic(fig, png, dpi=100)
    plt.close(fig)


def write_manifest(out):
    figs, rows, starts, once = [], [], [], {}
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
        starts += [[name, s] for s in startup_text(res, per_set=True)]
        once.update({s.split(" (")[0]: s for s in startup_text(res, per_set=False)})
    write_json_atomic(os.path.join(out, "figures.json"), {
        "title": "Work-precision sets (what accuracy costs in CPU time)",
        "about": "In-process methods (paper, IDA, exact): each point is beamimpact.run() called repeatedly in one "
                 "process (at least 3 times and until 0.2 s have passed), CPU time from time.process_time, minimum "
                 "and spread kept. Outside methods (FEniCSx, Siconos): `beamimpact run` as a child process, 3 "
                 "times, CPU from wait4, start-up included and shown apart. Ratios at equal impulse error below "
                 "(log-log interpolation along each method's front; range from the repeats' min and max).",
        "tables": [{"title": "CPU time at equal impulse error", "columns": ["set", "finding"], "rows": rows},
                   {"title": "Start-up per method (measured apart, not subtracted)", "columns": ["set", "start-up"],
                    "rows": [["every set", s] for s in once.values()] + starts}],
        "figures": figs})
    versions = ", ".join(sorted({fg["version"] for fg in figs}))
    write_text_atomic(os.path.join(out, "equal_error.md"), "".join(
        ["# CPU time at equal impulse error\n\nMade by `reports/work_precision.py` (beamimpact "
         f"{versions}: each set's version and command in its work_precision.json)."
         "\n\n| set | finding |\n|---|---|\n"]
        + [f"| {r[0]} | {r[1]} |\n" for r in rows]
        + ["\n## Start-up per method (measured apart, not subtracted)\n\n| set | start-up |\n|---|---|\n"]
        + [f"| {r[0]} | {r[1]} |\n" for r in [["every set", s] for s in once.values()] + starts]))
