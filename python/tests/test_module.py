"""The Python module against the CLI: the same numbers bit for bit (S1, S4-45), the same error
messages, run directories read back, the compare command's norms, and memory that does not grow
with the steps when no history is kept. Run from ctest (PYTHONPATH=build/python,
BEAMIMPACT_EXE, BEAMIMPACT_SOURCE)."""
import csv
import json
import os
import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest

import beamimpact

EXE = os.environ["BEAMIMPACT_EXE"]
PAPER = Path(os.environ["BEAMIMPACT_SOURCE"]) / "verification" / "scenes" / "paper"


def cli(*args):
    return subprocess.run([EXE, *map(str, args)], capture_output=True, text=True)


def cli_run(tmp_path, scene, method="paper", *sets):
    out = tmp_path / f"{Path(scene).stem}-{method}"
    args = ["run", scene, "--out", out, "--method", method, "--quiet"]
    for s in sets:
        args += ["--set", s]
    p = cli(*args)
    assert p.returncode == 0, p.stderr
    return out


def csv_columns(out):
    with open(out / "history.csv") as f:
        rows = list(csv.reader(f))
    return {name: np.array([float(r[i]) for r in rows[1:]]) for i, name in enumerate(rows[0])}


def same_summary(a, b):
    """Every key equal except the wall time and the cost rates made from it (measurements, not
    results)."""
    a, b = dict(a), dict(b)
    for s in (a, b):
        s.pop("wall_seconds")
        if "cost" in s:
            s["cost"] = {k: v for k, v in s["cost"].items() if not k.startswith("ns_per_")}
    assert a == b


@pytest.mark.parametrize("scene,method", [("s1_central", "paper"), ("s4_oblique_45", "paper"),
                                          ("s1_central", "exact")])
def test_module_equals_cli_bit_for_bit(tmp_path, scene, method):
    path = PAPER / f"{scene}.toml"
    out = cli_run(tmp_path, path, method)
    r = beamimpact.run(beamimpact.load_scene(path), method=method, progress=False)
    expected = csv_columns(out)
    assert list(r.columns) == list(expected)  # the same columns in the same order
    for name, col in expected.items():
        assert np.array_equal(r.columns[name], col), name  # exact: CSV holds round-trip decimals
    same_summary(r.summary, json.loads((out / "summary.json").read_text()))


def test_set_overrides_equal_cli_set(tmp_path):
    out = cli_run(tmp_path, PAPER / "s1_central.toml", "paper", "time.dt=0.005", "bodies.B.elements=20")
    r = beamimpact.run(PAPER / "s1_central.toml", overrides={"time.dt": 0.005, "bodies.B.elements": 20}, progress=False)
    assert np.array_equal(r.columns["R"], csv_columns(out)["R"])
    assert r.summary["overrides"] == {"time.dt": "0.005", "bodies.B.elements": "20"}
    same_summary(r.summary, json.loads((out / "summary.json").read_text()))


def test_set_keyword_still_works_with_a_deprecation_warning():
    # set= (which shadows the builtin) is the old name of overrides=: same scene, one warning per
    # call naming the replacement; both at once is an error rather than a silent choice.
    path = PAPER / "s1_central.toml"
    new = beamimpact.run(path, overrides={"time.dt": 0.02}, progress=False)
    with pytest.warns(DeprecationWarning, match=r"run\(set=\.\.\.\) is deprecated: use overrides="):
        old = beamimpact.run(path, set={"time.dt": 0.02}, progress=False)
    assert old.summary["overrides"] == new.summary["overrides"] == {"time.dt": "0.02"}
    assert np.array_equal(old.columns["R"], new.columns["R"])
    with pytest.warns(DeprecationWarning, match="load_scene"):
        assert beamimpact.load_scene(path, set={"time.dt": 0.02}).overrides == {"time.dt": "0.02"}
    with pytest.warns(DeprecationWarning, match="sweep"):
        assert [r["steps"] for r in beamimpact.sweep(path, [0.02, 0.01], set={"time.end": 1.0})] == [50, 100]
    with pytest.raises(TypeError, match="not both"), pytest.warns(DeprecationWarning):
        beamimpact.run(path, overrides={"time.dt": 0.02}, set={"time.dt": 0.01}, progress=False)


