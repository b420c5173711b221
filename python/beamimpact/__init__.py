"""beamimpact from Python: scenes, runs through the method registry, run directories, the
compare command's norms, and the verify, sweep, study, score and conform commands, over the C++
library (beamimpact._core).

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

import contextlib
import copy
import json
import os
import re
import sys
import tempfile
import warnings
from pathlib import Path
from typing import Any, Callable, Iterable, Mapping, Optional, Sequence, Union

import numpy as np

from . import _core
from ._core import InputError
from .fields import read_fields

__all__ = ["InputError", "Scene", "Run", "load_scene", "run", "read_run", "read_fields", "compare",
           "norm", "sweep", "verify", "study", "score", "conform", "load_methods", "methods", "scenes", "data_root"]
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
    arrays, or a pandas DataFrame when pandas is installed; `columns` is always the dict);
    `directory`: its run directory (read_run(), run(out=...)), or None when it has none."""

    def __init__(self, summary: dict, columns: dict[str, np.ndarray], label: str,
                 directory: Optional[Union[str, os.PathLike]] = None):
        self.summary, self.columns, self.label = summary, columns, label
        self.directory = Path(directory) if directory is not None else None
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
    _check_threads(threads)
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
    return Run(summary, columns, f"{method}:{s.name}", out)


def _check_threads(threads: Optional[int]) -> None:
    """InputError naming `threads` unless it is None or a whole number 1..max_threads."""
    if threads is not None and (isinstance(threads, bool) or not isinstance(threads, int)
                                or not 1 <= threads <= _core.max_threads):
        raise InputError(f"threads: expected a whole number of threads 1..{_core.max_threads}, got {threads!r}")


def read_run(directory: Union[str, os.PathLike]) -> Run:
    """Reads a run directory written by `beamimpact run` (or run(out=...)) as a Run."""
    summary, columns = _core.read_run(str(directory))
    return Run(summary, columns, str(directory), directory)


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


@contextlib.contextmanager
def _output_folder(out: Optional[Union[str, os.PathLike]], command: str):
    """`out` as a Path, or a temporary folder removed when the block ends."""
    if out is not None:
        yield Path(out)
        return
    with tempfile.TemporaryDirectory(prefix=f"beamimpact-{command}-") as folder:
        yield Path(folder)


def _scene_file(scene: SceneLike, overrides: Optional[Overrides], folder: Path) -> str:
    """The file a command reads for `scene`: the scene's own file when it has no overrides, else
    the scene with its overrides (or a dict scene) written as TOML to folder/scene/NAME.toml."""
    if not isinstance(scene, Scene) and not overrides:
        return _core.resolve_scene(os.fspath(scene))
    s = _as_scene(scene)  # loaded and validated here: a bad scene or override raises InputError now
    if overrides:
        s = s.with_overrides(overrides)
    if not s._is_dict and not s._overrides:
        return os.fspath(s._source)
    stem = Path(s._source).stem if not s._is_dict else (re.sub(r"[^A-Za-z0-9_.-]", "_", s.name) or "scene")
    path = folder / "scene" / f"{stem}.toml"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(_core.scene_toml(s._source, s._is_dict, s._overrides))
    return os.fspath(path)


def _sweep_reference(reference: Optional[Union[Run, str, os.PathLike]]) -> str:
    """The sweep's --reference: "self", a method name, or a run directory (a Run's own)."""
    if reference is None:
        return "self"
    if isinstance(reference, Run):
        if reference.directory is None:
            raise InputError("reference: a Run without a run directory (give run(..., out=DIR) or read_run(DIR)), "
                             "or \"self\", a method name or a run directory")
        return os.fspath(reference.directory)
    return os.fspath(reference)


