"""The figures of the report scripts that draw from runs (paper_figures.py, beam_theories.py,
plot_effects_benchmark.py, plot_sweep.py, stick_threshold.py), drawn from their committed data or,
where the data is runs that are not committed, from a small hand-made fixture: every label lies
inside the saved image (nothing clipped) and nothing of how the figure was made (the version, the
command) is drawn into it; that is said once, in the manifest the page reads (command, scene,
version, date, caption). The work-precision figures and the study maps have their own tests
(wp_figures_test.py, study_maps_test.py) with the same checks (figure_checks.py)."""
import csv
import json
import math
import os
import sys
import types

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "reports"))
import beam_theories  # noqa: E402
import paper_figures  # noqa: E402
import plot_effects_benchmark  # noqa: E402
import plot_sweep  # noqa: E402
import stick_threshold  # noqa: E402
from figure_checks import drawn_text, texts_outside  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

FIXTURE_VERSION = "0.0.0+fixture"
MADE_KEYS = ("png", "title", "command", "scene", "version", "made", "caption")


def check(fig, *provenance):
    """Every label inside the image and none of the `provenance` strings drawn."""
    try:
        assert texts_outside(fig) == []
        drawn = drawn_text(fig)
        for p in provenance:
            assert p not in drawn  # how it was made is the caption's, not the image's
    finally:
        plt.close(fig)


def capture_saves(monkeypatch, module):
    """Replaces `module`'s save_figure_atomic: each figure is checked by the caller, then saved."""
    figs = []

    def save(fig, path, **kwargs):
        figs.append((os.path.basename(path), fig))
        fig.canvas.draw()
        fig.savefig(path, **kwargs)

    monkeypatch.setattr(module, "save_figure_atomic", save)
    return figs


# Beam theories: the committed ladders (reports/beam_theories/ladders.json), both problems.
LADDERS = json.load(open(os.path.join(ROOT, "reports", "beam_theories", "ladders.json")))


@pytest.mark.parametrize("name", list(LADDERS["problems"]))
def test_beam_theories(name):
    check(beam_theories.draw(LADDERS["problems"][name]), LADDERS["version"], beam_theories.COMMAND)


def test_beam_theories_manifest(tmp_path):
    beam_theories.write_figures_json(str(tmp_path / "figures.json"), LADDERS)
    m = json.load(open(tmp_path / "figures.json"))
    assert [f["png"] for f in m["figures"]] == ["ladders.png", "ball_on_beam.png"]
    for f in m["figures"]:
        assert all(f[k] for k in MADE_KEYS) and f["version"] == LADDERS["version"]
        assert f["command"] == beam_theories.COMMAND and "dt ladder" in f["caption"]


# Per-effect benchmarks: the committed benchmark JSON; its version is the committed manifest's
# (the JSON was measured before the version was stamped into it).
def test_effects_benchmark():
    ctx, times = plot_effects_benchmark.load(os.path.join(ROOT, "reports", "benchmarks", "effects_benchmark.json"))
    version = plot_effects_benchmark.measured_version(ctx, os.path.join(ROOT, "reports", "benchmarks", "figures.json"))
    assert version.startswith("0.1.0+")  # the committed manifest's, not "unknown" nor this build's
    check(plot_effects_benchmark.draw(plot_effects_benchmark.summarise(times)), version, "--benchmark_out")


# The paper's figures: hand-made runs (history.csv) of the paper integrator and IDA on every scene,
# the exact method refused on the S4 scenes; the refusal is named in the caption, not drawn.
COLUMNS = ("t", "R", "va_x", "vb_x", "ua_x", "ub_x", "ua_y", "ub_y", "va_y", "vb_y")


