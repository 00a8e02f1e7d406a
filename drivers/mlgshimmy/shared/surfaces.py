"""Surfaces of periodic orbits over two parameters lofted between slices
(one-parameter diagrams at fixed values of the second parameter), as
quadrilaterals with a stability flag each; no AUTO import.

    curve = {"V": ..., "amp": ..., "stable": ...}     # one orbit family of a slice
    quads, stable = loft([(y1, {"high": curve1}), (y2, {"high": curve2})],
                         apexes={"high": [(V, y)]}, scale=(200.0, 0.5))

A slice holds at most one curve per key (a sheet, e.g. the high-frequency
orbits).  Each curve is cut into pieces monotone in V at its turns (folds),
and piece k of one slice is joined to piece k of the next, so that the
folds of neighbouring slices meet along one crease.  A slice with fewer
pieces gets empty ones at its start (where the curve leaves its Hopf point):
a fold born at a degenerate Hopf point has zero length there.  Joined pieces
are resampled at equal arclength in scaled (V, amp) and their points paired.
"""
from __future__ import annotations

from typing import Any, List, Mapping, Optional, Sequence, Tuple

import numpy
from numpy.typing import ArrayLike

TURN = 0.2         # [V units]: a turn in V counts once V has gone back this far
RETRACE = 0.01     # relative amplitude difference below which a turn retraces
POINTS = 40        # resampled points per piece
Piece = Tuple[numpy.ndarray, numpy.ndarray, numpy.ndarray]   # V, amplitude, stable


def turns(V: numpy.ndarray, tol: float = TURN) -> List[int]:
    """Indices where V turns back by more than tol (hysteresis: wiggles of
    AUTO's first steps from a Hopf point are not turns)."""
    V = numpy.asarray(V, dtype=float)
    found, direction, ext = [], 0.0, 0
    for i in range(1, len(V)):
        if direction == 0.0:
            if abs(V[i] - V[0]) > tol:
                direction, ext = numpy.sign(V[i] - V[0]), i
        elif direction * (V[i] - V[ext]) > 0:
            ext = i
        elif direction * (V[ext] - V[i]) > tol:
            found.append(ext)
            direction, ext = -direction, i
    return found


def _retraces(V, amp, before, after):
    """Whether the points `after` a turn lie on the piece `before` it (AUTO
    going back along the same orbits): equal amplitude, within RETRACE, at
    the quarter points of the V range both cover."""
    lo = max(V[before].min(), V[after].min())
    hi = min(V[before].max(), V[after].max())
    if hi - lo < 0.5 * numpy.ptp(V[before]):
        return False
    for v in lo + (hi - lo) * numpy.array([0.25, 0.5, 0.75]):
        a, b = (numpy.interp(v, *zip(*sorted(zip(V[s], amp[s])))) for s in (before, after))
        if abs(a - b) > RETRACE * max(abs(a), abs(b)):
            return False
    return True


def pieces(curve: Mapping[str, ArrayLike]) -> List[Piece]:
    """The curve cut at its turns into pieces monotone in V, [(V, amp,
    stable)], up to the first turn after which it retraces itself."""
    V, amp = numpy.asarray(curve["V"], float), numpy.asarray(curve["amp"], float)
    stable = numpy.asarray(curve["stable"], bool)
    cuts = [0] + turns(V) + [len(V) - 1]
    out = []
    for k in range(len(cuts) - 1):
        s = slice(cuts[k], cuts[k + 1] + 1)
        if out and _retraces(V, amp, slice(cuts[k - 1], cuts[k] + 1), s):
            break
        out.append((V[s], amp[s], stable[s]))
    return out


def resample(piece: Piece, scale: Tuple[float, float], n: int = POINTS) -> Piece:
    """n points of a piece at equal arclength in (V/scale[0], amp/scale[1]):
    (V, amp, stable) arrays."""
    V, amp, stable = piece
    step = numpy.hypot(numpy.diff(V) / scale[0], numpy.diff(amp) / scale[1])
    s = numpy.r_[0.0, numpy.cumsum(step)]
    if s[-1] == 0.0:
        return numpy.full(n, V[0]), numpy.full(n, amp[0]), numpy.full(n, stable[0])
    t = numpy.linspace(0.0, s[-1], n)
    nearest = numpy.clip(numpy.searchsorted(s, t), 0, len(s) - 1)
    return numpy.interp(t, s, V), numpy.interp(t, s, amp), stable[nearest]


def _point(V, amp, stable=True):
    return (numpy.array([V]), numpy.array([amp]), numpy.array([stable]))


def _strip(y1, piece1, y2, piece2, scale):
    """Quads [(4, 3)] and their stability between two pieces at y1, y2; a
    quad is stable if at least two of its corners are."""
    (V1, a1, s1), (V2, a2, s2) = (resample(p, scale) for p in (piece1, piece2))
    if len(piece1[0]) == 1:
        s1 = s2
    if len(piece2[0]) == 1:
        s2 = s1
    P = numpy.c_[V1, numpy.full_like(V1, y1), a1]
    Q = numpy.c_[V2, numpy.full_like(V2, y2), a2]
    quads = numpy.stack([P[:-1], P[1:], Q[1:], Q[:-1]], axis=1)
    votes = s1[:-1].astype(int) + s1[1:] + s2[1:] + s2[:-1]
    return quads, votes >= 2


def _join(y1, pieces1, y2, pieces2, scale):
    """The strips between two slices' pieces of one sheet, the shorter list
    padded at its start with its first point."""
    n = max(len(pieces1), len(pieces2))
    a, b = ([_point(p[0][0][0], p[0][1][0])] * (n - len(p)) + p for p in (pieces1, pieces2))
    return [_strip(y1, p, y2, q, scale) for p, q in zip(a, b)]


def loft(slices: Sequence[Tuple[float, Mapping[str, Any]]],
         apexes: Optional[Mapping[str, Sequence[Tuple[float, float]]]] = None,
         scale: Tuple[float, float] = (1.0, 1.0)) -> Tuple[numpy.ndarray, numpy.ndarray]:
    """The surfaces through the slices [(y, {key: curve})] (in order of y),
    as (quads of shape (n, 4, 3) with corners (V, y, amp), stable mask (n,)).
    Neighbouring slices holding the same key are joined.  apexes = {key:
    [(V, y)]}: points where a sheet shrinks to zero amplitude (the turning
    point of its Hopf curve), joined to the neighbouring slice holding the
    key when the other neighbour does not hold it.  scale: (V, amp) units of the arclength."""
    ys = [y for y, _ in slices]
    cut = [{key: pieces(c) for key, c in curves.items()} for _, curves in slices]
    strips = []
    for k in range(len(slices) - 1):
        for key in set(cut[k]) & set(cut[k + 1]):
            strips += _join(ys[k], cut[k][key], ys[k + 1], cut[k + 1][key], scale)
    for key, points in (apexes or {}).items():
        for V, y in points:
            near = [k for k in range(len(ys)) if ys[k] < y][-1:] + \
                   [k for k in range(len(ys)) if ys[k] > y][:1]
            holding = [k for k in near if key in cut[k]]
            if len(holding) == 1:   # the sheet ends between the slices
                strips += _join(y, [_point(V, 0.0)], ys[holding[0]], cut[holding[0]][key],
                                scale)
    if not strips:
        return numpy.zeros((0, 4, 3)), numpy.zeros(0, dtype=bool)
    return (numpy.concatenate([q for q, _ in strips]),
            numpy.concatenate([s for _, s in strips]))