def sweep(scene: SceneLike, dts: Optional[Sequence[float]] = None, method: str = "paper",
          reference: Optional[Union[Run, str, os.PathLike]] = None, overrides: Optional[Overrides] = None,
          progress: Any = None, *, set: Optional[Overrides] = None, fractions: Sequence[float] = (),
          meshes: Sequence[Union[int, str]] = (), out: Optional[Union[str, os.PathLike]] = None,
          jobs: int = 1, timeout: float = 3600.0, threads: Optional[int] = None,
          exe: Optional[Union[str, os.PathLike]] = None) -> list[dict]:
    """`beamimpact sweep` as a call (the same library function, verification::sweep): runs
    `scene` with `method` at each dt in `dts` (s; or, for scenes with dt = "auto", at each
    fraction of the critical step in `fractions`) on each of `meshes` (element multipliers or
    presets; default the scene's), compares every run with one reference and writes runs/,
    sweep.md, sweep.csv and sweep.json under `out` (default: a temporary folder, removed when the
    call returns).

    reference: None or "self" (the method at the finest dt / 4 on the finest mesh: a separate
    run, so the finest point's errors are not 0), a method name (run at the scene's own
    settings), a run directory, or a Run with a directory (read_run(), run(out=...); a Run
    without one raises InputError naming `reference`).
    overrides: {"time.dt": 0.005} as --set (`set` is its deprecated name): a scene with overrides,
    or a dict scene (Scene.from_dict), is written as TOML to `out`/scene/NAME.toml and that
    file is swept (its runs record no overrides: they are in the file).
    jobs: runs in parallel; timeout: s per run; threads: the paper integrator's threads of each
    run (None: each run's default); exe: a `beamimpact` program each run is a process of
    (`--isolate`); default every run goes in this process. The GIL is released meanwhile.
    progress: not taken: as the command does, the sweep prints one line on stderr per finished
    run (its runs' own progress is silenced); giving it warns (DeprecationWarning).

    Returns one dict per point, in the order dts x meshes: "dt" (s, as asked; for `fractions`
    "fraction" and "dt", the step used, s, or None), "mesh" (when `meshes` are given), "steps",
    "wall_seconds" (s, the method's own time), the norms `beamimpact sweep` tabulates
    (_core.sweep_norms()) that the comparison
    has (sweep.json's numbers), and "status" and "message" for a point that did not run
    ("not applicable", "failed", ...). Bad options raise InputError, as the command exits 2."""
    overrides = _overrides(overrides, set, "sweep")
    if progress is not None:
        warnings.warn("beamimpact.sweep(progress=...) is ignored: the sweep prints one line per finished run "
                      "on stderr, as the command does", DeprecationWarning, stacklevel=2)
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise InputError(f"jobs: expected a whole number of runs in parallel >= 1, got {jobs!r}")
    _check_threads(threads)
    o = _core.SweepOptions()
    o.method, o.reference = method, _sweep_reference(reference)
    o.dts = [float(d) for d in (dts if dts is not None else ())]
    o.fractions = [float(f) for f in fractions]
    o.meshes = [str(m) for m in meshes]
    o.jobs, o.timeout, o.threads = jobs, float(timeout), threads or 0
    o.exe = os.fspath(exe) if exe is not None else ""
    with _output_folder(out, "sweep") as folder:
        o.scene, o.out = _scene_file(scene, overrides, folder), os.fspath(folder)
        return _core.sweep(o)


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


def study(file: Union[str, os.PathLike], out: Union[str, os.PathLike], *, keep_runs: bool = False,
          fresh: bool = False) -> dict:
    """`beamimpact study` as a call (the same library function, study::run_study): runs the
    study file's every point (its scene over a grid or Latin hypercube of parameters, each
    method compared with the point's reference; format: ``verification/studies/*.toml``) and writes
    study.csv, study.json, study.md, timing.csv and timing.json under `out`, the points' records
    under `out`/points (a study interrupted in the same `out` with the same input is resumed;
    `fresh=True` runs every point again, as `--fresh`). keep_runs=True keeps every run's files
    under `out`/runs (`--keep-runs`). A relative `file` that does not exist here is looked for
    under data_root(). One line per finished point goes to stderr; the GIL is released meanwhile.

    Returns study.json's dict: the study's definition and "cases", one per point and method
    ("parameters", "method", "status", "steps", "dt" in s, "norms" by name, "energy_growth",
    "broke"); it has no timing field (timing.json has: s). Bad files raise InputError naming the
    file and key, as the command exits 2."""
    o = _core.StudyOptions()
    o.file = _core.resolve_data_file(os.fspath(file))
    o.out, o.keep_runs, o.fresh = os.fspath(out), bool(keep_runs), bool(fresh)
    return _core.study(o)


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
