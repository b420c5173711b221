"""beamimpact.score and beamimpact.conform: the library calls of `beamimpact score` and `beamimpact
conform`, with no program path given. Verdicts against known answers: the paper integrator's rigid
rod against its closed form (to round-off), S1's impulse against the exact one under a tolerance
it meets and one it misses, and the shipped example against a copy of it that breaks one output
rule. Run from ctest (PYTHONPATH=build/python, BEAMIMPACT_EXE, BEAMIMPACT_SOURCE)."""
import json
import os
import subprocess
from pathlib import Path

import pytest

import beamimpact

SOURCE = Path(os.environ["BEAMIMPACT_SOURCE"])
S1 = SOURCE / "verification" / "scenes" / "paper" / "s1_central.toml"


def s1_card(folder: Path, tol: float) -> Path:
    """A cards file of S1 against its exact solution with one gate on the impulse (as score_test.cc)."""
    folder.mkdir(parents=True, exist_ok=True)
    f = folder / "cards.toml"
    f.write_text(f'[[card]]\nscene = "{S1}"\nset = "paper"\nreference = {{ method = "exact" }}\nsource = ""\n'
                 f'quantities = [{{ metric = "impulse", tol = {tol}, why = "derived: a test\'s bound" }}]\n')
    return f


def test_score_passes_the_rigid_rod_against_its_closed_form_as_the_command_does(tmp_path):
    # rigid_rod_oblique (the exact set): a plastic closure of a rigid rod, the paper integrator's
    # impulse, final velocity and energy equal the closed form to round-off (tolerances 1e-9 in
    # verification/cards.toml, measured about 1e-14): every quantity passes.
    opts = dict(sets=["exact"], scenes=["rigid_rod_oblique"], ladder=False, cache=tmp_path / "cache")
    r = beamimpact.score("paper", tmp_path / "py", **opts)
    card = r["scorecards"]["paper"]
    assert r["passed"] and r["exit_code"] == 0 and card["verdict"] == "passed"
    assert [s["scene"] for s in card["scenes"]] == ["rigid_rod_oblique"]
    statuses = {q["metric"]: q["status"] for q in card["scenes"][0]["quantities"]}
    assert set(statuses.values()) == {"pass"}, statuses
    assert card["counts"] == {"pass": len(statuses)}
    impulse = next(q for q in card["scenes"][0]["quantities"] if q["metric"] == "impulse")
    assert impulse["error"] < 1e-9  # the closed form to round-off
    # The file written is the dict returned, and the command line it records is the command's.
    assert r["paths"] == [tmp_path / "py" / "scorecard.json"]
    written = json.loads(r["paths"][0].read_text())
    assert written["verdict"] == "passed" and written["counts"] == card["counts"]
    assert r["command"].startswith("beamimpact score paper --out ") and "--no-ladder" in r["command"]
    # The command with the same options: the same verdict and the same errors.
    p = subprocess.run([os.environ["BEAMIMPACT_EXE"], "score", "paper", "--out", str(tmp_path / "cli"),
                        "--sets", "exact", "--scenes", "rigid_rod_oblique", "--no-ladder",
                        "--cache", str(tmp_path / "cache")], capture_output=True, text=True, cwd=SOURCE)
    assert p.returncode == 0, p.stdout + p.stderr
    cli = json.loads((tmp_path / "cli" / "scorecard.json").read_text())
    assert [(q["metric"], q["status"], q["error"]) for q in cli["scenes"][0]["quantities"]] == \
        [(q["metric"], q["status"], q["error"]) for q in card["scenes"][0]["quantities"]]


