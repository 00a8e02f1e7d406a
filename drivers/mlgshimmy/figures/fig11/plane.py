"""The (V, F*) plane of Fig. 11: its ranges, the freeplay, the slice loads
and the grids the region map is painted on."""
from __future__ import annotations

from typing import Any, Mapping, Sequence

import numpy

from mlgshimmy.shared import branches
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import freeplay
from mlgshimmy.shared import gear
from mlgshimmy.shared import stationary

F_MIN, F_MAX = 0.02, 3.5
V_MIN, V_MAX = ct.V_MIN, ct.V_MAX
FREEPLAY = freeplay.NOMINAL
# the gear's changes ({} at the paper's, shared.gear) and every
# parameter the figure's models have besides V and F*
GEOMETRY = gear.parameters()
MODEL = {**FREEPLAY, **GEOMETRY}
# loads of the diagrams in V: denser where the low-load structure is; with
# side-stay angles one on the plane's lower edge too, for the structure
# below the first load (at both geometries run, a tongue of instability of
# the high-frequency orbit, F* < 0.032, V 60-200 m/s).  The paper's gear
# keeps its reference set's loads: its diagram at F_MIN ends at 79.7 m/s
# with no fold and no torus point.
EDGE_SLICE = () if stationary.symmetric(MODEL) else (F_MIN,)
SLICES = numpy.concatenate((EDGE_SLICE, numpy.arange(0.0625, 2.0, 0.125),
                            numpy.arange(2.125, 3.5, 0.25)))
F_GRID = numpy.arange(F_MIN, F_MAX + 1e-9, 0.01)
V_GRID = numpy.arange(V_MIN, V_MAX + 1e-9, 0.5)
STOP = {"Fstar": [F_MIN, F_MAX], "V": [V_MIN, V_MAX]}
V_SCAN = ct.SPEED_SCAN


def distance(point: Mapping[str, float], branch: Mapping[str, Any]) -> float:
    """The distance from `point` ({"V", "F*"}) to a branch drawn as a
    polyline through its points (in V/V_MAX and F*/F_MAX): to the nearest
    chord, not the nearest point, so that it does not grow with the
    branch's step (a torus curve's steps reach 5 m/s)."""
    x = numpy.c_[numpy.asarray(branch["V"], float) / V_MAX,
                 numpy.asarray(branch["Fstar"], float) / F_MAX]
    p = numpy.array([point["V"] / V_MAX, point["Fstar"] / F_MAX])
    if len(x) == 1:
        return float(numpy.hypot(*(x[0] - p)))
    return float(numpy.min(branches.chord_distances(x, p)))


ON_CURVE_TOL = 0.01   # in V/V_MAX, F*/F_MAX: a point this close to a curve lies on it


def on_curves(point: Mapping[str, float], curves: Sequence[Sequence[Mapping[str, Any]]],
              tol: float = ON_CURVE_TOL) -> bool:
    """Whether `point` ({"V", "Fstar"}) lies on one of the curves (lists of
    branches; distance below tol)."""
    return any(distance(point, branch) < tol for curve in curves for branch in curve)
