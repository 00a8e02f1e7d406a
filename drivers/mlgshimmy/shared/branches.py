"""Reading AUTO branches (parseB/bifDiag branch objects), with no AUTO
import: the labelled points of a branch and its split by stability.

    for index, label, kind in labelled_points(branch): ...
    for xs, ys, stable in segments(branch, "V", "psi_amp"): ...
"""
from __future__ import annotations

from typing import Any, List, Optional, Tuple

import numpy


def labelled_points(branch: Any, kind: Optional[str] = None) -> List[Tuple[int, int, str]]:
    """[(point index, label, type)] of the labelled special points of one
    branch, in order (of type `kind` only, if given).  AUTO also lists
    unlabelled stability entries ({"No Label": ...}); they are skipped."""
    found = []
    for index in branch.labels.getIndices():
        for ty, info in list(branch.labels[index].items()):
            if "LAB" in info and kind in (None, ty):
                found.append((index, info["LAB"], ty))
    return found


def stable_mask(branch: Any) -> numpy.ndarray:
    """Per point: True where stable.  AUTO's stability() lists the last point
    index of each run of equal stability, negative for stable runs."""
    mask = numpy.zeros(len(branch), dtype=bool)
    start = 0
    for end in branch.stability():
        mask[start:abs(end)] = end < 0
        start = abs(end)
    return mask


def runs_of(mask: numpy.ndarray, overlap: bool = True) -> List[slice]:
    """Slices of equal values of a boolean array; with overlap each reaches
    one point into the next, so that plotted segments join."""
    mask = numpy.asarray(mask)
    out, start = [], 0
    for i in range(1, len(mask) + 1):
        if i == len(mask) or mask[i] != mask[start]:
            out.append(slice(start, min(i + int(overlap), len(mask))))
            start = i
    return out


def segments(branch: Any, x: str, y: str) -> List[Tuple[numpy.ndarray, numpy.ndarray, bool]]:
    """One branch split into runs of equal stability: [(xs, ys, stable)]."""
    xs, ys = numpy.asarray(branch[x]), numpy.asarray(branch[y])
    stable = stable_mask(branch)
    return [(xs[s], ys[s], bool(stable[s.start])) for s in runs_of(stable)]


def chord_distances(x: numpy.ndarray, p: numpy.ndarray) -> numpy.ndarray:
    """[len(x) - 1] distances from the point p to each chord x[k] -> x[k + 1]
    of a polyline x ([n, 2], scaled as the caller wants): to the chord's
    nearest point, its ends included."""
    a, chord = x[:-1], numpy.diff(x, axis=0)
    t = numpy.clip(numpy.einsum("ij,ij->i", p - a, chord)
                   / numpy.maximum(numpy.einsum("ij,ij->i", chord, chord), 1e-300), 0.0, 1.0)
    return numpy.hypot(*(a + t[:, None] * chord - p).T)
