"""Shared helpers of the FEniCSx reference tests: run the real CLI (run.py) in a subprocess,
load its outputs, collect failed checks. A test exits 0 (pass), 1 (a check failed) or
77 (skipped: dolfinx or mpirun not available; ctest SKIP_RETURN_CODE)."""

import argparse
import json
import os
import shutil
import subprocess
import sys
import time

try:
    import numpy as np
except ImportError:
    print(f"SKIP: {sys.executable} has no numpy (and so no dolfinx)")
    sys.exit(77)

HERE = os.path.dirname(os.path.abspath(__file__))
RUN_PY = os.path.join(os.path.dirname(HERE), "run.py")
SOURCE = os.environ.get("BEAMIMPACT_SOURCE_DIR", os.path.abspath(os.path.join(HERE, "..", "..", "..")))
SCENES = os.path.join(SOURCE, "verification", "scenes", "paper")
SKIP = 77
_failures = []


def require_dolfinx():
    """Exits with the skip code when dolfinx cannot be imported by this interpreter."""
    # In a child process: importing dolfinx here would initialise MPI in the test process,
    # and an MPI-initialised parent cannot launch `mpirun` children.
    p = subprocess.run([sys.executable, "-c", "import dolfinx"], capture_output=True, text=True)
    if p.returncode != 0:
        print(f"SKIP: {sys.executable} cannot import dolfinx ({p.stderr.strip()[-300:]})")
        sys.exit(SKIP)


def work_dir():
    """The --work DIR argument (default: a folder under /tmp), emptied."""
    p = argparse.ArgumentParser()
    p.add_argument("--work", default=os.path.join("/tmp", "beamimpact-fenicsx-tests",
                                                  os.path.basename(sys.argv[0])[:-3]))
    d = p.parse_args().work
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    return d


def mpirun_prefix(n):
    """The mpirun command for n ranks (root needs --allow-run-as-root), or None."""
    exe = shutil.which("mpirun")
    if exe is None:
        return None
    cmd = [exe, "-n", str(n)]
    if os.geteuid() == 0:
        cmd.insert(1, "--allow-run-as-root")
    # Oversubscribe and yield: CI machines may have fewer free cores than ranks, and busy-polling
    # ranks sharing a core make every reduction cost a scheduler time slice.
    return cmd[:1] + ["--oversubscribe", "--mca", "mpi_yield_when_idle", "1"] + cmd[1:]


def run(scene, out, *args, ranks=1, expect=0):
    """Runs run.py on a scene (a path, or a name in the paper folder); returns (summary, history)
    or, when expect != 0, (returncode, stderr)."""
    path = scene if os.path.isabs(scene) else os.path.join(SCENES, scene)
    cmd = [sys.executable, RUN_PY, path, "--out", out, "--quiet", *args]
    if ranks > 1:
        cmd = mpirun_prefix(ranks) + cmd
    t = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - t
    if expect != 0:
        return p.returncode, p.stderr
    if p.returncode != 0:
        print(f"FAILED to run: {' '.join(cmd)}\n{p.stderr[-3000:]}")
        sys.exit(1)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    hist = np.genfromtxt(os.path.join(out, "history.csv"), delimiter=",", names=True)
    print(f"ran {os.path.basename(path)} {' '.join(args)} (ranks {ranks}): {summary['steps']} steps, "
          f"{wall:.1f} s wall")
    return summary, hist


def check(ok, what):
    """Records one check; prints it either way so the ctest log shows the numbers."""
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        _failures.append(what)


def finish():
    if _failures:
        print(f"{len(_failures)} check(s) failed")
        sys.exit(1)
    print("all checks passed")
    sys.exit(0)
