"""beamimpact.study against `beamimpact study`: one library call (study::run_study), so the same
study.json, and its norms are the ones theory gives. Run from ctest (PYTHONPATH=build/python,
BEAMIMPACT_EXE, BEAMIMPACT_SOURCE)."""
import json
import os
import subprocess
from pathlib import Path

import pytest

import beamimpact

EXE = os.environ["BEAMIMPACT_EXE"]
S1 = Path(os.environ["BEAMIMPACT_SOURCE"]) / "verification" / "scenes" / "paper" / "s1_central.toml"

# S1 (two equal free rods, A at 1 m/s) by the exact solution and the paper method at two steps,
# each against the exact solution with A at 2 m/s. The exact S1 transfers A's whole momentum:
# impulse 4 v N s, a force of 2 v N for 2 s (references.md), so the exact run's errors against the
# reference are |4 - 8| / 8 = 0.5 in impulse and |2 - 4| / 4 = 0.5 in peak force
# (verification/study/run_point_test.cc). Six runs of S1, well under a second.
STUDY = f"""
name = "s1_speed"
description = "S1 at 1 m/s, exact and paper, against the exact solution at 2 m/s"
scene = "{S1}"
methods = ["exact", "paper"]
reference = {{ method = "exact", set = ["bodies.A.velocity=[2.0, 0.0]"] }}
norms = ["impulse", "peak_R"]
breaks = [{{ metric = "impulse", above = 0.4 }}]

[[parameter]]
name = "dt"
key = "time.dt"
values = [0.02, 0.01]
"""


@pytest.fixture()
def study_file(tmp_path):
    f = tmp_path / "s1_speed.toml"
    f.write_text(STUDY)
    return f


def test_study_call_equals_the_command_and_theory(tmp_path, study_file):
    p = subprocess.run([EXE, "study", str(study_file), "--out", str(tmp_path / "cli")], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    cli = json.loads((tmp_path / "cli" / "study.json").read_text())
    py = beamimpact.study(study_file, tmp_path / "py")
    # study.json has no timing field (timing.json has them): the whole document is equal.
    assert py == cli
    assert py == json.loads((tmp_path / "py" / "study.json").read_text())
    for name in ("study.csv", "study.md", "timing.json", "timing.csv"):
        assert (tmp_path / "py" / name).is_file(), name
    cases = {(c["parameters"]["dt"], c["method"]): c for c in py["cases"]}
    assert sorted(cases) == [(0.01, "exact"), (0.01, "paper"), (0.02, "exact"), (0.02, "paper")]
    assert all(c["status"] == "ok" and c["reference_status"] == "ok" for c in cases.values())
    for dt in (0.02, 0.01):
        # The exact solutions are exact to roundoff; 1e-9 relative covers it.
        assert cases[(dt, "exact")]["norms"]["impulse"] == pytest.approx(0.5, abs=1e-9)
        assert cases[(dt, "exact")]["norms"]["peak_R"] == pytest.approx(0.5, abs=1e-9)
        # The paper method's impulse is within 5 % of 4 N s on S1 (test_module's compare test), so
        # its error against 8 N s is within 0.5 +- 0.05 / 2.
        assert abs(cases[(dt, "paper")]["norms"]["impulse"] - 0.5) <= 0.025
        assert cases[(dt, "paper")]["steps"] == round(4.0 / dt)
        assert cases[(dt, "exact")]["broke"] and cases[(dt, "paper")]["broke"]  # 0.5 > the bound 0.4


def test_study_keeps_runs_and_refuses_bad_files(tmp_path, study_file):
    beamimpact.study(study_file, tmp_path / "kept", keep_runs=True, fresh=True)
    assert (tmp_path / "kept" / "runs" / "0.reference" / "summary.json").is_file()
    bad = tmp_path / "bad.toml"
    bad.write_text(STUDY.replace('methods = ["exact", "paper"]', 'methods = ["nonesuch"]'))
    with pytest.raises(beamimpact.InputError, match=r"bad\.toml.*methods"):
        beamimpact.study(bad, tmp_path / "bad")
