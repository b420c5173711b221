#!/usr/bin/env python3
"""@brief Two threads against one on the kinds of scene users run, on the path they take:
`beamimpact run SCENE --threads N` with a history row every step (the default), at 1e4, 1e5 and
1e6 DOFs.

Kinds (each a paper scene refined, `time.dt = "auto"`, half the critical step):
- rods, contact: S1's two rods end-on, apart by what they close in 20 steps;
- rods, no contact: S1 with the rods 990 m apart (they never meet in the window);
- frames, chatter: S2's striker above the beam's midspan by what it closes in 20 steps (at least
  2e-8 m):
  node-to-surface contact that chatters (about a hundred impacts in the window at 1e5 DOFs);
- frames, no contact: S2 with the striker 100 m above the beam;
- frames, friction: the chatter scene with mu = 0.3 and the striker sliding at 0.5 m/s;
- frames, loads: the chatter scene under gravity (0, -9.81) m/s^2.
A run's step time is (wall of N steps - wall of one step) / (N - 1), each wall the least of
`--rounds` interleaved rounds (1 and 2 threads in turn), so that the set-up is left out and a
busy moment of the machine costs one round, not the ratio. N is chosen for about 4e8 DOF-steps.
Every round checks that history.csv is the same bytes on 1 and 2 threads (exit 1 otherwise).

Usage: threads_benchmark.py [--build build] [--sizes 1e4,1e5,1e6] [--kinds all|K1,K2]
                            [--rounds 3] [--out DIR] [--markdown FILE]
Prints one row per kind and size: DOFs, steps, us per step on 1 and 2 threads, the speed-up,
same bytes, the load average. Exit 2 on bad input, 1 when a run fails or the bytes differ.
"""
import argparse
import filecmp
import json
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
S1 = os.path.join(ROOT, "verification", "scenes", "paper", "s1_central.toml")
S2 = os.path.join(ROOT, "verification", "scenes", "paper", "s2_transverse.toml")
DOF_STEPS = 4e8
AUTO = ['time.dt="auto"', "time.allow_long_run=true"]


def chatter(gap):
    """S2's striker `gap` m above the beam's midspan (it closes at 1 m/s)."""
    return [f"bodies.A.start=[5.0, {5.0 + gap!r}]", f"bodies.A.end=[5.0, {gap!r}]"]


# kind: (scene, DOFs per element, overrides besides the mesh, from the gap that closes in 20 steps);
# S1's rods are collinear (one axial DOF a node), S2's frames have three.
KINDS = {
    "rods_contact": (S1, 1, lambda g: [f"bodies.B.start=[{10.0 + 2 * g!r}, 0.0]", f"bodies.B.end=[{20.0 + 2 * g!r}, 0.0]"]),
    "rods_no_contact": (S1, 1, lambda g: ["bodies.B.start=[1000.0, 0.0]", "bodies.B.end=[1010.0, 0.0]"]),
    "frames_chatter": (S2, 3, chatter),
    "frames_no_contact": (S2, 3, lambda g: ["bodies.A.start=[5.0, 105.0]", "bodies.A.end=[5.0, 100.0]"]),
    "frames_friction": (S2, 3, lambda g: chatter(g) + ["contacts[0].friction=0.3", "bodies.A.velocity=[0.5, -1.0]"]),
    "frames_loads": (S2, 3, lambda g: chatter(g) + ["loads.gravity=[0.0, -9.81]"]),
}


def fail(msg, code=2):
    print(f"threads_benchmark: {msg}", file=sys.stderr)
    sys.exit(code)


def mesh(kind, dofs):
    """Elements of A and B for about `dofs` equations: S1's rods half each, S2's beam twice the striker."""
    scene, per_element, _ = KINDS[kind]
    elements = max(2, int(dofs / per_element))
    a = elements // 2 if scene == S1 else elements // 3
    return [f"bodies.A.elements={a}", f"bodies.B.elements={elements - a}"]


