"""beamimpact.verify against `beamimpact verify`: the same matrix items give the same norms.json
numbers (timings aside) and the same verdict, and the verdict follows the gates. Run from ctest
(PYTHONPATH=build/python, BEAMIMPACT_EXE, BEAMIMPACT_SOURCE)."""
import json
import os
import subprocess
import sys
from pathlib import Path

import beamimpact

SOURCE = Path(os.environ["BEAMIMPACT_SOURCE"])
sys.path.insert(0, str(SOURCE / "tools" / "bench"))
from compare_norms import leaves  # noqa: E402  (every number of a JSON tree, timings left out)

MATRIX = SOURCE / "verification" / "matrix.toml"


def test_verify_call_equals_the_command(tmp_path):
    """The call (its runs in the Python process), the command (in its own process) and the
    command with --isolate (each run a `beamimpact run` process) give the same numbers."""
    only = "s1_central"
    p = subprocess.run([os.environ["BEAMIMPACT_EXE"], "verify", str(MATRIX), "--out", str(tmp_path / "cli"),
                        "--only", only, "--jobs", "2"], capture_output=True, text=True, cwd=SOURCE)
    cli = json.loads((tmp_path / "cli" / "norms.json").read_text())
    subprocess.run([os.environ["BEAMIMPACT_EXE"], "verify", str(MATRIX), "--out", str(tmp_path / "iso"),
                    "--only", only, "--jobs", "2", "--isolate"], capture_output=True, text=True, cwd=SOURCE)
    isolated = json.loads((tmp_path / "iso" / "norms.json").read_text())
    iso_logs = [f.read_text() for f in (tmp_path / "iso" / "runs").glob("*/run.log")]
    assert iso_logs and all(" run " in log.splitlines()[0] for log in iso_logs)  # each a process
    assert dict(leaves(isolated["items"])) == dict(leaves(cli["items"]))
    py = beamimpact.verify(MATRIX, tmp_path / "py", only=only, jobs=2)
    assert json.loads((tmp_path / "py" / "norms.json").read_text())["verdict"] == py["verdict"]
    assert dict(leaves(py["items"])) == dict(leaves(cli["items"]))
    assert py["gates"] > 0 and py["verdict"] == cli["verdict"]
    # The verdict is the gates' (a complete run): PASS exactly when every gate passed, as the exit status.
    every_gate = all(g["passed"] for item in py["items"] for g in item["gates"])
    assert (py["verdict"] == "PASS") == every_gate == (p.returncode == 0)


def test_verify_resumes_unless_fresh(tmp_path, capfd):
    """Again into the same `out`, verify takes every run recorded as finished with the same input
    (as the command does); fresh=True (the command's --fresh) runs them all again and says so in
    the command line it records."""
    only = "s1_central paper dt=0.01 vs"
    first = beamimpact.verify(MATRIX, tmp_path, only=only)
    assert "resumed:" not in capfd.readouterr().err
    runs = sorted((tmp_path / "runs").glob("*/finished.json"))
    assert len(runs) >= 2  # the case's run and its reference
    again = beamimpact.verify(MATRIX, tmp_path, only=only)
    assert f"resumed: {len(runs)} of {len(runs)} runs finished earlier" in capfd.readouterr().err
    fresh = beamimpact.verify(MATRIX, tmp_path, only=only, fresh=True)
    assert "resumed:" not in capfd.readouterr().err
    assert "--fresh" in fresh["command"] and "--fresh" not in again["command"]
    assert dict(leaves(fresh["items"])) == dict(leaves(again["items"])) == dict(leaves(first["items"]))


def test_verify_needs_no_program(tmp_path):
    """beamimpact.verify, score and conform run on the library: with no beamimpact program on
    PATH nor in BEAMIMPACT_EXE, a verify of S1 still runs and passes (its runs are calls in the
    Python process: run.log says so)."""
    env = {k: v for k, v in os.environ.items() if k != "BEAMIMPACT_EXE"}
    env["PATH"] = "/usr/bin:/bin"
    code = ("import beamimpact, sys; r = beamimpact.verify(sys.argv[1], sys.argv[2], only='s1_central paper dt=0.01 vs'); "
            "sys.exit(0 if r['verdict'] == 'PASS' else 1)")
    p = subprocess.run([sys.executable, "-c", code, str(MATRIX), str(tmp_path)], env=env, capture_output=True,
                       text=True, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    logs = [f.read_text() for f in (tmp_path / "runs").glob("*/run.log")]
    assert logs and all(log.startswith("in process: beamimpact::run(") for log in logs)
