#!/usr/bin/python3
"""FEniCSx reference: both bodies as 2D plane-stress continua (Q2 quadrilaterals), explicit
central difference, node-to-segment Lagrange-multiplier contact with Coulomb friction.

  /usr/bin/python3 references/fenicsx/run.py SCENE.toml --out DIR [--mesh coarse|default|fine]
  mpirun -n 2 /usr/bin/python3 references/fenicsx/run.py SCENE.toml --out DIR

Reads the same scene file as `beamimpact run` and writes the same history.csv and summary.json
(method "fenicsx"). Exit codes: 0 done, 2 bad input (scene, options, mesh, dolfinx missing),
3 a run that produced a non-finite number (nothing written).
"""

import argparse
import logging
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from options import PRESETS, resolve_options  # noqa: E402
from output import CONTACT_COLUMNS, ContactStats, history_columns, merge_gap, merge_rule, remove_stale, write_run  # noqa: E402
from scene import InputError, load_scene     # noqa: E402

try:
    from geometry import build_geometry      # needs numpy
    _IMPORT_ERROR = None
except ImportError as _e:
    _IMPORT_ERROR = _e


def _missing_dolfinx(e):
    print(f"error: {sys.executable} cannot import {getattr(e, 'name', None) or e} ({e}); expected the "
          "Debian packages python3-dolfinx 0.5.x and python3-numpy: run with /usr/bin/python3",
          file=sys.stderr)
    return 2


def _parse(argv):
    p = argparse.ArgumentParser(prog="references/fenicsx/run.py", description=__doc__.split("\n\n")[0])
    p.add_argument("scene", help="scene TOML file (docs/scene-format.md)")
    p.add_argument("--out", required=True, help="output directory (history.csv, summary.json)")
    p.add_argument("--mesh", choices=list(PRESETS), help="mesh preset: elements through the depth "
                   "1 | 2 | 4 with square elements (default: default)")
    p.add_argument("--elements-depth", type=int, help="Q2 elements through each body's depth")
    p.add_argument("--elements-length", help="Q2 elements along each body: N, or NAME=N[,NAME=N]")
    p.add_argument("--poisson", type=float, help="Poisson's ratio (default 0)")
    p.add_argument("--fraction", type=float, help="step as a fraction of the critical step (default 0.9)")
    p.add_argument("--output-interval", type=float, help="s between history rows")
    p.add_argument("--end", type=float, help="end time (s), overrides the scene's time.end")
    p.add_argument("--quiet", action="store_true", help="no progress messages on stderr")
    p.add_argument("--fields", action="store_true",
                   help="also write VTK fields OUT/fields.pvd (as [output] fields = true in the scene)")
    return p.parse_args(argv)


def _elements_length(text):
    if text is None:
        return None
    if "=" not in text:
        try:
            return int(text)
        except ValueError:
            return text
    out = {}
    for part in text.split(","):
        name, _, n = part.partition("=")
        try:
            out[name.strip()] = int(n)
        except ValueError:
            out[name.strip()] = n
    return out


def _version():
    try:
        git = subprocess.run(["git", "-C", HERE, "describe", "--always", "--dirty", "--tags"],
                             capture_output=True, text=True, timeout=10).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        git = ""
    return git or "unknown"


