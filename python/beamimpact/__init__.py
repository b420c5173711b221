"""beamimpact from Python: scenes, runs through the method registry, run directories and the
compare command's norms, over the C++ library (beamimpact._core).

    import beamimpact
    scene = beamimpact.load_scene("verification/scenes/paper/s1_central.toml")
    run = beamimpact.run(scene, method="paper", set={"time.dt": 0.005})
    run.summary["contacts"][0]["impulse_normal"], run.history["R"]
    beamimpact.compare(run, beamimpact.run(scene, method="exact"))["norms"]

Bad input raises beamimpact.InputError with the CLI's message (file, key, what was expected);
beamimpact.SceneError is the same class under its earlier name (deprecated).
"""
import json
import os
import shutil
import sys

import numpy as np

from . import _core
from ._core import InputError, SceneError
from .fields import read_fields

__all__ = ["InputError", "SceneError", "Scene", "Run", "load_scene", "run", "read_run", "read_fields", "compare",
           "norm", "sweep", "verify", "methods"]
__version__ = _core.__version__


def _plain(o):
    """json.dumps' fallback: numpy scalars and arrays as the Python values they hold."""
    if isinstance(o, (np.generic, np.ndarray)):
        return o.tolist()
    raise TypeError(f"{type(o).__name__} is not a scene value (numbers, strings, booleans, lists, dicts)")


def _toml_value(v):
    """A --set value as TOML: shortest round-trip numbers, true/false, quoted strings."""
    if isinstance(v, (np.generic, np.ndarray)):
        v = _plain(v)  # a numpy repr is no TOML number
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v)
    # Strings, and lists of numbers: JSON and TOML agree (numpy scalars inside a list as well).
    return json.dumps(v, default=_plain)


class Scene:
    """A validated scene: a file (load_scene) or a dict (Scene.from_dict), with --set overrides.

    Attributes of the loaded scene (name, file, sha256, bodies, assumed, overrides, ...) are
    those of the C++ Scene.
    """

    def __init__(self, source, overrides=(), *, _is_dict=False):
        self._source, self._is_dict = source, _is_dict
        self._overrides = list(overrides)
        if _is_dict:
            self._scene = _core.load_scene_dict(source, "<dict>", self._overrides)
        else:
            self._scene = _core.load_scene(str(source), self._overrides)

    @classmethod
    def from_dict(cls, tables):
        """A scene from a dict of its TOML tables ({"name": ..., "time": {...}, "bodies": [...]})."""
        return cls(json.dumps(tables, default=_plain), _is_dict=True)

    def with_set(self, settings):
        """This scene with more overrides ({"time.dt": 0.005} as --set time.dt=0.005)."""
        extra = [f"{k}={_toml_value(v)}" for k, v in (settings or {}).items()]
        return Scene(self._source, self._overrides + extra, _is_dict=self._is_dict)

    def __getattr__(self, name):
        scene = self.__dict__.get("_scene")
        if scene is None:
            raise AttributeError(name)
        return getattr(scene, name)

    def __repr__(self):
        return f"<beamimpact.Scene {self.name!r} from {self.file}>"


def load_scene(path, set=None):
    """Loads and validates a scene file; `set` as Scene.with_set()."""
    return Scene(path).with_set(set) if set else Scene(path)


class Run:
    """One run: `summary` (the summary.json dict) and `history` (history.csv's columns as numpy
    arrays, or a pandas DataFrame when pandas is installed; `columns` is always the dict)."""

    def __init__(self, summary, columns, label):
        self.summary, self.columns, self.label = summary, columns, label
        try:
            import pandas
            self.history = pandas.DataFrame(columns)
        except ImportError:
            self.history = columns

    def __repr__(self):
        rows = len(next(iter(self.columns.values()))) if self.columns else 0
        return f"<beamimpact.Run {self.summary.get('method')} on {self.summary.get('scene')}: {rows} rows>"


def _as_scene(scene):
    return scene if isinstance(scene, Scene) else load_scene(scene)


class _Progress:
    """One progress line on stderr (Jupyter shows it under the cell), rewritten in place."""

    def __init__(self):
        self.printed = False

    def __call__(self, label, value, total):
        pct = 100.0 * value / total if total else 0.0
        sys.stderr.write(f"\r{label}: {pct:3.0f}% (t = {value:.4g} of {total:.4g} s)")
        sys.stderr.flush()
        self.printed = True

    def close(self):
        if self.printed:
            sys.stderr.write("\n")


