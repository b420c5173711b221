"""beamimpact from Python: scenes, runs through the method registry, run directories, the
compare command's norms, and the verify, score and conform commands, over the C++ library
(beamimpact._core).

    import beamimpact
    scene = beamimpact.load_scene("s1_central")   # a shipped scene by name, or any scene file
    run = beamimpact.run(scene, method="paper", overrides={"time.dt": 0.005})
    run.summary["contacts"][0]["impulse_normal"], run.history["R"]
    beamimpact.compare(run, beamimpact.run(scene, method="exact"))["norms"]

A scene argument is a file, or a shipped scene's name (scenes(); the rule is the command's:
docs/installation.md); the shipped data are found from the installed package (data_root()).

Bad input raises beamimpact.InputError with the CLI's message (file, key, what was expected).
"""
from __future__ import annotations

import copy
import json
import os
import sys
import warnings
from pathlib import Path
from typing import Any, Callable, Iterable, Mapping, Optional, Sequence, Union

import numpy as np

from . import _core
from ._core import InputError
from .fields import read_fields

__all__ = ["InputError", "Scene", "Run", "load_scene", "run", "read_run", "read_fields", "compare",
           "norm", "sweep", "verify", "score", "conform", "load_methods", "methods", "scenes", "data_root"]
__version__ = _core.__version__

#: A scene given as a loaded Scene or as the path of its TOML file.
SceneLike = Union["Scene", str, "os.PathLike[str]"]
#: Scene overrides by key, as --set KEY=VALUE: {"time.dt": 0.005, "bodies.B.elements": 20}.
Overrides = Mapping[str, Any]
#: A progress callback: (label, value, total).
ProgressFn = Callable[[str, float, float], None]


def _overrides(overrides: Optional[Overrides], set_: Optional[Overrides], where: str) -> Optional[Overrides]:
    """The overrides of a call that may still use the deprecated keyword set= (it shadows the builtin)."""
    if set_ is None:
        return overrides
    warnings.warn(f"beamimpact.{where}(set=...) is deprecated: use overrides=...", DeprecationWarning, stacklevel=3)
    if overrides is not None:
        raise TypeError(f"beamimpact.{where}: give overrides= or set=, not both")
    return set_


def _plain(o):
    """json.dumps' fallback: numpy scalars and arrays as the Python values they hold."""
    if isinstance(o, (np.generic, np.ndarray)):
        return o.tolist()
    raise TypeError(f"{type(o).__name__} is not a scene value (numbers, strings, booleans, lists, dicts)")


def _toml_value(v):
    """The text a run records for an override value (summary.json "overrides"), as --set would
    show it: shortest round-trip numbers, true/false, quoted strings. The value itself reaches the
    scene as a typed TOML value, not through this text."""
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

    def __init__(self, source: Union[str, os.PathLike, Mapping[str, Any]], overrides: Iterable = (), *,
                 _is_dict: bool = False):
        # overrides: "key=value" text (as --set) or (key, value, recorded text) triples.
        self._source, self._is_dict = source, _is_dict
        self._overrides = list(overrides)
        if _is_dict:
            self._scene = _core.load_scene_dict(source, "<dict>", self._overrides)
        else:
            self._source = source = _core.resolve_scene(os.fspath(source))
            self._scene = _core.load_scene_with(str(source), self._overrides)

    @classmethod
    def from_dict(cls, tables: Mapping[str, Any]) -> Scene:
        """A scene from a dict of its TOML tables ({"name": ..., "time": {...}, "bodies": [...]})."""
        return cls(copy.deepcopy(dict(tables)), _is_dict=True)  # later edits of `tables` do not reach it

    def with_overrides(self, settings: Optional[Overrides]) -> Scene:
        """This scene with more overrides ({"time.dt": 0.005} as --set time.dt=0.005)."""
        extra = [(k, v, _toml_value(v)) for k, v in (settings or {}).items()]
        return Scene(self._source, self._overrides + extra, _is_dict=self._is_dict)

    def with_set(self, settings: Optional[Overrides]) -> Scene:
        """The same as with_overrides()."""
        return self.with_overrides(settings)

    def __getattr__(self, name: str) -> Any:
        scene = self.__dict__.get("_scene")
        if scene is None:
            raise AttributeError(name)
        return getattr(scene, name)

    def __repr__(self) -> str:
        return f"<beamimpact.Scene {self.name!r} from {self.file}>"


def load_scene(path: Union[str, os.PathLike], overrides: Optional[Overrides] = None, *,
               set: Optional[Overrides] = None) -> Scene:
    """Loads and validates a scene file (or a shipped scene by name: scenes()); `overrides` as Scene.with_overrides() (`set` is the
    deprecated name of `overrides`)."""
    overrides = _overrides(overrides, set, "load_scene")
    return Scene(path).with_overrides(overrides) if overrides else Scene(path)