def main(argv):
    args = _parse(argv)
    if _IMPORT_ERROR is not None:
        return _missing_dolfinx(_IMPORT_ERROR)
    try:
        scene = load_scene(args.scene)
        cli = {"mesh": args.mesh, "elements_depth": args.elements_depth,
               "elements_length": _elements_length(args.elements_length), "poisson": args.poisson,
               "fraction": args.fraction, "output_interval": args.output_interval, "end": args.end}
        opts = resolve_options(scene, cli)
        rects, contacts = build_geometry(scene, opts)
    except InputError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    try:
        from mpi4py import MPI
        import dolfinx
        from continuum import Continuum
        import integrator
    except ImportError as e:
        return _missing_dolfinx(e)
    # ffcx logs its just-in-time compilation at INFO on the root logger; keep stderr for messages.
    logging.disable(logging.INFO)
    comm = MPI.COMM_WORLD
    wall0 = time.time()
    try:
        if comm.rank == 0:
            remove_stale(args.out)
        cont = Continuum(comm, rects, opts.poisson)
        st = integrator.setup(scene, opts, cont, contacts)
    except InputError as e:
        if comm.rank == 0:
            print(f"error: {e}", file=sys.stderr)
        return 2
    # The suite's default merge gap (references/common/contact_intervals.py) of the samples' spacing:
    # the scene's step, else the output rows' (the statistics see one sample a row).
    spacing = scene.dt if scene.dt else st["dt"] * st["out_every"]
    stats = [ContactStats(merge_gap(spacing), merge_rule(spacing)) for _ in contacts]
    fields = None
    if args.fields or scene.fields:
        from fields import FieldOutput
        comm.Barrier()  # rank 0 has removed the stale fields (remove_stale)
        fields = FieldOutput(cont, args.out)
    res = integrator.run(cont, st, stats, progress=not args.quiet, fields=fields)
    if fields is not None:
        fields.close()
    wall = time.time() - wall0

    assumed = dict(scene.assumed)
    assumed.update(opts.assumed)
    assumed["fenicsx.model"] = ("2D plane stress, Q2 quadrilaterals, depth sqrt(12 I/A), thickness A/depth, "
                                "row-sum lumped mass, small strain")
    if scene.model["kinematics"] == "corotational":
        assumed["fenicsx.kinematics"] = "small-strain (linear) continuum; the scene's corotational is not modelled"
    if scene.model["mass"] == "consistent":
        assumed["fenicsx.mass"] = "row-sum lumped (the scene's consistent mass is not modelled)"
    effects = ["axial", "bending", "plane_stress"]
    if any(c.friction > 0 for c in contacts):
        effects.append("friction")
    if scene.loads.any():
        effects.append("loads")
    csum = []
    ncol = len(CONTACT_COLUMNS)
    for k, (c, s) in enumerate(zip(contacts, stats)):
        d = {"striker": rects[c.striker].name, "target": rects[c.target].name, "kind": c.kind,
             "friction": c.friction}
        d.update(s.summary())
        d["impacts"] = len(d["intervals"])
        # The gap column is measured on the deformed mesh (node to deformed segment): its least
        # value over the rows is this method's real gap.
        gaps = [row[1 + ncol * k + 2] for row in res["rows"]]
        i_min = min(range(len(gaps)), key=gaps.__getitem__)
        d["real_gap_min"], d["real_gap_min_time"] = gaps[i_min], res["rows"][i_min][0]
        csum.append(d)
    summary = {
        "scene": scene.name, "scene_file": scene.file, "scene_sha256": scene.sha256,
        "description": scene.description, "method": "fenicsx",
        "version": f"{_version()} (dolfinx {dolfinx.__version__})",
        "contact_sampling": "fixed steps: contact statistics from every time step; energies and momentum "
                            "at the output rows",
        "dt": st["dt"], "steps": st["nsteps"], "end_time": st["end"], "wall_seconds": wall,
        "critical_dt": st["dt_crit"], "effects": effects, "assumed": assumed,
        "overrides": {},
        "energy_initial": res["E0"], "energy_final": res["E_final"],
        "momentum_drift_max": res["drift"],
        "bodies": {n: {"final_velocity": v} for n, v in res["final_velocity"].items()},
        "contacts": csum,
        "units": {"t": "s", "R": "N", "tau": "N", "gap": "m", "u": "m", "v": "m/s", "energy": "J",
                  "momentum": "N s", "impulse": "N s"},
        "complete": True,
        "fenicsx": {
            "ranks": comm.size, "end": st["end"], "output_every_steps": st["out_every"],
            "nodes": cont.V.dofmap.index_map.size_global, "poisson": opts.poisson,
            "fraction": opts.fraction,
            "mesh": {r.name: {"elements_length": r.nx, "elements_depth": r.ny, "depth": r.h,
                              "thickness": r.b, "origin": [float(r.p0[0]), float(r.p0[1])]}
                     for r in rects},
            "initial_gap": [c.gap0 for c in contacts],
            "shadow_energy_error_max": res["shadow_err"],
            "friction_power_max": res["friction_power_max"],
        },
    }
    if scene.loads.any():
        summary["loads"] = scene.loads.summary(scene.bodies, res["load_work"])
    if comm.rank == 0:
        try:
            write_run(args.out, history_columns(len(contacts)), res["rows"], summary)
        except RuntimeError as e:
            print(f"error: {scene.file}: {e}", file=sys.stderr)
            return 3
        if not args.quiet:
            print(f"[fenicsx] {scene.name}: {st['nsteps']} steps of {st['dt']:.4g} s in {wall:.1f} s, "
                  f"wrote {args.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
