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
from matplotlib.text import Text  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

SETS = sorted(glob.glob(os.path.join(ROOT, "reports", "work_precision", "*", "work_precision.json")))


def texts_outside(fig):
    """What the saved figure would clip: the tight box of everything drawn (tick labels within the
    axes' view included, matplotlib's get_tightbbox) against the figure's box, and each visible
    text but tick labels (titles, axis labels, legend) by its own drawn box (get_window_extent).
    1 px of antialiasing allowed."""
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    w, h = fig.bbox.width, fig.bbox.height
    out = []
    tight = fig.get_tightbbox(r).transformed(fig.dpi_scale_trans)  # inches -> pixels
    if tight.x0 < -1 or tight.y0 < -1 or tight.x1 > w + 1 or tight.y1 > h + 1:
        out.append(f"drawn content spans x {tight.x0:.0f}..{tight.x1:.0f}, y {tight.y0:.0f}..{tight.y1:.0f} of {w:.0f}x{h:.0f}")
    ticks = {id(t) for ax in fig.axes for t in ax.get_xticklabels(which="both") + ax.get_yticklabels(which="both")}
    for t in fig.findobj(Text):
        if id(t) in ticks or not t.get_visible() or not t.get_text().strip():
            continue
        b = t.get_window_extent(r)
        if b.x0 < -1 or b.y0 < -1 or b.x1 > w + 1 or b.y1 > h + 1:
            out.append(f"{t.get_text()!r} at x {b.x0:.0f}..{b.x1:.0f}, y {b.y0:.0f}..{b.y1:.0f} of {w:.0f}x{h:.0f}")
    return out


@pytest.mark.parametrize("path", SETS, ids=[os.path.basename(os.path.dirname(p)) for p in SETS])
def test_every_label_inside_and_no_footer(path):
    with open(path) as f:
        res = json.load(f)
    fig = wp_figures.draw(res)
    try:
        assert texts_outside(fig) == []
        drawn = " ".join(t.get_text() for t in fig.findobj(Text))
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