def run(exe, kind, sets, threads, out, gap=1e-6):
    """One `beamimpact run`; returns its summary."""
    scene = KINDS[kind][0]
    shutil.rmtree(out, ignore_errors=True)
    cmd = [exe, "run", scene, "--out", out, "--quiet", "--threads", str(threads)]
    for s in AUTO + KINDS[kind][2](gap) + sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"{' '.join(cmd)} exited {r.returncode}: {(r.stderr or r.stdout).strip()[-400:]}", 1)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def measure(exe, kind, dofs, rounds, tmp):
    """The row of one kind and size."""
    sets = mesh(kind, dofs)
    probe = run(exe, kind, sets + ["time.end=1e-9"], 1, f"{tmp}/probe")
    dt, n_dofs = probe["dt"], probe["dofs"]
    # m: 20 steps at the closing speed of 1 m/s, and at least twice the least gap a scene may
    # start with (1e-9 of its longest body, 10 m): on the finest frames the contact then closes
    # after about 250 of the 400 steps.
    gap = max(20 * dt * 1.0, 2e-8)
    steps = max(20, int(DOF_STEPS / n_dofs))
    window = [f"time.end={steps * dt!r}"]
    one_step = [f"time.end={dt!r}"]
    best = {}
    same = True
    impacts = None
    for _ in range(rounds):
        for threads in (1, 2):
            for tag, extra in (("run", window), ("setup", one_step)):
                s = run(exe, kind, sets + extra, threads, f"{tmp}/{tag}{threads}", gap)
                if s.get("threads") != threads:
                    fail(f"{kind}: asked for {threads} threads, the run used {s.get('threads')}: "
                         f"{s.get('threads_note', '')}", 1)
                key = (tag, threads)
                best[key] = min(best.get(key, float("inf")), s["wall_seconds"])
                if tag == "run" and threads == 1:
                    impacts = len(s["contacts"][0].get("intervals", []))
                    run_steps = s["steps"]
        same = same and filecmp.cmp(f"{tmp}/run1/history.csv", f"{tmp}/run2/history.csv", shallow=False)
    per_step = {t: (best[("run", t)] - best[("setup", t)]) / (run_steps - 1) for t in (1, 2)}
    return {"kind": kind, "dofs": n_dofs, "steps": run_steps, "impacts": impacts,
            "us_per_step_1": 1e6 * per_step[1], "us_per_step_2": 1e6 * per_step[2],
            "speedup": per_step[1] / per_step[2], "same_bytes": same,
            "load": os.getloadavg()[0]}


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--sizes", default="1e4,1e5,1e6")
    p.add_argument("--kinds", default="all")
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--markdown", default=None, help="also write the table here")
    a = p.parse_args()
    exe = os.path.join(a.build, "beamimpact")
    if not os.access(exe, os.X_OK):
        fail(f"{exe}: no beamimpact program (build it: bash tools/build.sh beamimpact)")
    try:
        sizes = [float(x) for x in a.sizes.split(",")]
    except ValueError:
        fail(f"--sizes: expected numbers of DOFs separated by commas, got '{a.sizes}'")
    if any(s < 100 or s > 1e7 for s in sizes):
        fail(f"--sizes: expected DOFs from 100 to 1e7, got '{a.sizes}'")
    kinds = list(KINDS) if a.kinds == "all" else a.kinds.split(",")
    for k in kinds:
        if k not in KINDS:
            fail(f"--kinds: expected 'all' or some of {', '.join(KINDS)}, got '{k}'")
    if a.rounds < 1:
        fail(f"--rounds: expected 1 or more, got {a.rounds}")
    version = subprocess.run([exe, "--version"], capture_output=True, text=True).stdout.strip()
    head = (f"{version}, `benchmarks/threads_benchmark.py {' '.join(sys.argv[1:])}`, "
            f"{os.cpu_count()} cores, best of {a.rounds} interleaved rounds, a history row every step")
    lines = [head, "",
             "| kind | DOFs | steps | impacts | us/step, 1 thread | us/step, 2 threads | speed-up | same bytes | load |",
             "|---|---:|---:|---:|---:|---:|---:|:---:|---:|"]
    print(head, flush=True)
    ok = True
    with tempfile.TemporaryDirectory() as tmp:
        for size in sizes:
            for k in kinds:
                r = measure(exe, k, size, a.rounds, tmp)
                ok = ok and r["same_bytes"]
                line = (f"| {k} | {r['dofs']} | {r['steps']} | {r['impacts']} | {r['us_per_step_1']:.1f} | "
                        f"{r['us_per_step_2']:.1f} | {r['speedup']:.2f} | {'yes' if r['same_bytes'] else 'NO'} | "
                        f"{r['load']:.2f} |")
                lines.append(line)
                print(line, flush=True)
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write("\n".join(lines) + "\n")
    if not ok:
        fail("history.csv differs between 1 and 2 threads", 1)


if __name__ == "__main__":
    main()
