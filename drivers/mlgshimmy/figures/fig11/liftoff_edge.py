"""Fig. 11's wheel lift-off edge, by simulation (shared.liftoff): the edge
speed bisected on a few loads, its two ends on V = V_MAX bisected in F*."""
from __future__ import annotations

import numpy
import os
from typing import Any, Dict, List, Mapping, Optional, Sequence

from mlgshimmy.figures.fig11.orbits import ROLLING
from mlgshimmy.figures.fig11.plane import F_MAX, F_MIN, FREEPLAY, V_MAX
from mlgshimmy.shared import gear
from mlgshimmy.shared import liftoff
from mlgshimmy.shared import paths

# The lift-off edge: bisected in V on these loads (from a speed without
# lift-off within liftoff.T_END up to V_MAX), its ends in F* on V = V_MAX.
LIFTOFF_LOADS = numpy.round(numpy.arange(0.1, 0.71, 0.1), 2)
LIFTOFF_FROM = 500.0   # m/s: the bisection's lower end (no lift-off there; liftoff.bisected)


def liftoff_rundir() -> str:
    return paths.rundir("fig11/liftoff")


def liftoff_speed(Fstar: float) -> Dict[str, Optional[float]]:
    """A part: the lowest speed (to liftoff.TOL_V) at which a wheel lifts
    off at load F*, bisected from LIFTOFF_FROM up to V_MAX; None if none
    does at V_MAX."""
    csv = os.path.join(liftoff_rundir(), f"F{Fstar:.2f}.csv")
    V = liftoff.edge_speed(csv, Fstar, LIFTOFF_FROM, V_MAX, case=FREEPLAY,
                           params=gear.simulator_params(), rolling=ROLLING)
    print(f"fig11: lift-off at F* = {Fstar:.2f}: "
          + (f"from V = {V:.1f} m/s" if V else f"none up to V = {V_MAX:g} m/s"), flush=True)
    return {"Fstar": float(Fstar), "V": V}


def liftoff_loads(speeds: Sequence[Mapping[str, Any]]) -> List[int]:
    """The indices of the loads with lift-off in the parts' speeds [{"Fstar",
    "V" or None}] (they must be contiguous)."""
    found = [k for k, s in enumerate(speeds) if s["V"] is not None]
    if found != list(range(found[0], found[-1] + 1) if found else []):
        raise RuntimeError("fig11: the loads with lift-off are not contiguous: "
                           f"{[s['Fstar'] for s in speeds if s['V'] is not None]}")
    return found


# the two ends of the lift-off edge on V = V_MAX: {part: the outermost load
# with lift-off on that side (index into the loads with lift-off)}
LIFTOFF_ENDS = {"liftoff_end_light": 0, "liftoff_end_heavy": -1}


def liftoff_end(parts: Mapping[str, Any], part: str) -> Dict[str, Optional[float]]:
    """A part: the load on V = V_MAX where lift-off starts beyond the
    outermost load with lift-off (LIFTOFF_ENDS), bisected in F* towards
    its neighbour without ({"Fstar": ..., or None if no load lifts a wheel
    off}), or towards the plane's edge (F_MIN, F_MAX) beyond the outermost
    load.  The bracket's ends are not run again where the liftoff_<F*>
    parts ran both at V_MAX."""
    speeds = [parts[f"liftoff_{Fstar:.2f}"] for Fstar in LIFTOFF_LOADS]
    found = liftoff_loads(speeds)
    if not found:
        return {"Fstar": None}
    end = LIFTOFF_ENDS[part]
    inside = found[end]
    outside = inside + (-1 if end == 0 else 1)
    csv = os.path.join(liftoff_rundir(), f"{part}.csv")
    options = dict(case=FREEPLAY, params=gear.simulator_params(), rolling=ROLLING)
    if 0 <= outside < len(speeds):
        Fstar = liftoff.edge_load(csv, V_MAX, speeds[outside]["Fstar"],
                                  speeds[inside]["Fstar"], checked=True, **options)
    else:
        # the outermost load lifts a wheel off (a side-stay geometry can
        # move the edge): the bracket's other end is the plane's edge
        Fstar = liftoff.edge_load(csv, V_MAX, F_MIN if end == 0 else F_MAX,
                                  speeds[inside]["Fstar"], **options)
    print(f"fig11: lift-off on V = {V_MAX:g} from F* = {Fstar:.4f}", flush=True)
    return {"Fstar": Fstar}


def liftoff_edge(speeds: Sequence[Mapping[str, Any]],
                 ends: Sequence[Mapping[str, Any]]) -> Optional[Dict[str, Any]]:
    """The lift-off edge from the parts' speeds [{"Fstar", "V" or None}] and
    its two ends' loads on V = V_MAX (liftoff_end): {"points": [(V, F*)],
    "V", "Fstar": a smooth curve through them (PCHIP in F*)}, or None if no
    load lifts a wheel off."""
    from scipy.interpolate import PchipInterpolator   # 0.3 s to load: not in every part job
    found = liftoff_loads(speeds)
    if not found:
        return None
    points = [(V_MAX, ends[0])] + [(speeds[k]["V"], speeds[k]["Fstar"]) for k in found] \
        + [(V_MAX, ends[1])]
    V, F = numpy.array(points).T
    Fs = numpy.linspace(F[0], F[-1], 200)
    return {"points": points, "V": numpy.minimum(PchipInterpolator(F, V)(Fs), V_MAX),
            "Fstar": Fs}
