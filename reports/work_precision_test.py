"""work_precision.py --quick on S1 into a temporary folder: every in-process point timed at least
3 times with CPU min <= max, a start-up entry for every method on the diagram and for the
program, the load average recorded, errors against the exact solution; the equal-error ratios'
log-log interpolation and range on made-up fronts; bad options refused with exit 2. Timings are
checked for structure and units only (speed is measured in the reports, not asserted here)."""
import json
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.environ.get("BEAMIMPACT_BUILD_DIR", os.path.join(ROOT, "build"))
SCRIPT = os.path.join(ROOT, "reports", "work_precision.py")
sys.path.insert(0, os.path.join(ROOT, "reports"))
import work_precision  # noqa: E402


def run(*args):
    return subprocess.run(["/usr/bin/python3", SCRIPT, "--build", BUILD, *args], cwd=ROOT, capture_output=True,
                          text=True)


def test_quick_set_has_repeated_timings_and_startups(tmp_path):
    r = run("--quick", "--scenes", "s1_central", "--out", str(tmp_path / "out"), "--runs", str(tmp_path / "runs"))
    assert r.returncode == 0, r.stderr[-2000:]
    with open(tmp_path / "out" / "s1_central" / "work_precision.json") as f:
        res = json.load(f)
    assert (tmp_path / "out" / "s1_central" / "work_precision.png").stat().st_size > 0
    ok = [p for p in res["points"] if p["status"] == "ok"]
    in_process = [p for p in ok if p["timed"] == "in process"]
    assert {p["method_name"] for p in in_process} == {"paper", "ida"}  # S1's in-process curves in --quick
    for p in in_process:
        assert p["repeats"] >= 3 and len(p["cpu_seconds_all"]) == p["repeats"] == len(p["wall_seconds_all"])
        assert 0 < p["cpu_seconds_min"] <= p["cpu_seconds_max"] and 0 < p["wall_seconds_min"] <= p["wall_seconds_max"]
        assert p["cost"]["steps"] > 0
    for p in ok:
        lo, hi = p["loadavg_1min"]
        assert 0 <= lo <= hi
        # S1's exact solution is d'Alembert's; the paper-size meshes are 0.5-5 % off in impulse.
        assert 0 < p["error"]["impulse"] < 0.1 and math.isfinite(p["error"]["ub.rel_l2"])
    for m in {p["method_name"] for p in res["points"]}:
        assert m in res["startup"], m  # every method on the diagram has its start-up beside it
    for m in ("paper", "ida"):
        s = res["startup"][m]
        assert s["process_cpu_seconds_min"] > 0 and s["in_process_cpu_seconds_min"] > 0 and "startup_cpu_seconds" in s
    assert res["startup"]["beamimpact --version"]["cpu_seconds_min"] > 0
    assert [e["impulse_error"] for e in res["equal_error"]] == [0.03, 0.01, 0.001]
    with open(tmp_path / "out" / "figures.json") as f:
        manifest = json.load(f)
    assert [fig["png"] for fig in manifest["figures"]] == ["s1_central/work_precision.png"]
    assert "not reached" in open(tmp_path / "out" / "equal_error.md").read()  # S1 at 0.1 %: no --quick rung


def point(method, cpu, cpu_max, err):
    return {"method": method, "status": "ok", "cpu_seconds_min": cpu, "cpu_seconds_max": cpu_max,
            "error": {"impulse": err}}


def test_equal_error_interpolates_in_log_log_and_gives_the_range():
    # paper: errors 5 % and 0.5 % at 1 s and 2 s; at 1 % the log-log line gives 2^(log 5 / log 10) s.
    # IDA: the same front at twice the CPU time, so the ratio is 2; the repeats' max are 1.5x the min
    # for the paper and equal for IDA, so the range is 2 / 1.5 .. 2.
    pts = [point("paper (dt)", 1.0, 1.5, 0.05), point("paper (dt)", 2.0, 3.0, 0.005),
           point("IDA (rtol)", 2.0, 2.0, 0.05), point("IDA (rtol)", 4.0, 4.0, 0.005)]
    at1 = work_precision.equal_error(pts)[1]
    assert math.isclose(at1["cpu_s"]["paper"], 2 ** (math.log(5) / math.log(10)), rel_tol=1e-12)
    assert math.isclose(at1["ratio_to_paper"]["IDA"], 2.0, rel_tol=1e-12)
    assert all(math.isclose(a, b, rel_tol=1e-12) for a, b in zip(at1["ratio_range"]["IDA"], (2 / 1.5, 2.0)))
    at01 = work_precision.equal_error(pts)[2]
    assert at01["cpu_s"]["paper"] is None and "paper not reached" in at01["text"]


def test_bad_options_exit_2_with_one_line(tmp_path):
    for args in (["--sizes", "s3_surface_10_x4"], ["--scenes", "nope"], ["--repeats", "0"]):
        r = run(*args, "--out", str(tmp_path), "--runs", str(tmp_path))
        assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, (args, r.stderr)
        assert r.stderr.startswith("work_precision: ")