def test_numpy_scalars_are_set_as_the_numbers_they_hold():
    # np.float64 / np.int64 (what np.logspace and friends give) reach the scene as 0.005 and 20.
    r = beamimpact.run(PAPER / "s1_central.toml", overrides={"time.dt": np.float64(0.005), "bodies.B.elements": np.int64(20)},
                       progress=False)
    assert r.summary["overrides"] == {"time.dt": "0.005", "bodies.B.elements": "20"}


def test_from_dict_runs_as_the_file_does():
    path = PAPER / "s1_central.toml"
    tables = tomllib.loads(path.read_text())
    a = beamimpact.run(beamimpact.Scene.from_dict(tables), progress=False)
    b = beamimpact.run(path, progress=False)
    for name in b.columns:
        assert np.array_equal(a.columns[name], b.columns[name])
    assert a.summary["scene_file"] == "<dict>"


def test_from_dict_takes_numpy_values():
    # A dict built with numpy (np.int64 is no JSON number) loads as the plain values it holds.
    tables = tomllib.loads((PAPER / "s1_central.toml").read_text())
    tables["bodies"][1]["elements"] = np.int64(20)
    tables["time"]["dt"] = np.float64(0.005)
    a = beamimpact.run(beamimpact.Scene.from_dict(tables), progress=False)
    b = beamimpact.run(PAPER / "s1_central.toml", overrides={"bodies.B.elements": 20, "time.dt": 0.005}, progress=False)
    for name in b.columns:
        assert np.array_equal(a.columns[name], b.columns[name])


def test_dict_scene_is_the_file_scene_with_typed_overrides():
    # The dict reaches the loader as TOML values (no text): the scene of the file, and overrides of
    # it are typed values recorded as the --set text they always were.
    path = PAPER / "s1_central.toml"
    tables = tomllib.loads(path.read_text())
    d = beamimpact.Scene.from_dict(tables).with_overrides({"time.dt": 0.005, "bodies.B.elements": np.int64(20)})
    f = beamimpact.load_scene(path, overrides={"time.dt": 0.005, "bodies.B.elements": 20})
    assert d.overrides == f.overrides == {"time.dt": "0.005", "bodies.B.elements": "20"}
    assert d.assumed == f.assumed and d.bodies == f.bodies and d.end_time == f.end_time
    a, b = beamimpact.run(d, progress=False), beamimpact.run(f, progress=False)
    for name in b.columns:
        assert np.array_equal(a.columns[name], b.columns[name]), name
    s = beamimpact.Scene.from_dict(tables)
    tables["time"]["dt"] = 0.02  # the scene took a copy: this edit is not in it
    assert beamimpact.run(s, overrides={"time.end": 1.0}, progress=False).summary["dt"] == 0.01
    with pytest.raises(beamimpact.InputError, match=r"<dict>: key 'time.dt'.*auto"):
        beamimpact.Scene.from_dict(tomllib.loads(path.read_text())).with_overrides({"time.dt": "fast"})
    with pytest.raises(beamimpact.InputError, match=r"<dict>: key 'bodies\[1\].elements'"):
        tables = tomllib.loads(path.read_text())
        tables["bodies"][1]["elements"] = 2**70
        beamimpact.Scene.from_dict(tables)
    with pytest.raises(TypeError, match="is not a scene value"):
        beamimpact.Scene.from_dict({"name": object()})


def test_bad_scene_raises_the_cli_message(tmp_path):
    path = PAPER / "s1_central.toml"
    p = cli("run", path, "--out", tmp_path / "bad", "--set", "bodies.A.area=-0.4")
    assert p.returncode == 2
    with pytest.raises(beamimpact.InputError) as e:
        beamimpact.load_scene(path, overrides={"bodies.A.area": -0.4})
    assert str(e.value) in p.stderr  # the CLI prints the same message (with its "error: " prefix)
    assert "bodies[0].area" in str(e.value) and "positive" in str(e.value)


