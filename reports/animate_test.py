"""reports/animate.py on a real run: a frame and a GIF are written (valid image files whose
frame count is the number of steps used), each with its manifest (command, version, date,
caption) and with every label inside the frame and nothing of how it was made drawn into it; bad
requests fail with a clear message, exit 2.
Run from ctest (BEAMIMPACT_EXE, BEAMIMPACT_SOURCE)."""
import json
import os
import subprocess
import sys
from pathlib import Path

import matplotlib.figure
import pytest

EXE = os.environ["BEAMIMPACT_EXE"]
SOURCE = Path(os.environ["BEAMIMPACT_SOURCE"])
ANIMATE = SOURCE / "reports" / "animate.py"


def animate(*args):
    return subprocess.run([sys.executable, str(ANIMATE), *map(str, args)], capture_output=True, text=True)


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("anim") / "s2"
    subprocess.run([EXE, "run", SOURCE / "verification/scenes/paper/s2_transverse.toml", "--out", out,
                    "--fields", "--quiet", "--set", "time.end=0.5"], check=True)
    return out


def test_frame_and_gif(run_dir, tmp_path):
    p = animate(run_dir, "--frame", "0.3", "--out", tmp_path / "f.png")
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "f.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    pil = pytest.importorskip("PIL.Image", reason="python3-pil missing: the GIF writer is not available")
    p = animate(run_dir, "--every", "10", "--out", tmp_path / "a.gif")
    assert p.returncode == 0, p.stderr
    with pil.open(tmp_path / "a.gif") as gif:
        assert gif.n_frames == 6  # rows 0, 10, ..., 50 of the 51 (0.5 s / 0.01 s + 1)


def test_frame_draws_no_provenance_and_its_manifest_says_it(run_dir, tmp_path, monkeypatch):
    sys.path.insert(0, str(SOURCE / "reports"))
    import animate
    from figure_checks import drawn_text, texts_outside
    saved = []
    real = matplotlib.figure.Figure.savefig

    def capture(fig, path, **kwargs):
        assert texts_outside(fig) == []  # every label inside the frame
        saved.append(drawn_text(fig))
        real(fig, path, **kwargs)

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", capture)
    assert animate.main([str(run_dir), "--frame", "0.3", "--out", str(tmp_path / "f.png")]) == 0
    summary = json.loads((run_dir / "summary.json").read_text())
    assert len(saved) == 1 and "m/N" in saved[0]  # the scales are drawn: they are how to read it
    assert summary["version"] not in saved[0] and "animate.py" not in saved[0]
    fig = json.loads((tmp_path / "f_figures.json").read_text())["figures"][0]
    assert fig["png"] == "f.png" and fig["version"] == summary["version"] and fig["made"].endswith("Z")
    assert "reports/animate.py" in fig["command"] and "--frame 0.3" in fig["command"]


def test_clear_errors(run_dir, tmp_path):
    p = animate(run_dir, "--out", tmp_path / "a.avi")
    assert p.returncode == 2 and "expected a .gif or .mp4" in p.stderr
    p = animate(tmp_path, "--out", tmp_path / "a.gif")  # a directory without fields
    assert p.returncode == 2 and "no fields in this run directory" in p.stderr
    p = animate(run_dir, "--scale", "big")
    assert p.returncode == 2 and "--scale big" in p.stderr
