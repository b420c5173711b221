"""Every option of the Python `compare` and `sweep` against the CLI on the same runs: each option
set alone (a binding that hands one option's value to another, or drops it, gives other norms
than the CLI flag of that name), all of them at once, and each shown to change the norms (so the
equality cannot hold by the option doing nothing). Run from ctest (PYTHONPATH=build/python,
BEAMIMPACT_EXE, BEAMIMPACT_SOURCE)."""
import json
import os
import subprocess
from pathlib import Path

import pytest

import beamimpact

EXE = os.environ["BEAMIMPACT_EXE"]
PAPER = Path(os.environ["BEAMIMPACT_SOURCE"]) / "verification" / "scenes" / "paper"
S1, S2 = PAPER / "s1_central.toml", PAPER / "s2_transverse.toml"

# One value per option, each far from its default (S2 at dt 0.01 against dt 0.005: grid 0.005 s,
# window 0.1 s, merge 0.035 s, threshold 1e-6) and far from the other options' values, so a value
# passed to the wrong option changes the norms. merge 0.4 s joins S2's second and third impacts
# (0.5 s apart at most); threshold 0.3 moves the contact start and end off the closure samples.
OPTIONS = {"grid_step": ("--grid", 0.0037), "window": ("--window", 0.23), "merge_gap": ("--merge", 0.4),
           "threshold": ("--threshold", 0.3)}


def cli(*args):
    p = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return p


@pytest.fixture(scope="module")
def s2_runs(tmp_path_factory):
    """S2 by the CLI at dt 0.01 and 0.005 (both paper): output steps differ, so every default matters."""
    d = tmp_path_factory.mktemp("s2")
    cli("run", S2, "--out", d / "coarse", "--quiet", "--set", "time.dt=0.01")
    cli("run", S2, "--out", d / "fine", "--quiet", "--set", "time.dt=0.005")
    return d


def cli_compare(runs, flags, name):
    cli("compare", runs / "coarse", runs / "fine", "--json", runs / f"{name}.json", *flags)
    return json.loads((runs / f"{name}.json").read_text())


def same(got, expected):
    """The same norms (every key of every norm) and the same settings the comparison reports."""
    assert got["norms"] == expected["norms"]
    for key in ("grid_step_s", "window_s", "merge_gap_s", "force_threshold_N", "overlap_s"):
        assert got[key] == expected[key], key


@pytest.mark.parametrize("option", sorted(OPTIONS))
def test_each_compare_option_equals_its_cli_flag(s2_runs, option):
    flag, value = OPTIONS[option]
    expected = cli_compare(s2_runs, [flag, value], option)
    got = beamimpact.compare(s2_runs / "coarse", s2_runs / "fine", **{option: value})
    same(got, expected)
    # The option bites: its norms differ from the defaults' (else the equality proves nothing).
    default = beamimpact.compare(s2_runs / "coarse", s2_runs / "fine")
    assert got["norms"] != default["norms"], option


def test_all_compare_options_at_once_equal_the_cli(s2_runs):
    flags = [x for flag, value in OPTIONS.values() for x in (flag, value)]
    expected = cli_compare(s2_runs, flags, "all")
    got = beamimpact.compare(beamimpact.read_run(s2_runs / "coarse"), beamimpact.read_run(s2_runs / "fine"),
                             **{k: v for k, (_, v) in OPTIONS.items()})
    same(got, expected)


def test_compare_defaults_equal_the_cli_defaults(s2_runs):
    same(beamimpact.compare(s2_runs / "coarse", s2_runs / "fine"), cli_compare(s2_runs, [], "defaults"))


def sweep_rows(path):
    """`beamimpact sweep`'s sweep.json: dt (as the float it prints) -> {norm: value}."""
    points = json.loads(Path(path).read_text())["points"]
    return {float(p["dt"]): {n["name"]: n["value"] for n in p["comparison"]["norms"]} for p in points}


def same_rows(py_rows, cli_rows, dts):
    assert sorted(cli_rows) == sorted(dts)
    for row in py_rows:
        expected = cli_rows[row["dt"]]
        for name in beamimpact._core.sweep_norms():
            if name in expected:
                assert row[name] == expected[name], (row["dt"], name)


DTS = [0.02, 0.01]


def test_sweep_reference_method_equals_cli_sweep(tmp_path):
    # reference = a method name: both run it at the scene's own settings.
    cli("sweep", S1, "--dt", ",".join(map(str, DTS)), "--reference", "exact", "--out", tmp_path / "sw")
    rows = beamimpact.sweep(S1, DTS, reference="exact")
    same_rows(rows, sweep_rows(tmp_path / "sw" / "sweep.json"), DTS)
    assert rows[0]["impulse"] > 0.0  # against the exact solution: the paper's error is not 0