def test_bad_dict_names_the_key():
    tables = tomllib.loads((PAPER / "s1_central.toml").read_text())
    tables["time"]["dt"] = "fast"
    with pytest.raises(beamimpact.InputError, match=r"<dict>: key 'time.dt'.*auto"):
        beamimpact.Scene.from_dict(tables)
    tables["time"]["dt"] = None
    with pytest.raises(beamimpact.InputError, match=r"time.dt.*None"):
        beamimpact.Scene.from_dict(tables)
    with pytest.raises(beamimpact.InputError, match="expected a method name"):
        beamimpact.run(PAPER / "s1_central.toml", method="nope", progress=False)


def test_read_run_of_a_cli_directory(tmp_path):
    out = cli_run(tmp_path, PAPER / "s4_oblique_45.toml")
    r = beamimpact.read_run(out)
    for name, col in csv_columns(out).items():
        assert np.array_equal(r.columns[name], col), name
    assert r.summary == json.loads((out / "summary.json").read_text())
    with pytest.raises(beamimpact.InputError, match="summary.json|history.csv"):
        beamimpact.read_run(tmp_path / "missing")


def test_compare_gives_the_compare_commands_norms(tmp_path):
    a = cli_run(tmp_path, PAPER / "s1_central.toml", "paper", "time.dt=0.02")
    b = cli_run(tmp_path, PAPER / "s1_central.toml", "exact")
    p = cli("compare", a, b, "--json", tmp_path / "c.json")
    assert p.returncode == 0, p.stderr
    expected = json.loads((tmp_path / "c.json").read_text())
    got = beamimpact.compare(beamimpact.run(PAPER / "s1_central.toml", overrides={"time.dt": 0.02}, progress=False),
                             beamimpact.read_run(b))
    strip = lambda c: [{k: v for k, v in n.items()} for n in c["norms"]]  # noqa: E731
    assert strip(got) == strip(expected)
    # The exact solution's impulse is 4 N s (references.md); the paper's run is within 5 %.
    assert beamimpact.norm(got, "impulse") < 0.05


def cli_sweep_points(out):
    """`beamimpact sweep`'s sweep.json points: (dt as the float it prints, mesh) -> the point."""
    return {(float(p["dt"]), p["mesh"]): p for p in json.loads((out / "sweep.json").read_text())["points"]}


def test_sweep_is_the_commands_sweep_and_converges(tmp_path):
    # The call and the command are one library call (verification::sweep): the same norms, bit
    # for bit, against the same reference "self" (a separate run at the finest dt / 4).
    dts = [0.04, 0.02, 0.01]
    p = cli("sweep", PAPER / "s1_central.toml", "--dt", "0.04,0.02,0.01", "--out", tmp_path / "cli")
    assert p.returncode == 0, p.stderr
    expected = cli_sweep_points(tmp_path / "cli")
    rows = beamimpact.sweep(PAPER / "s1_central.toml", dts, out=tmp_path / "py")
    assert [r["dt"] for r in rows] == dts and [r["steps"] for r in rows] == [100, 200, 400]  # 4 s / dt
    for row in rows:
        point = expected[(row["dt"], "")]
        norms = {n["name"]: n["value"] for n in point["comparison"]["norms"]}
        assert row["steps"] == point["steps"]
        assert {k: v for k, v in row.items() if k in norms} == {k: norms[k] for k in beamimpact._core.sweep_norms()
                                                                 if k in norms}
        assert "status" not in row and "mesh" not in row  # every point ran; the scene's mesh
    assert set(beamimpact._core.sweep_norms()) <= set(rows[0])  # the sweep command's columns
    # The reports stay in `out`, with the command's numbers (timings and folders aside).
    written = json.loads((tmp_path / "py" / "sweep.json").read_text())
    numbers = lambda c: {k: v for k, v in c.items() if k not in ("run", "reference")}  # noqa: E731 (folders)
    assert [numbers(q["comparison"]) for q in written["points"]] == [numbers(q["comparison"])
                                                                    for q in expected.values()]
    ref = json.loads((Path(written["reference_dir"]) / "summary.json").read_text())
    assert ref["steps"] == 1600  # the reference: dt = 0.01 / 4 on 4 s
    # Theory: the scheme converges in dt at first order or better. Against a reference at
    # dt_ref = 0.0025, a first-order error e = C (dt - dt_ref) falls by (0.04 - 0.0025) /
    # (0.02 - 0.0025) = 2.14 and (0.02 - 0.0025) / (0.01 - 0.0025) = 2.33 per halving; 2 (the
    # order exactly 1 against the exact limit) leaves room for a constant that is not yet
    # asymptotic. The finest point is not the reference: its error is not 0.
    errors = [r["impulse"] for r in rows]
    assert errors[0] >= 2.0 * errors[1] and errors[1] >= 2.0 * errors[2] and errors[2] > 0.0


