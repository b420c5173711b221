"""The work-precision figures drawn from every committed set (reports/work_precision/*/
work_precision.json): every text of the figure (tick labels, axis labels, legend, title) lies
inside the figure's own box, so nothing is clipped when it is saved; the figure holds no
provenance footer (the caption carries command and version, once); the README's hero panel
keeps its text at least 10 pt at 100 dpi, readable at half size."""
import glob
import json
import os
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "reports"))
import wp_figures  # noqa: E402
from figure_checks import drawn_text, texts_outside  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

SETS = sorted(glob.glob(os.path.join(ROOT, "reports", "work_precision", "*", "work_precision.json")))


@pytest.mark.parametrize("path", SETS, ids=[os.path.basename(os.path.dirname(p)) for p in SETS])
def test_every_label_inside_and_no_footer(path):
    with open(path) as f:
        res = json.load(f)
    fig = wp_figures.draw(res)
    try:
        assert texts_outside(fig) == []
        drawn = drawn_text(fig)
        assert res["version"] not in drawn and res["command"] not in drawn  # provenance is the caption's
    finally:
        plt.close(fig)


def test_hero_is_readable_small():
    with open(os.path.join(ROOT, "reports", "work_precision", wp_figures.HERO, "work_precision.json")) as f:
        res = json.load(f)
    fig = wp_figures.draw(res, ("impulse",), hero=True)
    try:
        assert texts_outside(fig) == []
        ax = fig.axes[0]
        sizes = [t.get_fontsize() for t in [ax.xaxis.label, ax.yaxis.label, fig._suptitle]
                 + ax.get_legend().get_texts() + ax.get_xticklabels() + ax.get_yticklabels()]
        assert min(sizes) >= 10  # pt; at 100 dpi, 10 pt is 14 px: 7 px at a half-size thumbnail
    finally:
        plt.close(fig)


def test_manifest_says_how_each_figure_was_made(tmp_path):
    # Two committed sets copied: figures.json names each one's command, scene and version (its
    # work_precision.json's), the date and a caption; equal_error.md is written beside it.
    import shutil
    for name in ("s1_central", "s4_oblique_90"):
        shutil.copytree(os.path.join(ROOT, "reports", "work_precision", name), tmp_path / name)
    wp_figures.write_manifest(str(tmp_path))
    with open(tmp_path / "figures.json") as f:
        figs = json.load(f)["figures"]
    assert [f["png"] for f in figs] == ["s1_central/work_precision.png", "s4_oblique_90/work_precision.png"]
    for f in figs:
        with open(tmp_path / os.path.dirname(f["png"]) / "work_precision.json") as g:
            res = json.load(g)
        assert (f["command"], f["scene"], f["version"]) == (res["command"], res["scene"], res["version"])
        assert f["made"].endswith("Z") and f["caption"].startswith("Reference: ")
    assert (tmp_path / "equal_error.md").is_file()
