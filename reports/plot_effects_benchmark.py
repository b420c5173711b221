#!/usr/bin/env python3
"""@brief Per-effect cost per step: reads the JSON of benchmarks/effects_benchmark (--benchmark_out),
divides every variant's CPU time per step by the hand-written kernel's at the same size (same run),
and writes the plot, the table (markdown) and the manifest the HTML report reads (figures.json: the
figure's command, version, date and caption, with the machine's load; nothing of it drawn).

Usage: plot_effects_benchmark.py [--run] [--json reports/benchmarks/effects_benchmark.json]
                                 [--out reports/benchmarks] [--build build]
--run  first runs the benchmark (3 interleaved repetitions, about 2-4 min) into --json.
Per point the minimum over repetitions is used (on a shared machine other load only adds time);
"spread" is (max - min) / min of the point's own repetitions, the noise against which "costs
nothing" is judged. Rows NAME_threads_2 run the step on 2 threads: they are timed in wall time,
their ratio to the kernel uses the kernel's wall time and their change is against NAME's wall
time (negative: faster); the threads column is the count each row used.
"""
import argparse
import json
import os
import subprocess
import sys

from figure_sets import manifest_figure, write_manifest
from report_files import save_figure_atomic, write_json_atomic, write_text_atomic

import matplotlib


matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

BASELINE = "frames"  # effects are costed relative to this variant (open contact, nothing else on)
KERNEL = {"rods": "rod_kernel"}  # every other variant is a frame model
BENCH_ARGS = ["--benchmark_repetitions=3", "--benchmark_enable_random_interleaving=true",
              "--benchmark_min_time=0.2", "--benchmark_out_format=json"]


def fail(msg):
    print(f"plot_effects_benchmark: {msg}", file=sys.stderr)
    sys.exit(2)


def load(path):
    try:
        with open(path) as f:
            data = json.load(f)
    except (OSError, json.JSONDecodeError) as e:
        fail(f"{path}: cannot read a Google Benchmark JSON ({e})")
    times = {}
    for b in data.get("benchmarks", []):
        if b.get("run_type") != "iteration" or b.get("error_occurred"):
            continue
        # run_variant/frames/1000, kernel/frame_kernel/1000, run_variant/frames_threads_2/1000/real_time
        parts = [p for p in b["run_name"].split("/") if p != "real_time"]
        if len(parts) != 3:
            continue
        times.setdefault((parts[1], int(parts[2])), []).append(
            {"cpu": b["cpu_time"], "real": b["real_time"], "closed": b.get("closed"), "dofs": b.get("dofs"),
             "threads": int(b.get("threads", 1))})
    if not times:
        fail(f"{path}: no benchmark result in it")
    return data["context"], times


THREADED = "_threads_"  # NAME_threads_N: NAME on N threads, costed in wall time against NAME


def one_thread(name):
    """The variant a thread row runs on more threads (itself for the others)."""
    return name.split(THREADED)[0]


def baseline_of(name):
    """Thread rows are costed against their variant on 1 thread; contact rows (8 targets) against
    contact_0 (same layout, all open); the rest against frames."""
    if THREADED in name:
        return one_thread(name)
    return "contact_0" if name.startswith("contact_") and name != "contact_0" else BASELINE


def summarise(times):
    med = {k: min(x["cpu"] for x in v) for k, v in times.items()}
    wall = {k: min(x["real"] for x in v) for k, v in times.items()}
    spread = {k: (max(x["cpu"] for x in v) - min(x["cpu"] for x in v)) / med[k] for k, v in times.items()}
    rows = {}
    for (name, size), t in med.items():
        if name.endswith("_kernel"):
            continue
        clock = wall if THREADED in name else med  # the other threads' CPU time is not the caller's
        t = clock[(name, size)]
        kern = clock.get((KERNEL.get(one_thread(name), "frame_kernel"), size))
        base = clock.get((baseline_of(name), size))
        closed = [x["closed"] for x in times[(name, size)] if x["closed"] is not None]
        rows[(name, size)] = {"variant": name, "size": size, "dofs": times[(name, size)][0]["dofs"],
                              "cpu_ns_per_step": t, "ratio_to_kernel": t / kern if kern else None,
                              "vs_baseline": (t / base - 1.0) if base and name not in ("rods", BASELINE) else None,
                              "spread": spread[(name, size)], "closed_fraction": min(closed) if closed else None,
                              "threads": max(x["threads"] for x in times[(name, size)]),
                              "clock": "wall" if THREADED in name else "cpu"}
    return rows