def test_score_fails_a_tolerance_the_mesh_error_exceeds(tmp_path):
    # The paper integrator's S1 impulse is 3.6 % off the exact one at 10 elements (the mesh error,
    # docs/benchmarks.md): it passes under 4 % and fails under 1 %, "fail" in the JSON, and the
    # verdict line says "fail (outside tolerance)".
    common = dict(sets=["paper"], ladder=False, cache=tmp_path / "cache")
    ok = beamimpact.score("paper", tmp_path / "ok", cards=s1_card(tmp_path / "c4", 0.04), **common)
    assert ok["passed"] and ok["scorecards"]["paper"]["verdict"] == "passed"
    bad = beamimpact.score("paper", tmp_path / "bad", cards=s1_card(tmp_path / "c1", 0.01), **common)
    card = bad["scorecards"]["paper"]
    assert not bad["passed"] and bad["exit_code"] == 1 and card["verdict"] == "failed"
    q = card["scenes"][0]["quantities"][0]
    assert q["status"] == "fail" and 0.01 < q["error"] < 0.04
    assert "1 fail (outside tolerance)" in card["verdict_line"]
    assert card["statuses"]["fail"] == "fail (outside tolerance)" and card["statuses"]["failed"] == "run failed"
    # The ratchet: against the passing scorecard with its error halved, today's error grew.
    base = json.loads(ok["paths"][0].read_text())
    base["scenes"][0]["quantities"][0]["error"] /= 2
    (tmp_path / "half.json").write_text(json.dumps(base))
    grown = beamimpact.score("paper", tmp_path / "again", cards=s1_card(tmp_path / "c4", 0.04),
                             baseline=tmp_path / "half.json", **common)
    assert grown["exit_code"] == 1 and len(grown["scorecards"]["paper"]["ratchet"]["grown"]) == 1


def test_score_refuses_bad_options_as_input_errors(tmp_path):
    with pytest.raises(beamimpact.InputError, match="--sets"):
        beamimpact.score("paper", tmp_path, sets=["papers"])
    with pytest.raises(beamimpact.InputError, match="--rungs"):
        beamimpact.score("paper", tmp_path, rungs=2)
    with pytest.raises(beamimpact.InputError, match="--timeout"):
        beamimpact.score("paper", tmp_path, timeout=0)
    with pytest.raises(beamimpact.InputError, match="--scenes"):
        beamimpact.score("paper", tmp_path, scenes=["no_such_scene"])


def example_copy(folder: Path, name: str, mode: str) -> Path:
    """A methods file declaring the shipped example behind testdata/broken_copy.py MODE as `name`."""
    f = folder / f"{name}.toml"
    f.write_text(f'[[method]]\nname = "{name}"\n'
                 f'command = ["/usr/bin/python3", "{SOURCE}/tools/beamimpact/testdata/broken_copy.py", "{mode}", '
                 '"{scene}", "--out", "{out}", "--quiet", "--beamimpact", "{beamimpact}", "--dt", "{dt}"]\n'
                 'check = ["/usr/bin/python3", "-c", "import scipy"]\n'
                 'accepts = { dt = true, several_contacts = true, timoshenko = true, bending = true, '
                 'node_to_surface = true, loads = true }\n')
    return f


def test_conform_passes_the_example_and_fails_a_copy_that_breaks_a_rule(tmp_path):
    honest = beamimpact.conform("example", tmp_path / "example", scenes=["end_to_end"])
    assert honest["passed"] and honest["verdict"] == "passed", [x for x in honest["results"] if not x["passed"]]
    assert honest["counts"]["broken"] == 0 and honest["counts"]["checks"] > 0
    assert honest["paths"] == [tmp_path / "example" / "junit.xml", tmp_path / "example" / "conform.json"]
    assert json.loads(honest["paths"][1].read_text())["verdict"] == "passed"
    # history.csv's force x 1.5 with the summary's impulse untouched: the summary no longer agrees
    # with its own rows (the consistency rule), and only that rule breaks.
    broken = beamimpact.conform("copy_r_x1_5", tmp_path / "broken", scenes=["end_to_end"],
                                methods=[example_copy(tmp_path, "copy_r_x1_5", "r-x1.5")])
    assert not broken["passed"] and broken["verdict"] == "failed"
    assert {x["rule"] for x in broken["results"] if not x["passed"]} == {"consistency"}
    assert broken["counts"]["broken"] >= 1
    with pytest.raises(beamimpact.InputError, match="built in"):
        beamimpact.conform("paper", tmp_path / "paper")
    with pytest.raises(beamimpact.InputError, match="--scenes"):
        beamimpact.conform("example", tmp_path / "x", scenes=["sideways"])