def test_sweep_meshes_and_dict_scene_equal_the_command(tmp_path):
    # meshes reach the runs (dts x meshes, mesh in each row), and a dict scene with overrides is
    # written as the TOML file the command reads: the same numbers as the command on that scene
    # given by its file and --set through `run` (a file with the overrides in it).
    path = PAPER / "s1_central.toml"
    scene_file = tmp_path / "s1_short.toml"
    scene_file.write_text(path.read_text().replace("end = 4.0 ", "end = 3.0 "))
    p = cli("sweep", scene_file, "--dt", "0.02,0.01", "--mesh", "1,2", "--out", tmp_path / "cli")
    assert p.returncode == 0, p.stderr
    expected = cli_sweep_points(tmp_path / "cli")
    scene = beamimpact.Scene.from_dict(tomllib.loads(path.read_text()))
    rows = beamimpact.sweep(scene, [0.02, 0.01], meshes=[1, 2], overrides={"time.end": 3.0}, out=tmp_path / "py")
    assert [(r["dt"], r["mesh"]) for r in rows] == [(0.02, "1"), (0.02, "2"), (0.01, "1"), (0.01, "2")]
    assert [r["steps"] for r in rows] == [150, 150, 300, 300]  # 3 s / dt: the override is in the file
    for row in rows:
        norms = {n["name"]: n["value"] for n in expected[(row["dt"], row["mesh"])]["comparison"]["norms"]}
        for name in beamimpact._core.sweep_norms():
            if name in norms:
                assert row[name] == norms[name], (row["dt"], row["mesh"], name)
    assert rows[0]["impulse"] != rows[1]["impulse"]  # the mesh reached the runs
    assert (tmp_path / "py" / "scene" / "s1_central.toml").is_file()


def test_sweep_refusals_name_their_key(tmp_path):
    path = PAPER / "s1_central.toml"
    r = beamimpact.run(path, overrides={"time.dt": 0.02}, progress=False)  # no run directory
    with pytest.raises(beamimpact.InputError, match="reference"):
        beamimpact.sweep(path, [0.02], reference=r)
    with pytest.raises(beamimpact.InputError, match="--dt"):
        beamimpact.sweep(path, [])
    with pytest.raises(beamimpact.InputError, match="jobs"):
        beamimpact.sweep(path, [0.02], jobs=0)
    # progress is not taken (the library prints one line per run): the call says so and runs.
    with pytest.warns(DeprecationWarning, match="progress"):
        assert [row["steps"] for row in beamimpact.sweep(path, [0.02], progress=False)] == [200]
    # A point the method refuses (dt above S1's critical step) is a row with its status.
    rows = beamimpact.sweep(path, [0.02, 1.0], reference="exact", out=tmp_path / "refused")
    assert "status" not in rows[0] and rows[1]["status"] == "not applicable" and rows[1]["message"]


# The peak is this process's own (VmHWM, kB): getrusage's ru_maxrss survives fork and exec, so it
# would start at the test process's peak (a sweep earlier in the session) and hide the run's.
MEMORY = r"""
import sys, beamimpact
steps, keep = int(sys.argv[1]), sys.argv[2] == "1"
r = beamimpact.run(sys.argv[3], overrides={"time.dt": 4.0 / steps, "time.allow_long_run": True},
                   history=keep, progress=False)
assert r.summary["steps"] == steps
print(next(l.split()[1] for l in open("/proc/self/status") if l.startswith("VmHWM:")))  # kB
"""