ORDER = ("rods", "frames", "consistent_mass", "damping", "corotational", "friction_declared_contact_open",
         "corotational_declared_target_held", "contact_0", "contact_1", "contact_2", "contact_8", "contact_1_friction",
         "rods_threads_2", "frames_threads_2", "contact_8_threads_2")


def order(rows):
    present = {n for (n, _) in rows}
    names = [n for n in ORDER if n in present] + sorted(present - set(ORDER))
    return names, sorted({s for (_, s) in rows})


def table(rows):
    names, sizes = order(rows)
    head = ("| variant | threads | " + " | ".join(f"{s:g} DOFs: x kernel (change vs baseline)" for s in sizes)
            + " | steps with the pushed contacts closed |\n")
    out = head + "|---|---:|" + "---|" * (len(sizes) + 1) + "\n"
    for n in names:
        cells = []
        for s in sizes:
            r = rows.get((n, s))
            if not r or r["ratio_to_kernel"] is None:
                cells.append("n/a")
                continue
            vs = "" if r["vs_baseline"] is None else f" ({r['vs_baseline']:+.0%})"
            cells.append(f"{r['ratio_to_kernel']:.2f}{vs} ±{r['spread'] / 2:.0%}")
        closed = [rows[(n, s)]["closed_fraction"] for s in sizes if (n, s) in rows]
        cl = "-" if not n.startswith("contact_") or n == "contact_0" else " / ".join(
            "n/a" if c is None else f"{c:.0%}" for c in closed)
        used = sorted({rows[(n, s)]["threads"] for s in sizes if (n, s) in rows})
        out += f"| {n} | {'/'.join(map(str, used))} | " + " | ".join(cells) + f" | {cl} |\n"
    return out


