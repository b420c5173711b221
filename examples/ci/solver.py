#!/usr/bin/python3
"""The solver of this example repository: here it runs beamimpact's minimal outside solver
(penalty_central.py, installed with beamimpact under share/beamimpact/examples/external_solver/),
found from the beamimpact program it is given. Replace this file with your own solver: it reads
SCENE, writes DIR/history.csv and DIR/summary.json (beamimpact's docs/protocol.md).
Usage: solver.py SCENE --out DIR --beamimpact PROGRAM [--dt S] [--mesh M] [--quiet]"""
import os
import sys
from pathlib import Path


def installed_solver(program):
    """penalty_central.py of the installation (or the clone) the program belongs to."""
    for d in Path(program).resolve().parents:
        for candidate in (d / "share/beamimpact/examples/external_solver/penalty_central.py",
                          d / "examples/external_solver/penalty_central.py"):
            if candidate.is_file():
                return candidate
    print(f"error: no penalty_central.py beside {program} (install beamimpact with pip)", file=sys.stderr)
    sys.exit(2)


args = sys.argv[1:]
program = args[args.index("--beamimpact") + 1] if "--beamimpact" in args[:-1] else "beamimpact"
solver = installed_solver(program)
os.execv(sys.executable, [sys.executable, str(solver), *args])
