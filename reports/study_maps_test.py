"""study_maps.py on a hand-made 2 x 2 grid study: every label inside the saved maps, no provenance
text in them (the version and the command are not drawn into the images); the manifest PREFIX_figures.json says how each map was
made (command, version, scene, date) and its caption names the study and the reference."""
import json
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "reports"))
import study_maps  # noqa: E402
from figure_checks import drawn_text, texts_outside  # noqa: E402

STUDY = {"study": "fixture_study", "file": "verification/studies/fixture.toml", "scene": "s4_oblique_90",
         "set": ["paper.n=10"], "reference": {"method": "ida", "set": ["ida.rtol=1e-8"]},
         "version": "0.0.0+fixture", "design": "grid", "norms": ["impulse"], "energy_growth_bound": 0.01,
         "breaks": [{"metric": "impacts", "above": 0}],
         "cases": [{"method": "paper", "parameters": {"alpha0": a, "mu": m}, "norms": {"impulse": 0.01 * (1 + a + m)},
                    "status": "ok", "broke": a > 10} for a in (5.0, 45.0) for m in (0.0, 0.3)]}


def test_maps_draw_no_provenance_and_the_manifest_says_it(tmp_path, monkeypatch):
    (tmp_path / "study.json").write_text(json.dumps(STUDY))
    drawn = []

    def capture(fig, path, **kwargs):
        assert texts_outside(fig) == []  # every label inside the saved image
        drawn.append(drawn_text(fig))
        fig.savefig(path, **kwargs)

    monkeypatch.setattr(study_maps, "save_figure_atomic", capture)
    command = "fixture-study-command --grid"
    monkeypatch.setattr(sys, "argv", ["study_maps.py", str(tmp_path), "--x", "alpha0", "--y", "mu",
                                      "--command", command])
    study_maps.main()
    assert len(drawn) == 2
    for text in drawn:
        assert "0.0.0+fixture" not in text and command not in text and "fixture.toml" not in text
    with open(tmp_path / "study_figures.json") as f:
        manifest = json.load(f)
    assert [f["png"] for f in manifest["figures"]] == ["study_error.png", "study_stability.png"]
    for f in manifest["figures"]:
        assert (tmp_path / f["png"]).is_file()
        assert f["command"] == command and f["version"] == "0.0.0+fixture" and f["scene"] == "s4_oblique_90"
        assert f["made"].endswith("Z")
        assert "verification/studies/fixture.toml" in f["caption"] and "ida ida.rtol=1e-8" in f["caption"]
