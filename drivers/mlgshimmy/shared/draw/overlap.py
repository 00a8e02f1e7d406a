"""Text that overlaps other text in a drawn figure: titles, axis labels,
tick labels, names of points, annotations and legend entries, compared by
their bounding boxes as rendered.  draw.save reports every overlap it finds
(one line each); tests/figures/test_figure_style.py requires none."""
from __future__ import annotations

from typing import Any, List, Tuple

import matplotlib


def _undrawn_ticks(fig) -> set:
    """The labels of ticks outside their axis's view: laid out, not drawn."""
    out = set()
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            lo, hi = sorted(axis.get_view_interval())
            tol = 1e-9 * max(1.0, abs(lo), abs(hi))
            for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                if not lo - tol <= tick.get_loc() <= hi + tol:
                    out.update((id(tick.label1), id(tick.label2)))
    return out


def _texts(fig) -> List[matplotlib.text.Text]:
    """Every text the figure draws (visible, not empty)."""
    undrawn = _undrawn_ticks(fig)
    return [t for t in fig.findobj(matplotlib.text.Text)
            if t.get_visible() and t.get_text().strip() and id(t) not in undrawn]


def overlaps(fig: Any, slack: float = 1.0) -> List[Tuple[str, str]]:
    """[(text, text)] of every pair of drawn texts whose boxes overlap by
    more than `slack` pixels each way."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in _texts(fig)]
    out = []
    for i, (a, box_a) in enumerate(boxes):
        for b, box_b in boxes[i + 1:]:
            wide = min(box_a.x1, box_b.x1) - max(box_a.x0, box_b.x0)
            high = min(box_a.y1, box_b.y1) - max(box_a.y0, box_b.y0)
            if wide > slack and high > slack:
                out.append((a, b))
    return out