def fake_run(path, scale):
    os.makedirs(path)
    with open(os.path.join(path, "history.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for k in range(301):
            t = 0.01 * k
            w.writerow([t] + [scale * (i + 1) * math.sin(t + i) for i in range(len(COLUMNS) - 1)])


def test_paper_figures(tmp_path, monkeypatch):
    runs, notes = {}, {}
    for s in paper_figures.SCENES:
        for m, scale in (("paper", 1.0), ("ida", 1.02), ("exact", 0.99)):
            if m == "exact" and s.startswith("s4"):
                runs[(s, m)] = None
                notes[(s, m)] = f"exact ({s}) refused: fixture refusal with friction"
                continue
            runs[(s, m)] = str(tmp_path / f"{s}.{m}")
            fake_run(runs[(s, m)], 1e3 * scale)  # N-sized values: the widest tick labels
    figs = capture_saves(monkeypatch, paper_figures)
    F = paper_figures.Figures(types.SimpleNamespace(out=str(tmp_path)), runs, notes, FIXTURE_VERSION)
    paper_figures.all_figures(F)
    assert [p for p, _ in figs] == [f"fig{n:02d}.png" for n in range(6, 15)]
    for _, fig in figs:
        check(fig, FIXTURE_VERSION, paper_figures.COMMAND, "refused")
    for f in F.manifest:
        assert all(k in f for k in MADE_KEYS) and f["version"] == FIXTURE_VERSION
        s4 = "s4_oblique" in f["scene"]
        assert ("Not shown: exact (s4_oblique_" in f["caption"]) == s4  # the refusal is said, where it applies


# A sweep: a hand-made sweep folder (two meshes, three steps each).
def test_plot_sweep(tmp_path, monkeypatch):
    with open(tmp_path / "sweep.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["dt", "mesh", "status", "steps", "solver_seconds", "process_seconds", "impulse"])
        for mesh in (1, 2):
            for k, dt in enumerate((0.01, 0.005, 0.0025)):
                w.writerow([dt, mesh, "ok", int(3 / dt), 0.01 * 2 ** k * mesh, 0.02, 0.1 / mesh * 0.5 ** k])
    json.dump({"scene": "verification/scenes/paper/s1_central.toml", "method": "paper", "reference": "exact"},
              open(tmp_path / "sweep.json", "w"))
    figs = capture_saves(monkeypatch, plot_sweep)
    command = "beamimpact sweep fixture --dt 0.01,0.005,0.0025"
    plot_sweep.plot(types.SimpleNamespace(dir=str(tmp_path), title="S1 fixture", command=command,
                                          version=FIXTURE_VERSION, norm="impulse"))
    assert [p for p, _ in figs] == ["sensitivity.png", "work_precision.png"]
    for _, fig in figs:
        check(fig, FIXTURE_VERSION, command, "s1_central.toml")
    m = json.load(open(tmp_path / "figures.json"))
    for f in m["figures"]:
        assert all(f[k] for k in MADE_KEYS) and (tmp_path / f["png"]).is_file()
        assert f["command"] == command and f["version"] == FIXTURE_VERSION and f["scene"].endswith("s1_central.toml")


# The stick threshold: a hand-made result of two angles (the threshold's shape, cot(alpha0) / (1 - phi)).
def test_stick_threshold():
    angles = []
    for deg in (60, 45):
        cot = 1 / math.tan(math.radians(deg))
        pts = [{"phi": (k + 0.5) / 8, "step": cot / (1 - (k + 0.5) / 8), "from_closure": cot} for k in range(8)]
        angles.append({"alpha0_deg": deg, "scene": f"verification/scenes/paper/s4_oblique_{deg}.toml", "dt": 8.55e-5,
                       "cot_alpha0": cot, "points": pts})
    result = {"command": "reports/stick_threshold.py --fixture", "version": FIXTURE_VERSION, "angles": angles}
    check(stick_threshold.draw(result), FIXTURE_VERSION, result["command"])
    assert f"beamimpact {FIXTURE_VERSION}" in stick_threshold.markdown(result)  # the table says it, in words
