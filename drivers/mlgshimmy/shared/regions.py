"""Region maps whose edges are the computed curves (no AUTO import).

The curves, drawn onto a raster, cut the plane into pieces; each piece takes
the label that most of the sampled points inside it carry (points of
diagrams in one parameter, an eigenvalue grid, simulations).  So the edges
follow the curves, and the samples only say what lives between them.

    edges = curve_pixels(x, y, [(xs, ys), ...])    # bool [len(y), len(x)]
    codes, check = paint(edges, samples)           # samples: int, -1 = none

A piece holding no sample (a sliver between two curves) and the curve pixels
themselves take the label of the nearest labelled pixel.  `check` counts the
samples that disagree with their piece's label: a missing edge curve shows
up there, as two regions merged into one piece.
"""
from __future__ import annotations

from typing import Any, Dict, Iterable, Optional, Sequence, Tuple

import numpy
from numpy.typing import ArrayLike


def index_of(grid: numpy.ndarray, values: ArrayLike) -> numpy.ndarray:
    """Fractional raster index of `values` on the increasing `grid` (uneven
    grids, e.g. logarithmic, need no transform), extended linearly beyond
    its ends with the end spacing."""
    grid = numpy.asarray(grid, dtype=float)
    values = numpy.asarray(values, dtype=float)
    at = numpy.interp(values, grid, numpy.arange(len(grid)))
    below = (values - grid[0]) / (grid[1] - grid[0])
    above = len(grid) - 1 + (values - grid[-1]) / (grid[-1] - grid[-2])
    return numpy.where(values < grid[0], below, numpy.where(values > grid[-1], above, at))


def curve_pixels(x: numpy.ndarray, y: numpy.ndarray,
                 curves: Sequence[Tuple[ArrayLike, ArrayLike]]) -> numpy.ndarray:
    """[len(y), len(x)] True on the pixels each polyline (xs, ys) passes
    through: every segment sampled at least twice per pixel, so the curve is
    8-connected and 4-connected pieces cannot leak across it.  NaN breaks a
    polyline; what lies outside the raster is clipped off."""
    mask = numpy.zeros((len(y), len(x)), dtype=bool)
    for xs, ys in curves:
        i, j = index_of(y, ys), index_of(x, xs)
        for k in range(len(i) - 1):
            if not numpy.all(numpy.isfinite([i[k], i[k + 1], j[k], j[k + 1]])):
                continue
            n = int(2 * max(abs(i[k + 1] - i[k]), abs(j[k + 1] - j[k]))) + 2
            t = numpy.linspace(0.0, 1.0, n)
            ii = numpy.rint(i[k] + t * (i[k + 1] - i[k])).astype(int)
            jj = numpy.rint(j[k] + t * (j[k + 1] - j[k])).astype(int)
            inside = (ii >= 0) & (ii < len(y)) & (jj >= 0) & (jj < len(x))
            mask[ii[inside], jj[inside]] = True
    return mask


def boundary_pixels(field: numpy.ndarray) -> numpy.ndarray:
    """True where an integer raster differs from a 4-neighbour (both sides):
    the edges of a map computed pixel by pixel, e.g. an eigenvalue grid."""
    field = numpy.asarray(field)
    out = numpy.zeros(field.shape, dtype=bool)
    rows = field[1:, :] != field[:-1, :]
    cols = field[:, 1:] != field[:, :-1]
    out[1:, :] |= rows
    out[:-1, :] |= rows
    out[:, 1:] |= cols
    out[:, :-1] |= cols
    return out


