"""Bad input of every kind raises beamimpact.InputError naming the file, its one name. Run from
ctest (PYTHONPATH=build/python)."""
import pytest

import beamimpact


def test_bad_input_has_one_name():
    assert not hasattr(beamimpact, "SceneError")
    assert issubclass(beamimpact.InputError, ValueError)


def test_run_directory_without_summary_names_the_file(tmp_path):
    (tmp_path / "history.csv").write_text("t,R\n0,0\n")
    with pytest.raises(beamimpact.InputError, match=r"summary\.json.*expected summary\.json of a complete run"):
        beamimpact.read_run(tmp_path)