def run(scene, method="paper", set=None, *, out=None, history=True, fields=False, progress=True):
    """Runs a scene (a Scene or a path) with a method of the registry (methods()).

    set: overrides {"time.dt": 0.005}; out: also write the run directory there (as
    `beamimpact run --out`); history=False keeps no rows (memory independent of the steps; the
    summary still has the energies); fields=True writes VTK fields into `out`; progress: True
    (a line on stderr, shown in notebooks), False, or a function (label, value, total).
    The GIL is released while the run goes on.
    """
    s = _as_scene(scene)
    settings = dict(set or {})
    if not history:
        settings["output.history"] = False
    if fields:
        settings["output.fields"] = True
    if settings:
        s = s.with_set(settings)
    callback = _Progress() if progress is True else (progress or None)
    try:
        summary, names, rows = _core.run(s._scene, method, None if out is None else str(out), callback)
    finally:
        if isinstance(callback, _Progress):
            callback.close()
    columns = {n: rows[:, i] for i, n in enumerate(names)}
    return Run(summary, columns, f"{method}:{s.name}")


def read_run(directory):
    """Reads a run directory written by `beamimpact run` (or run(out=...)) as a Run."""
    summary, columns = _core.read_run(str(directory))
    return Run(summary, columns, str(directory))


def _stored(r):
    if not isinstance(r, Run):
        r = read_run(r)
    return {k: list(v) for k, v in r.columns.items()}, r.summary, r.label


def compare(run_, reference, *, grid_step=0.0, window=0.0, merge_gap=0.0, threshold=1e-6):
    """The `beamimpact compare` norms of `run_` against `reference` (Runs or run directories),
    as the dict `compare --json` writes; norms by name in result["norms"]."""
    a, b = _stored(run_), _stored(reference)
    return _core.compare(*a, *b, grid_step, window, merge_gap, threshold)


def norm(comparison, name):
    """The value of the norm `name` ("impulse", "R.rel_l2", ...) of a compare() result, or None."""
    for n in comparison["norms"]:
        if n["name"] == name:
            return n.get("value")
    raise KeyError(f"no norm {name!r} in the comparison")


def sweep(scene, dts, method="paper", reference=None, set=None, progress=False):
    """A dt ladder: runs `scene` at each dt (s) and compares each run with `reference` (a Run,
    a run directory, or a method name run at the scene's own settings; default: the smallest
    dt's run, whose own errors are then 0 - unlike `beamimpact sweep`'s reference "self", a
    separate run at the finest dt / 4). Returns one dict per dt: dt, steps, wall_seconds and
    the norms `beamimpact sweep` tabulates."""
    s = _as_scene(scene)
    if set:
        s = s.with_set(set)
    runs = [run(s, method, {"time.dt": dt}, progress=progress) for dt in dts]
    if reference is None:
        ref = runs[min(range(len(dts)), key=lambda i: dts[i])]
    elif isinstance(reference, str) and reference in methods():
        ref = run(s, reference, progress=progress)
    else:
        ref = reference
    table = []
    for dt, r in zip(dts, runs):
        c = compare(r, ref)
        row = {"dt": dt, "steps": r.summary["steps"], "wall_seconds": r.summary["wall_seconds"]}
        row.update({n: norm(c, n) for n in _core.sweep_norms() if any(x["name"] == n for x in c["norms"])})
        table.append(row)
    return table


def verify(matrix="verification/matrix.toml", out="out/verify", *, tier="quick", only="", jobs=1, exe=None):
    """`beamimpact verify` as a call: runs the matrix's `tier` (items whose name contains `only`)
    with `jobs` runs in parallel, each a process of the `beamimpact` executable `exe` (default
    $BEAMIMPACT_EXE, else `beamimpact` on PATH), writes runs/, junit.xml, norms.json and report.md
    under `out`, and returns norms.json's dict: result["verdict"] is "PASS" or "FAIL" by the
    library's one pass rule (complete, no gate failed); each gate has "passed" and "margin"."""
    exe = exe or os.environ.get("BEAMIMPACT_EXE") or shutil.which("beamimpact")
    if not exe:
        raise FileNotFoundError("verify: no beamimpact executable (pass exe= or set BEAMIMPACT_EXE)")
    return _core.verify(str(matrix), str(out), tier, only, jobs, str(exe))


def methods():
    """The names of the methods of the registry (in-process ones run with run())."""
    return _core.methods()