def paint(edges: numpy.ndarray, samples: numpy.ndarray) -> Tuple[numpy.ndarray, Dict[str, Any]]:
    """(labels, check): each 4-connected piece of ~edges labelled by the
    most common sample label in it (samples: int raster, -1 where there is
    none), the rest by the nearest labelled pixel.  check: {"samples",
    "disagree": count, "pieces": [(row, col, n samples, {label: count})] of
    the pieces whose samples are not unanimous}."""
    from scipy import ndimage   # 0.1-0.2 s to load: only where a map is painted
    samples = numpy.asarray(samples, dtype=int)
    pieces, count = ndimage.label(~edges)
    sampled = (samples >= 0) & ~edges
    out = numpy.full(samples.shape, -1, dtype=int)
    check = {"samples": int(sampled.sum()), "disagree": 0, "pieces": []}
    found = ndimage.find_objects(pieces)
    for k in range(1, count + 1):
        window = found[k - 1]
        inside = pieces[window] == k
        votes = samples[window][inside & sampled[window]]
        if votes.size == 0:
            continue
        labels, counts = numpy.unique(votes, return_counts=True)
        out[window][inside] = labels[numpy.argmax(counts)]
        if len(labels) > 1:
            check["disagree"] += int(votes.size - counts.max())
            rows, cols = numpy.nonzero(inside)
            check["pieces"].append((int(rows.mean() + window[0].start),
                                    int(cols.mean() + window[1].start), int(votes.size),
                                    {int(a): int(b) for a, b in zip(labels, counts)}))
    if (out < 0).all():
        raise ValueError("regions.paint: no sample lies off the curves")
    nearest = ndimage.distance_transform_edt(out < 0, return_distances=False,
                                             return_indices=True)
    return out[tuple(nearest)], check


# The attractors that coexist in a region of the (V, F*) plane, as the bits
# of its code: one table for Fig. 11's region map and the atlas's cells.
ATTRACTORS = {"straight": 1, "low": 2, "high": 4, "yaw": 8, "quasi": 16, "liftoff": 32}
ATTRACTOR_NAMES = {1: "straight rolling", 2: "low-frequency shimmy", 4: "high-frequency shimmy",
                   8: "off-centre yaw equilibria", 16: "quasi-periodic shimmy",
                   32: "wheel lift-off (the model's domain ends)"}
# an atlas end state that left the model's domain is the lift-off attractor
END_STATE_ATTRACTOR = {"domain": "liftoff"}


def code(kinds: Iterable[str]) -> int:
    """The region code of a set of attractors (or of atlas end-state kinds)."""
    bits = 0
    for kind in kinds:
        bits |= ATTRACTORS[END_STATE_ATTRACTOR.get(kind, kind)]
    return bits



# the kinds of attractor a region map is shown by (an animation each), and
# the start of the simulation that reaches each (shared.motion.STARTS)
SHOWN = {"straight": "rolling", "low": "shimmy", "high": "shimmy", "quasi": "shimmy",
         "yaw": "yawed"}


def deepest(x: numpy.ndarray, y: numpy.ndarray,
            inside: numpy.ndarray) -> Optional[Tuple[float, float]]:
    """The point (x, y) of the mask inside[y, x] farthest from its edge and
    from the grid's (distances in units of the grid's ranges; of several as
    far, as in a band, the one nearest their middle), or None if the mask
    is empty."""
    from scipy import ndimage
    if not inside.any():
        return None
    steps = ((y[1] - y[0]) / (y[-1] - y[0]), (x[1] - x[0]) / (x[-1] - x[0]))
    depth = ndimage.distance_transform_edt(numpy.pad(inside, 1), sampling=steps)[1:-1, 1:-1]
    rows, cols = numpy.nonzero(depth >= depth.max() * (1 - 1e-9))
    middle = numpy.hypot((rows - rows.mean()) * steps[0], (cols - cols.mean()) * steps[1])
    row, col = rows[numpy.argmin(middle)], cols[numpy.argmin(middle)]
    return round(float(x[col]), 6), round(float(y[row]), 6)


def representatives(x: numpy.ndarray, y: numpy.ndarray,
                    found: numpy.ndarray) -> Dict[str, Dict[str, Any]]:
    """{kind: {"x", "y", "alone", "start"}} for each kind of SHOWN found in
    the map found[y, x] (codes of ATTRACTORS): the deepest point (deepest)
    of the region where it is the only stable state ("alone": any start
    reaches it), or else of those where it is one of several (its start,
    SHOWN, decides)."""
    out = {}
    for kind, start in SHOWN.items():
        bit = ATTRACTORS[kind]
        for alone, inside in ((True, found == bit), (False, (found & bit) != 0)):
            point = deepest(x, y, inside)
            if point:
                out[kind] = {"x": point[0], "y": point[1], "alone": alone, "start": start}
                break
    return out
