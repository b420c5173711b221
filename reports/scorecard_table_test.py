"""scorecard_table.py on a scorecard worked by hand: the impulse cell says how the quantity was judged
(a ladder's limit or a single run), with its uncertainty and verdict, and counts the scene's other
quantities that do not pass; a refused scene reads `not applicable`; the committed copy names no
absolute path of the machine that made it."""
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "reports"))
import scorecard_table  # noqa: E402


def quantity(metric, status, error, judged="single run", uncertainty=0.0):
    return {"metric": metric, "status": status, "error": error, "judged": judged, "uncertainty": uncertainty,
            "tol": 0.01, "note": ""}


def card(tmp_path):
    scene_file = os.path.join(ROOT, "verification", "scenes", "benchmarks", "rod_on_wall.toml")
    return {"method": "mine", "version": "0.1.0+test", "made": "2026-01-01T00:00:00Z", "command": "beamimpact score mine",
            "references": "converged", "counts": {"pass": 2, "fail": 2, "not applicable": 1},
            "scenes": [
                {"scene": "s1_central", "file": "verification/scenes/paper/s1_central.toml", "status": "ok",
                 "reference": "exact", "reference_kind": "exact",
                 "quantities": [quantity("impulse", "pass", 0.0016, "limit", 0.0029),
                                quantity("energy_final", "pass", 1e-5, "limit", 4e-5)]},
                {"scene": "s3_surface_10", "file": "verification/scenes/paper/s3_surface_10.toml", "status": "ok",
                 "reference": "ida", "reference_kind": "ida",
                 "quantities": [quantity("impulse", "fail", 0.0059, uncertainty=6.5e-5),
                                quantity("final_velocity", "fail", 0.0069),
                                quantity("impacts", "pass", 0.0)]},
                {"scene": "rod_on_wall", "file": "verification/scenes/benchmarks/rod_on_wall.toml",
                 "status": "not applicable", "reference": "exact", "reference_kind": "exact",
                 "message": f"{scene_file}: key 'bodies[1].rigid': not applicable", "quantities": []}]}


def test_cells_say_how_each_impulse_was_judged():
    c = card(None)
    counts, (columns, rows) = scorecard_table.tables([c])
    assert counts[0] == ["method", "fail", "not applicable", "pass"] and counts[1] == [["mine", 2, 1, 2]]
    by_scene = {r[0]: r for r in rows}
    assert by_scene["s1_central"][1:] == ["exact", "limit 0.0016 ± 0.0029 (pass)"]
    # The converged IDA reference is named as such; one of the two other quantities fails.
    assert by_scene["s3_surface_10"][1:] == ["ida, converged", "0.0059 ± 6.5e-05 (fail); 1 of 2 other(s) fail"]
    assert by_scene["rod_on_wall"][2] == "not applicable"


def test_committed_copy_names_no_folder_of_the_machine(tmp_path):
    src = tmp_path / "mine"
    src.mkdir()
    (src / "scorecard.json").write_text(json.dumps(card(tmp_path)))
    out = tmp_path / "set"
    r = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "reports", "scorecard_table.py"), str(src),
                        "--set", str(out)], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    text = (out / "mine" / "scorecard.json").read_text()
    assert ROOT not in text
    assert "verification/scenes/benchmarks/rod_on_wall.toml: key 'bodies[1].rigid'" in text
    assert "limit 0.0016 ± 0.0029 (pass)" in (out / "scorecards.md").read_text()


def test_a_folder_without_a_scorecard_is_bad_input(tmp_path):
    r = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "reports", "scorecard_table.py"), str(tmp_path)],
                       capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 2 and "scorecard.json" in r.stderr
