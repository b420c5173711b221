#!/usr/bin/python3
"""GetFEM reference: the scene's bodies built with GetFEM's own finite elements (P1 bars, cubic
Hermite Euler-Bernoulli beams, mass and stiffness from its weak-form language), stepped by an
implicit Newmark scheme on the assembled matrices, frictionless penalty contact at the striker
node. See assembly.py, contact.py, newmark.py and docs/getfem.md.

  /usr/bin/python3 references/getfem/run.py SCENE.toml --out DIR [--dt S] [--mesh FACTOR] [--penalty GAMMA0]
      [--mass consistent|lumped] [--beta 0.25] [--gamma 0.5]
      [--quiet]

Writes DIR/history.csv and DIR/summary.json (method "getfem"). Exit codes: 0 done; 2 refused or
bad input (one line on stderr: what the scene asks that this reference does not model, or a bad
option); 3 the run failed (nothing written)."""

import argparse
import importlib.util
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from scene_input import Refused, load, refine  # noqa: E402

METHOD = "getfem"


def _fenicsx_output():
    """The FEniCSx reference's output module (pure Python, no dolfinx): the suite's contact
    interval rule and the protocol's atomic write, shared rather than copied."""
    spec = importlib.util.spec_from_file_location("fenicsx_output", os.path.join(HERE, "..", "fenicsx", "output.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line on stderr, exit 2 (the protocol's bad input)
        print(f"error: getfem adapter: {message}", file=sys.stderr)
        sys.exit(2)


def parse(argv):
    ap = _Parser(description="GetFEM beams/bars, Newmark, penalty contact")
    ap.add_argument("scene")
    ap.add_argument("--out", required=True)
    ap.add_argument("--dt", default="", help="time step (s); empty: the scene's time.dt")
    ap.add_argument("--mesh", default="", help="element multiplier of every body (1 .. 64); empty: 1")
    ap.add_argument("--penalty", type=float, default=None, help="gamma0: kn = gamma0 E A / h (default 10)")
    ap.add_argument("--mass", default=None, help="axial mass: consistent (default) or lumped")
    ap.add_argument("--beta", type=float, default=None, help="Newmark beta (default 1/4)")
    ap.add_argument("--gamma", type=float, default=None, help="Newmark gamma (default 1/2)")
    ap.add_argument("--quiet", action="store_true")
    return ap.parse_args(argv)


def options(scene, args):
    """Newmark and penalty options: command line over the scene's [getfem] table over defaults."""
    from newmark import Options
    opts, table = Options(), dict(scene.options)
    for key in ("beta", "gamma", "penalty", "mass"):
        if key in table:
            v = table.pop(key)
            if key == "mass":
                setattr(opts, key, v)
            elif isinstance(v, bool) or not isinstance(v, (int, float)):
                raise Refused(scene.file, f"getfem.{key}", f"expected a number, found {v!r}")
            else:
                setattr(opts, key, float(v))
        if getattr(args, key) is not None:
            setattr(opts, key, getattr(args, key))
    if table:
        raise Refused(scene.file, f"getfem.{next(iter(table))}", "unknown key; expected beta, gamma, penalty or mass")
    try:
        opts.check()
    except ValueError as e:
        raise Refused(scene.file, "getfem", str(e))
    return opts


def main(argv):
    args = parse(argv)
    try:
        import getfem  # noqa: F401  (its absence is a refusal, before any work)
    except ImportError as e:
        print(f"error: getfem: {sys.executable} cannot import getfem ({e}); expected Debian's python3-getfem "
              "(apt-get install python3-getfem): run with /usr/bin/python3", file=sys.stderr)
        return 2
    from simulate import simulate
    out = _fenicsx_output()
    try:
        scene = load(args.scene)
        if args.dt:
            try:
                scene.dt = float(args.dt)
            except ValueError:
                raise Refused(scene.file, "--dt", f"expected a step in s, found {args.dt!r}")
            if not 0 < scene.dt <= scene.end:
                raise Refused(scene.file, "--dt", f"expected 0 < dt <= time.end, found {args.dt}")
        if args.mesh:
            if not args.mesh.isdigit() or not 1 <= int(args.mesh) <= 64:
                raise Refused(scene.file, "--mesh", f"expected an element multiplier 1 .. 64, found {args.mesh!r}")
            refine(scene, int(args.mesh))
        opts = options(scene, args)
        out.remove_stale(args.out)
    except Refused as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    try:
        start, cpu = time.perf_counter(), time.process_time()

        def make_stats(dt):  # the suite's default merge gap (references/common/contact_intervals.py)
            return out.ContactStats(out.merge_gap(dt), out.merge_rule(dt))

        rows, summary = simulate(scene, opts, make_stats)
        summary["wall_seconds"] = time.perf_counter() - start
        summary["cpu_seconds"] = time.process_time() - cpu
        out.write_run(args.out, out.history_columns(len(scene.contacts)), rows, summary)
    except Refused as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    except (RuntimeError, ValueError, MemoryError, ArithmeticError) as e:
        print(f"error: getfem: {e}", file=sys.stderr)
        return 3
    if not args.quiet:
        for c in summary["contacts"]:
            print(f"getfem: {c['striker']} -> {c['target']}: impulse {c['impulse_normal']:.6g} N s, "
                  f"intervals {c['intervals'][:3]}")
        print(f"  wrote {args.out}/history.csv and {args.out}/summary.json")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
