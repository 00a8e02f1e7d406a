"""Names of marked special points, placed when the figure is final.

register(ax, x, y, "H1") remembers a name at a data point; place(fig)
(draw.save calls it) draws every name of every axes next to its point,
where it overlaps no name already placed (nor touches one: PAD), no marked
point and as few curves as possible, inside the axes.  Points of one name
closer than MERGE pixels are one cluster: one marker, named with their
count (four torus points within 10 m/s: one triangle, "TR ×4").
Positions are found in display space after the figure is laid out, so they
hold for the saved file (bbox_inches="tight" only crops)."""
from __future__ import annotations

from typing import Any, List, Sequence, Tuple

import numpy

from mlgshimmy.shared.draw import palette

FONTSIZE = 8
GAP = 3.0       # points between a marker and its name
MERGE = 14.0    # pixels: points of one name closer than this are drawn once
PAD = 0.25      # of a name's height: the space kept between two names
LEADER_FROM = 4  # candidates from this one on are far enough to need a leader line
# offsets of the name's lower-left corner from the point, in units of the
# name's (width, height) plus GAP; first wins when nothing is in the way
CANDIDATES = ((0, 0), (0, -1), (-1, 0), (-1, -1), (-0.5, 0.3), (-0.5, -1.3),
              (0, 0.9), (0, -1.9), (-1, 0.9), (-1, -1.9), (0.6, -0.5), (-1.6, -0.5),
              (0.6, 1.6), (-1.6, 1.6), (0.6, -2.6), (-1.6, -2.6))


def register(ax: Any, x: float, y: float, name: str, marker: Any = None) -> None:
    """Name the point (x, y) when the figure is placed; marker: its Line2D,
    hidden if the point joins a cluster of its name."""
    if name:
        ax.__dict__.setdefault("_mlg_labels", []).append((float(x), float(y), name, marker))


def _segments(ax):
    """Display-space segments (n, 2, 2) of the axes' lines."""
    out = []
    for line in ax.get_lines():
        if not line.get_visible() or line.get_linestyle() in ("None", "", " ", "none"):
            continue
        xy = line.get_xydata()
        if len(xy) < 2:
            continue
        d = line.get_transform().transform(xy)
        good = numpy.isfinite(d).all(axis=1)
        seg = numpy.stack([d[:-1], d[1:]], axis=1)[good[:-1] & good[1:]]
        out.append(seg)
    return numpy.concatenate(out) if out else numpy.zeros((0, 2, 2))


def _crossings(segments, box):
    """How many segments cross the box (x0, y0, x1, y1): Liang-Barsky."""
    if not len(segments):
        return 0
    x0, y0, x1, y1 = box
    p, q = segments[:, 0], segments[:, 1] - segments[:, 0]
    lo = numpy.zeros(len(p))
    hi = numpy.ones(len(p))
    keep = numpy.ones(len(p), dtype=bool)
    for axis, (a, b) in enumerate(((x0, x1), (y0, y1))):
        d = q[:, axis]
        still = numpy.abs(d) < 1e-12
        keep &= ~still | ((p[:, axis] >= a) & (p[:, axis] <= b))
        with numpy.errstate(divide="ignore", invalid="ignore"):
            ta, tb = (a - p[:, axis]) / d, (b - p[:, axis]) / d
        t0, t1 = numpy.minimum(ta, tb), numpy.maximum(ta, tb)
        lo = numpy.where(still, lo, numpy.maximum(lo, t0))
        hi = numpy.where(still, hi, numpy.minimum(hi, t1))
    return int(numpy.count_nonzero(keep & (lo <= hi)))


def _overlaps(a, b, pad=0.0):
    return a[0] < b[2] + pad and b[0] < a[2] + pad and a[1] < b[3] + pad and b[1] < a[3] + pad


def clusters(points: Sequence[Tuple[float, float, str, Any]],
             markers: Sequence[Tuple[float, float]]) -> List[List[int]]:
    """[[index of its first point, count]] of the clusters: points of one
    name chained closer than MERGE pixels (display positions `markers`).
    The markers of all but a cluster's first point are hidden."""
    owner, out = [], []
    for k, ((_, _, name, marker), at) in enumerate(zip(points, markers)):
        near = next((owner[j] for j in range(k) if points[j][2] == name
                     and numpy.hypot(*(at - markers[j])) < MERGE), None)
        if near is None:
            owner.append(len(out))
            out.append([k, 1])
            continue
        owner.append(near)
        out[near][1] += 1
        if marker is not None:
            marker.set_visible(False)
    return out


def place_axes(ax: Any, renderer: Any) -> None:
    points = ax.__dict__.get("_mlg_labels", [])
    if not points or getattr(ax, "name", "") == "3d":
        return
    scale = ax.figure.dpi / 72.0
    frame = ax.get_window_extent(renderer).extents
    segments = _segments(ax)
    markers = [ax.transData.transform((x, y)) for x, y, _, _ in points]
    inside = [k for k, at in enumerate(markers)
              if frame[0] - 1 <= at[0] <= frame[2] + 1 and frame[1] - 1 <= at[1] <= frame[3] + 1]
    points, markers = [points[k] for k in inside], [markers[k] for k in inside]
    placed = []
    for first, count in clusters(points, markers):
        (x, y, name, _), at = points[first], markers[first]
        name = name if count == 1 else f"{name} ×{count}"
        text = ax.annotate(name, (x, y), xytext=(0, 0), textcoords="offset points",
                           fontsize=FONTSIZE, ha="left", va="bottom", zorder=6,
                           annotation_clip=False)
        box = text.get_window_extent(renderer)
        w, h = box.width, box.height
        gap = GAP * scale
        best = None
        for k, (cx, cy) in enumerate(CANDIDATES):
            dx = cx * w + (gap if cx >= 0 else -gap)
            dy = cy * h + (gap if cy >= 0 else -gap)
            rect = (at[0] + dx, at[1] + dy, at[0] + dx + w, at[1] + dy + h)
            score = 0.0
            if rect[0] < frame[0] or rect[2] > frame[2] or rect[1] < frame[1] or rect[3] > frame[3]:
                score += 100
            score += 20 * sum(_overlaps(rect, other, PAD * h) for other in placed)
            score += 10 * sum(_overlaps(rect, (m[0] - 3 * scale, m[1] - 3 * scale,
                                               m[0] + 3 * scale, m[1] + 3 * scale))
                              for m, p in zip(markers, points)
                              if p[3] is None or p[3].get_visible())
            score += _crossings(segments, rect)
            if best is None or score < best[0]:
                best = (score, dx, dy, rect, k)
            if score == 0:
                break
        _, dx, dy, rect, k = best
        text.xyann = (dx / scale, dy / scale)
        if k >= LEADER_FROM:   # away from its point: a thin line shows whose name it is
            near = (min(max(at[0], rect[0]), rect[2]) - at[0],
                    min(max(at[1], rect[1]), rect[3]) - at[1])
            ax.annotate("", (x, y), xytext=(near[0] / scale, near[1] / scale),
                        textcoords="offset points", annotation_clip=False,
                        arrowprops={"arrowstyle": "-", "lw": 0.5, "color": palette.NEUTRAL,
                                    "shrinkA": 0, "shrinkB": 2.5})
        placed.append(rect)


def place(fig: Any) -> None:
    """Place the registered names of every axes of fig (once)."""
    if not any(ax.__dict__.get("_mlg_labels") for ax in fig.axes):
        return
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for ax in fig.axes:
        place_axes(ax, renderer)
        ax.__dict__["_mlg_labels"] = []