def peak_kb(steps, keep):
    p = subprocess.run([sys.executable, "-c", MEMORY, str(steps), "1" if keep else "0", str(PAPER / "s1_central.toml")],
                       capture_output=True, text=True, env=os.environ)
    assert p.returncode == 0, p.stderr
    return int(p.stdout)


def test_no_history_no_memory_growth_over_a_million_steps():
    # A kept row costs >= 150 bytes (18 doubles plus its vector of contact samples), so 1e6 kept
    # rows would add >= 150 MB; without history the peak may differ from a 1e4-step run only by
    # allocator noise (10 MB). The 1e5-step run that keeps its rows shows the measure bites.
    small, big = peak_kb(10_000, False), peak_kb(1_000_000, False)
    assert big - small < 10_000
    assert peak_kb(100_000, True) - small > 10_000


def test_fields_from_python_read_back(tmp_path):
    # run(fields=True) writes the same VTK fields as `beamimpact run --fields`; read_fields streams
    # them: one frame per history row, the striker node (A's end, node 10) moving as ua in history
    # (the fields in single precision, the default: history's double rounded to the nearest float).
    r = beamimpact.run(PAPER / "s1_central.toml", out=tmp_path / "s1", fields=True, progress=False)
    frames = list(beamimpact.read_fields(tmp_path / "s1"))
    assert [t for t, _ in frames] == list(r.columns["t"])
    assert [f["displacement"][10, 0] for _, f in frames] == [float(np.float32(u)) for u in r.columns["ua_x"]]
    assert all(len(f["points"]) == 22 for _, f in frames)
    with pytest.raises(beamimpact.InputError, match="output.fields.*output directory"):
        beamimpact.run(PAPER / "s1_central.toml", fields=True, progress=False)


def test_threads_change_no_bit_and_are_reported(tmp_path):
    """threads=2 and 3 split the paper integrator's element sweep with the one-thread sums: the
    same history bits (S2 refined to 20 + 40 elements, through its contact), the count used in
    the summary (at most the cores this process may use: more are capped to them), and the same
    run as the CLI's --threads."""
    cores = min(os.cpu_count() or 1, len(os.sched_getaffinity(0)))
    scene = beamimpact.load_scene(PAPER / "s2_transverse.toml",
                                  {"bodies.A.elements": 20, "bodies.B.elements": 40, "time.dt": "auto"})
    one = beamimpact.run(scene, progress=False, threads=1)
    assert one.summary["threads"] == 1
    for threads in (2, 3):
        r = beamimpact.run(scene, progress=False, threads=threads)
        assert r.summary["threads"] == min(threads, cores)
        assert r.summary["settings"]["threads"]["asked"] == threads
        for name, column in one.columns.items():
            assert np.array_equal(column, r.columns[name]), (threads, name)
    out = tmp_path / "cli"
    p = cli("run", PAPER / "s2_transverse.toml", "--out", out, "--quiet", "--threads", 2,
            "--set", "bodies.A.elements=20", "--set", "bodies.B.elements=40", "--set", 'time.dt="auto"')
    assert p.returncode == 0, p.stderr
    assert json.loads((out / "summary.json").read_text())["threads"] == min(2, cores)
    assert beamimpact.read_run(out).columns["R"].tolist() == one.columns["R"].tolist()


def test_threads_default_is_written(tmp_path):
    """Without threads the default is used and written: 1 for a model of 66 equations."""
    r = beamimpact.run(PAPER / "s1_central.toml", progress=False)
    assert r.summary["threads"] == 1
    assert r.summary["assumed"]["paper.threads"].startswith("1: the machine's")


@pytest.mark.parametrize("bad", [0, -1, 1.5, "2", True])
def test_bad_threads_raise_input_error_naming_it(bad):
    with pytest.raises(beamimpact.InputError, match="threads: expected a whole number of threads 1..1024"):
        beamimpact.run(PAPER / "s1_central.toml", progress=False, threads=bad)