def test_sweep_method_and_reference_directory_equal_cli_sweep(tmp_path):
    # method = exact against a paper run directory: the method option reaches the runs (exact and
    # paper differ by the mesh error, about 1 % in the impulse), the directory is the reference.
    ref = tmp_path / "paper"
    cli("run", S1, "--out", ref, "--quiet", "--set", "time.dt=0.005")
    cli("sweep", S1, "--dt", ",".join(map(str, DTS)), "--method", "exact", "--reference", ref, "--out",
        tmp_path / "sw")
    rows = beamimpact.sweep(S1, DTS, method="exact", reference=str(ref))
    same_rows(rows, sweep_rows(tmp_path / "sw" / "sweep.json"), DTS)
    paper_rows = beamimpact.sweep(S1, DTS, reference=str(ref))
    assert rows[0]["impulse"] != paper_rows[0]["impulse"]
    # reference given as a Run: the same norms as the directory it was read from.
    as_run = beamimpact.sweep(S1, DTS, method="exact", reference=beamimpact.read_run(ref))
    strip = lambda rs: [{k: v for k, v in r.items() if k != "wall_seconds"} for r in rs]  # noqa: E731
    assert strip(as_run) == strip(rows)
    # A Run written by run(out=...) is its directory too.
    written = beamimpact.run(S1, "paper", {"time.dt": 0.005}, out=tmp_path / "written", progress=False)
    assert strip(beamimpact.sweep(S1, DTS, method="exact", reference=written)) == strip(rows)


def test_all_sweep_options_at_once_equal_cli_sweep(tmp_path):
    # fractions (S4-45 has dt = "auto"), meshes, jobs, threads and exe (each run a process of the
    # program, as --isolate) at once: the CLI's sweep.json numbers. Threads change no bit (the
    # split sums are the one-thread sums), so they cannot show in the norms.
    s4 = PAPER / "s4_oblique_45.toml"
    cli("sweep", s4, "--fraction", "0.5,0.25", "--mesh", "1,2", "--jobs", 2, "--threads", 2, "--isolate",
        "--out", tmp_path / "cli")
    points = json.loads((tmp_path / "cli" / "sweep.json").read_text())["points"]
    rows = beamimpact.sweep(s4, fractions=[0.5, 0.25], meshes=[1, 2], jobs=2, threads=2, exe=EXE,
                            out=tmp_path / "py")
    assert [(r["fraction"], r["mesh"]) for r in rows] == [(0.5, "1"), (0.5, "2"), (0.25, "1"), (0.25, "2")]
    for row, point in zip(rows, points):
        assert (row["mesh"], row["steps"]) == (point["mesh"], point["steps"])
        assert row["dt"] == pytest.approx(float(point["dt"]), rel=1e-5)  # sweep.json prints 6 digits
        norms = {n["name"]: n["value"] for n in point["comparison"]["norms"]}
        for name in beamimpact._core.sweep_norms():
            if name in norms:
                assert row[name] == norms[name], (row["fraction"], row["mesh"], name)
    assert rows[0]["steps"] < rows[2]["steps"] and rows[0]["impulse"] != rows[1]["impulse"]  # both bite
    logs = [f.read_text() for f in (tmp_path / "py" / "runs").glob("*/run.log")]
    assert len(logs) == 5 and all(" run " in log.splitlines()[0] and " --threads 2 " in log.splitlines()[0]
                                  for log in logs)  # each a process of exe, with the threads asked for


def test_sweep_set_equals_cli_runs_with_set(tmp_path):
    # overrides of every run (the scene written with them to a file and that file swept): the
    # CLI's runs with the same --set, compared by `compare`.
    ref = tmp_path / "ref"
    cli("run", S1, "--out", ref, "--quiet", "--method", "exact")
    rows = beamimpact.sweep(S1, DTS, reference=str(ref), overrides={"bodies.B.elements": 20})
    for row, dt in zip(rows, DTS):
        out = tmp_path / f"dt{dt}"
        cli("run", S1, "--out", out, "--quiet", "--set", f"time.dt={dt}", "--set", "bodies.B.elements=20")
        expected = {n["name"]: n["value"] for n in cli_compare_dirs(out, ref, tmp_path / f"c{dt}.json")["norms"]}
        assert row["steps"] == json.loads((out / "summary.json").read_text())["steps"]
        for name in beamimpact._core.sweep_norms():
            if name in expected:
                assert row[name] == expected[name], (dt, name)
    plain = beamimpact.sweep(S1, DTS, reference=str(ref))
    assert plain[0]["impulse"] != rows[0]["impulse"]  # 20 elements in B: another mesh error


def cli_compare_dirs(a, b, json_path):
    cli("compare", a, b, "--json", json_path)
    return json.loads(Path(json_path).read_text())
