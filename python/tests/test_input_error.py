"""Bad input of every kind raises beamimpact.InputError naming the file (SceneError is the same
class under its earlier name). Run from ctest (PYTHONPATH=build/python)."""
import pytest

import beamimpact


def test_scene_error_is_input_error():
    assert beamimpact.SceneError is beamimpact.InputError


def test_run_directory_without_summary_names_the_file(tmp_path):
    (tmp_path / "history.csv").write_text("t,R\n0,0\n")
    with pytest.raises(beamimpact.InputError, match=r"summary\.json.*expected summary\.json of a complete run"):
        beamimpact.read_run(tmp_path)