def draw(rows):
    """@brief Each variant's cost per step against size, as a ratio to the kernel, every label inside
    the image (constrained layout); how it was made is the manifest's caption.
    @return the matplotlib figure"""
    names, sizes = order(rows)
    fig, ax = plt.subplots(figsize=(8, 5), layout="constrained")
    for i, n in enumerate(names):
        pts = [(rows[(n, s)]["dofs"], rows[(n, s)]["ratio_to_kernel"], rows[(n, s)]["spread"])
               for s in sizes if (n, s) in rows and rows[(n, s)]["ratio_to_kernel"]]
        if pts:
            ax.errorbar([p[0] for p in pts], [p[1] for p in pts], yerr=[[p[1] * p[2] / 2 for p in pts]] * 2,
                        fmt="o", ms=3, capsize=2, label=n, color=f"C{i % 10}", ls="-" if i < 10 else "--")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("degrees of freedom")
    ax.set_ylabel("CPU time per step / hand-written kernel's (same run)")
    ax.set_title("Cost per step of each effect, as a ratio to the lumped-mass kernel", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return fig


def plot(rows, png):
    """@brief draw() saved to `png`."""
    fig = draw(rows)
    save_figure_atomic(fig, png, dpi=100)
    plt.close(fig)


def stamp_version(path, version):
    """The build that measured: written into the benchmark JSON's context ("beamimpact_version"), so
    that a re-plot of it (no --run) names that build, not the one plotting."""
    with open(path) as f:
        data = json.load(f)
    data["context"]["beamimpact_version"] = version
    write_json_atomic(path, data)


def measured_version(ctx, manifest):
    """The version that measured the JSON: its context's, else (a JSON from before the stamp) the
    version its earlier manifest named, else "unknown"."""
    if ctx.get("beamimpact_version"):
        return ctx["beamimpact_version"]
    try:
        with open(manifest) as f:
            return json.load(f)["figures"][0]["version"]
    except (OSError, ValueError, KeyError, IndexError):
        return "unknown"


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--run", action="store_true")
    p.add_argument("--json", default="reports/benchmarks/effects_benchmark.json")
    p.add_argument("--out", default="reports/benchmarks")
    p.add_argument("--build", default=os.environ.get("BEAMIMPACT_BUILD_DIR", "build"))
    a = p.parse_args()
    exe = os.path.join(a.build, "benchmarks", "effects_benchmark")
    cmd = f"{exe} {' '.join(BENCH_ARGS)} --benchmark_out={a.json}"
    if a.run:
        if not os.access(exe, os.X_OK):
            fail(f"--build {a.build}: no benchmarks/effects_benchmark there (cmake --build {a.build} --target effects_benchmark)")
        os.makedirs(os.path.dirname(os.path.abspath(a.json)), exist_ok=True)
        subprocess.run(cmd.split(), check=True)
        stamp_version(a.json, subprocess.run([os.path.join(a.build, "beamimpact"), "--version"], capture_output=True,
                                             text=True).stdout.strip() or "unknown")
    ctx, times = load(a.json)
    version = measured_version(ctx, os.path.join(a.out, "figures.json"))
    rows = summarise(times)
    os.makedirs(a.out, exist_ok=True)
    load_avg = ctx.get("load_avg", [])
    plot(rows, os.path.join(a.out, "effects.png"))
    md = table(rows)
    write_text_atomic(os.path.join(a.out, "effects_table.md"),
                      f"Made by `{cmd}` then `reports/plot_effects_benchmark.py`, beamimpact {version}, "
                      f"load average {load_avg}.\n\n{md}")
    names, sizes = order(rows)
    trows = [[n, "/".join(str(t) for t in sorted({rows[(n, s)]["threads"] for s in sizes if (n, s) in rows}))]
             + [("n/a" if (n, s) not in rows or rows[(n, s)]["ratio_to_kernel"] is None else
                     f"{rows[(n, s)]['ratio_to_kernel']:.2f}" + ("" if rows[(n, s)]["vs_baseline"] is None
                                                                else f" ({rows[(n, s)]['vs_baseline']:+.0%})"))
                    for s in sizes] for n in names]
    write_manifest(
        os.path.join(a.out, "figures.json"), "Per-effect benchmarks (cost per step, ratio to the hand-written kernel)",
        [manifest_figure("effects.png", "Cost per step against size, per effect",
                         cmd + " && /usr/bin/python3 reports/plot_effects_benchmark.py",
                         "generated in benchmarks/effects_benchmark.cc (S2's beam, rigid strikers)", version,
                         f"Ratios within one run: the minimum of the repetitions, bars half their spread; "
                         f"measured {ctx.get('date', '?')} on {ctx.get('num_cpus')} CPUs, shared, load average {load_avg} "
                         "at the start.")],
        about="benchmarks/effects_benchmark.cc: the paper integrator on a 10 m target of n elements "
              "with one effect on at a time; CPU time per step divided by beamimpact::bench::StepKernel's "
              "at the same size in the same run (minimum of 3 interleaved repetitions); in brackets the change against the "
              "baseline: 'frames' (one target, open contact, no other effect), for the contact rows "
              "'contact_0' (8 targets, all contacts open); NAME_threads_2: NAME on 2 threads, in "
              "wall time against NAME's wall time (negative: faster).",
        tables=[{"title": "ratio to the kernel (change vs baseline)",
                 "columns": ["variant", "threads"] + [f"{s:g} DOFs" for s in sizes], "rows": trows}])
    print(md)


if __name__ == "__main__":
    main()
