"""@brief What the figure tests check on a drawn matplotlib figure: every label inside the image
saved from it (nothing clipped) and the words drawn into it (provenance is a caption, not a drawing)."""
from matplotlib.text import Text


def texts_outside(fig):
    """@brief What the saved figure would clip: the tight box of everything drawn (tick labels
    within the axes' view included, matplotlib's get_tightbbox) against the figure's box, and each
    visible text but tick labels (titles, axis labels, legend) by its own drawn box
    (get_window_extent). 1 px of antialiasing allowed.
    @return one line per text (or for the whole drawing) outside the image; empty when none"""
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


def drawn_text(fig):
    """@brief Every text drawn into the figure (titles, labels, legend, free text), joined by spaces."""
    return " ".join(t.get_text() for t in fig.findobj(Text) if t.get_visible())