class Run:
    """One run: `summary` (the summary.json dict) and `history` (history.csv's columns as numpy
    arrays, or a pandas DataFrame when pandas is installed; `columns` is always the dict)."""

    def __init__(self, summary: dict, columns: dict[str, np.ndarray], label: str):
        self.summary, self.columns, self.label = summary, columns, label
        try:
            import pandas
            self.history = pandas.DataFrame(columns)
        except ImportError:
            self.history = columns

    def __repr__(self) -> str:
        rows = len(next(iter(self.columns.values()))) if self.columns else 0
        return f"<beamimpact.Run {self.summary.get('method')} on {self.summary.get('scene')}: {rows} rows>"


def _as_scene(scene: SceneLike) -> Scene:
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


def run(scene: SceneLike, method: str = "paper", overrides: Optional[Overrides] = None, *,
        out: Optional[Union[str, os.PathLike]] = None, history: bool = True, fields: bool = False,
        progress: Union[bool, ProgressFn] = True, set: Optional[Overrides] = None,
        threads: Optional[int] = None) -> Run:
    """Runs a scene (a Scene or a path) with a method of the registry (methods()).

    overrides: {"time.dt": 0.005} as --set time.dt=0.005 (`set` is its deprecated name); out: also write the run directory there (as
    `beamimpact run --out`); history=False keeps no rows (memory independent of the steps; the
    summary still has the energies); fields=True writes VTK fields into `out`; progress: True
    (a line on stderr, shown in notebooks), False, or a function (label, value, total).
    threads: the paper integrator's threads (an int >= 1, as `beamimpact run --threads`); None:
    the machine's, 1 for small models; the results are the same bits at any count, and
    summary["threads"] says how many were used.
    The GIL is released while the run goes on.
    """
    s = _as_scene(scene)
    settings = dict(_overrides(overrides, set, "run") or {})
    if threads is not None and (isinstance(threads, bool) or not isinstance(threads, int)
                                or not 1 <= threads <= _core.max_threads):
        raise InputError(f"threads: expected a whole number of threads 1..{_core.max_threads}, got {threads!r}")
    if not history:
        settings["output.history"] = False
    if fields:
        settings["output.fields"] = True
    if settings:
        s = s.with_overrides(settings)
    callback = _Progress() if progress is True else (progress or None)
    try:
        summary, names, rows = _core.run(s._scene, method, None if out is None else str(out), callback, threads)
    finally:
        if isinstance(callback, _Progress):
            callback.close()
    columns = {n: rows[:, i] for i, n in enumerate(names)}
    return Run(summary, columns, f"{method}:{s.name}")


def read_run(directory: Union[str, os.PathLike]) -> Run:
    """Reads a run directory written by `beamimpact run` (or run(out=...)) as a Run."""
    summary, columns = _core.read_run(str(directory))
    return Run(summary, columns, str(directory))


def _stored(r):
    if not isinstance(r, Run):
        r = read_run(r)
    return {k: list(v) for k, v in r.columns.items()}, r.summary, r.label


def compare(run_: Union[Run, str, os.PathLike], reference: Union[Run, str, os.PathLike], *,
            grid_step: float = 0.0, window: float = 0.0, merge_gap: float = 0.0,
            threshold: float = 1e-6) -> dict:
    """The `beamimpact compare` norms of `run_` against `reference` (Runs or run directories),
    as the dict `compare --json` writes; norms by name in result["norms"]."""
    a, b = _stored(run_), _stored(reference)
    return _core.compare(*a, *b, grid_step, window, merge_gap, threshold)


def norm(comparison: dict, name: str) -> Optional[float]:
    """The value of the norm `name` ("impulse", "R.rel_l2", ...) of a compare() result, or None."""
    for n in comparison["norms"]:
        if n["name"] == name:
            return n.get("value")
    raise KeyError(f"no norm {name!r} in the comparison")


def sweep(scene: SceneLike, dts: Sequence[float], method: str = "paper",
          reference: Optional[Union[Run, str, os.PathLike]] = None, overrides: Optional[Overrides] = None,
          progress: Union[bool, ProgressFn] = False, *, set: Optional[Overrides] = None) -> list[dict]:
    """A dt ladder: runs `scene` at each dt (s) and compares each run with `reference` (a Run,
    a run directory, or a method name run at the scene's own settings; default: the smallest
    dt's run, whose own errors are then 0 - unlike `beamimpact sweep`'s reference "self", a
    separate run at the finest dt / 4). Returns one dict per dt: dt, steps, wall_seconds and
    the norms `beamimpact sweep` tabulates."""
    s = _as_scene(scene)
    overrides = _overrides(overrides, set, "sweep")
    if overrides:
        s = s.with_overrides(overrides)
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


def verify(matrix: Union[str, os.PathLike] = "verification/matrix.toml", out: Union[str, os.PathLike] = "out/verify", *,
           tier: str = "quick", only: str = "", jobs: int = 1, exe: Optional[Union[str, os.PathLike]] = None,
           fresh: bool = False) -> dict:
    """`beamimpact verify` as a call: runs the matrix's `tier` (items whose name contains `only`)
    with `jobs` runs in parallel, each in this process (the library's beamimpact::run; an outside
    method's program is its own process), or, with `exe` (a `beamimpact` program), each as a
    process of it (`--isolate`), writes runs/, junit.xml, norms.json and report.md
    under `out`, and returns norms.json's dict: result["verdict"] is "PASS" or "FAIL" by the
    library's one pass rule (complete, no gate failed); each gate has "passed" and "margin".
    A run recorded as finished under `out`/runs with the same input (an interrupted verify's) is
    taken as it is, as the command does (docs/resuming.md); `fresh=True` runs everything again
    (`--fresh`). A relative `matrix` that does not exist here is the shipped one (data_root()),
    so the default works from any folder."""
    return _core.verify(str(_core.resolve_data_file(os.fspath(matrix))), str(out), tier, only, jobs,
                        os.fspath(exe) if exe is not None else "", fresh)


