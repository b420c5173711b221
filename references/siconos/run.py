#!/usr/bin/python3
"""Siconos reference: the exported beamimpact model stepped by Siconos 4.4 (Moreau-Jean,
Newton impact law, LCP or 2D Coulomb friction contact). See stepping.py and docs/siconos.md.

  /usr/bin/python3 references/siconos/run.py SCENE.toml --out DIR --beamimpact PROGRAM
      [--dt S] [--mesh FACTOR] [--theta 0.5] [--restitution 0] [--set KEY=VALUE ...] [--quiet]

Writes DIR/history.csv and DIR/summary.json (method "siconos"). Exit codes: 0 done; 2 refused or
bad input (one line on stderr saying why: a scene the model export refuses, an option out of
range, Siconos missing); 3 the run failed (nothing written).
"""

import argparse
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from exported_model import Refused, load  # noqa: E402
from output import Recorder, remove_stale, write_run  # noqa: E402
from stepping import Options, Simulation  # noqa: E402

METHOD = "siconos"


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line on stderr, exit 2 (the protocol's bad input)
        print(f"error: siconos adapter: {message}", file=sys.stderr)
        sys.exit(2)


def parse(argv):
    ap = _Parser(description="Siconos (Moreau-Jean) on the exported beamimpact model")
    ap.add_argument("scene")
    ap.add_argument("--out", required=True)
    ap.add_argument("--beamimpact", required=True, help="the beamimpact program (exports the model)")
    ap.add_argument("--dt", default="", help="time step (s); empty: the scene's")
    ap.add_argument("--mesh", default="", help="element multiplier of every body; empty: 1")
    ap.add_argument("--theta", type=float, default=0.5, help="Moreau-Jean theta (0.5 .. 1)")
    ap.add_argument("--restitution", type=float, default=0.0, help="Newton's coefficient e (0 .. 1)")
    ap.add_argument("--set", action="append", default=[], help="scene override KEY=VALUE (repeatable)")
    ap.add_argument("--quiet", action="store_true")
    return ap.parse_args(argv)


def refuse(why):
    print(f"error: {why}", file=sys.stderr)
    return 2


def summary_of(model, opts, rec, steps, dt, wall, version):
    doc = model.doc
    first, last = rec.rows[0], rec.rows[-1]
    return {
        "scene": doc["scene"], "scene_file": doc["scene_file"], "scene_sha256": doc["scene_sha256"],
        "description": doc["description"], "method": METHOD, "version": version,
        "contact_sampling": "every step: Moreau-Jean's impulse over the step divided by dt, at the step's start",
        "dt": dt, "steps": steps, "end_time": doc["time"]["end"], "wall_seconds": wall, "critical_dt": 0.0,
        "effects": doc["effects"],
        "assumed": {**doc["assumed"], "siconos.theta": str(opts.theta),
                    "siconos.restitution": str(opts.restitution),
                    "siconos.contact_point": "fixed at t = 0 (the exported linear rows)"},
        "overrides": doc["overrides"],
        "energy_initial": first[-6] + first[-5], "energy_final": last[-6] + last[-5],
        "momentum_drift_max": rec.drift,
        "bodies": {name: {"final_velocity": v} for name, v in model.final_velocities(rec.v_final).items()},
        "contacts": [s.summary(c) for s, c in zip(rec.stats, model.contacts)],
        "units": {"t": "s", "R": "N", "tau": "N", "gap": "m", "u": "m", "v": "m/s", "energy": "J",
                  "momentum": "N s", "impulse": "N s"},
        "siconos": {**opts.as_dict(), "integrator": "MoreauJeanOSI",
                    "problem": "FrictionContact(2), NSGS" if "friction" in doc["effects"] else "LCP, Lemke",
                    "law": "NewtonImpactFrictionNSL" if "friction" in doc["effects"] else "NewtonImpactNSL",
                    "model_layout": doc["layout"], "equations": doc["equations"],
                    # s; 0 when nothing limits an explicit step (rigid bodies only)
                    "explicit_critical_dt": doc["time"]["critical_dt"] or 0.0},
        "complete": True,
    }


def main(argv):
    args = parse(argv)
    try:
        import siconos
        version = f"siconos {getattr(siconos, '__version__', '4.4')}"
    except ImportError as e:
        return refuse(f"{sys.executable} cannot import siconos ({e}); expected Debian's python3-siconos "
                      "(apt-get install python3-siconos): run with /usr/bin/python3")
    try:
        opts = Options(theta=args.theta, restitution=args.restitution)
        remove_stale(args.out)
        model = load(args.beamimpact, args.scene, args.dt or None, args.mesh or None, args.set)
        dt = model.doc["time"]["dt"]
        steps = int(round(model.doc["time"]["end"] / dt))
        start, cpu = time.perf_counter(), time.process_time()
        simulation = Simulation(model, opts, steps, dt)
    except (Refused, ValueError) as e:
        return refuse(str(e))
    except (RuntimeError, OSError) as e:  # the export crashed or the model could not be read
        print(f"error: {e}", file=sys.stderr)
        return 3
    try:
        rec = Recorder(model, dt, model.doc["time"]["output_every"])
        for t, u, v, R, tau in simulation.run():
            rec.add(t, u, v, R, tau, last=R is None)
        rec.v_final = v
        summary = summary_of(model, opts, rec, steps, dt, time.perf_counter() - start, version)
        summary["cpu_seconds"] = time.process_time() - cpu
        write_run(args.out, len(model.contacts), rec.rows, summary)
    except (RuntimeError, ValueError, MemoryError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 3
    if not args.quiet:
        for c in summary["contacts"]:
            print(f"siconos: {c['striker']} -> {c['target']}: impulse {c['impulse_normal']:.6g} N s, "
                  f"intervals {c['intervals'][:3]}")
        print(f"  wrote {args.out}/history.csv and {args.out}/summary.json")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