def load_methods(*files: Union[str, os.PathLike]) -> None:
    """Adds the external methods declared in methods files to the registry, as `--methods FILE`
    does (docs/protocol.md); a file already read is not read again. Bad files raise InputError."""
    for f in files:
        _core.load_methods_file(os.fspath(f))


def score(method: Union[str, Sequence[str]], out: Optional[Union[str, os.PathLike]] = None, *,
          sets: Sequence[str] = ("paper", "hard", "exact"), scenes: Sequence[str] = (),
          references: str = "converged", ladder: bool = True, rungs: int = 3,
          cards: Optional[Union[str, os.PathLike]] = None, cache: Optional[Union[str, os.PathLike]] = None,
          baseline: Optional[Union[str, os.PathLike]] = None, jobs: int = 1, timeout: float = 900.0,
          methods: Sequence[Union[str, os.PathLike]] = (), exe: Optional[Union[str, os.PathLike]] = None) -> dict:
    """`beamimpact score` as a call (the same library function, docs/protocol.md): scores `method`
    (a name, or several) on the benchmark set under each scene's card and writes each scorecard.json
    (under `out`, default score-NAME; NAME/ for each of several methods). The options are the
    command's: `sets`, `scenes` (by name; default every scene of the sets), `references`
    ("converged" or "matrix"), `ladder` (False: --no-ladder), `rungs`, `cards` (default the shipped
    verification/cards.toml), `cache` (the reference cache; default as the command's), `baseline`
    (an earlier scorecard.json: the ratchet), `jobs`, `timeout` (s per run); `methods`: methods
    files to read first (load_methods). Each run goes in this process, or, with `exe` (a
    `beamimpact` program), is a process of it, as verify() does. No page is rendered (reports/render.py scorecard DIR makes it).

    Returns {"passed": bool, "exit_code": the command's (0, 1, or 128 + a signal), "command",
    "cache" and "paths" (the scorecard.json files written; pathlib.Path), "scorecards": {name:
    scorecard.json's dict (its "verdict", "counts", "scenes" with every quantity's "status"), with
    "ratchet": {"grown", "improved"} or None}}. Bad options raise InputError, as the command exits 2."""
    load_methods(*methods)
    o = _core.ScoreOptions()
    o.methods = [method] if isinstance(method, str) else list(method)
    o.out = os.fspath(out) if out is not None else ""
    o.sets, o.scenes, o.references, o.ladder, o.rungs = list(sets), list(scenes), references, ladder, rungs
    o.cards = os.fspath(cards) if cards is not None else ""
    o.cache = os.fspath(cache) if cache is not None else ""
    o.baseline = os.fspath(baseline) if baseline is not None else ""
    o.jobs, o.timeout = jobs, float(timeout)
    o.exe = os.fspath(exe) if exe is not None else ""
    return _core.score(o)


def conform(method: str, out: Optional[Union[str, os.PathLike]] = None, *, scenes: Sequence[str] = (),
            timeout: float = 600.0, methods: Sequence[Union[str, os.PathLike]] = ()) -> dict:
    """`beamimpact conform` as a call (the same library function, docs/protocol.md): runs the
    external method `method` on the conformance scenes (`scenes`, default all; the malformed one
    always) into `out` (default conform-NAME), checks every rule of the protocol and writes
    junit.xml and conform.json there. `methods`: methods files to read first (load_methods);
    `timeout`: s per run. Returns conform.json's dict ("verdict": "passed" or "failed", "counts",
    every rule's "results") with "passed" (bool) and "paths" (the files written). An unknown or
    built-in method, or bad options, raise InputError, as the command exits 2."""
    load_methods(*methods)
    o = _core.ConformOptions()
    o.method = method
    o.out = os.fspath(out) if out is not None else ""
    o.scenes, o.timeout = list(scenes), float(timeout)
    return _core.conform(o)


def data_root() -> Optional[Path]:
    """The folder of the shipped data (verification/scenes, verification/matrix.toml,
    verification/methods.toml, references/): the installed share/beamimpact or the repository;
    None when neither is found."""
    root = _core.data_root()
    return Path(root) if str(root) else None


def scenes() -> dict[str, Path]:
    """The shipped scenes by name ("s1_central": its file); a name works wherever a scene file
    does (run("s1_central"), `beamimpact run s1_central`)."""
    return {name: Path(file) for name, file in _core.shipped_scenes()}


def methods() -> list[str]:
    """The names of the methods of the registry (in-process ones run with run())."""
    return _core.methods()
