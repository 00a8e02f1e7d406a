"""The allowed freeplay kappa* of eq. (17) and the window points of Fig. 18
from eigenvalue scans of straight rolling (no AUTO): the growth of each
frequency band, where it changes sign in y_fp, the least unstable y_fp over
the speeds up to V_LIMIT, and its minimum over the loads (with the oleo's
stage switch, shared.stage_switch)."""
from __future__ import annotations

from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import mlgmodel, rolling, spectrum
from mlgshimmy.shared.freeplay import EPSILON, width
from mlgshimmy.shared.rolling_state import rolling_state
from mlgshimmy.shared.stage_switch import stage_switch_loads, stage_switch_window
from mlgshimmy.shared.yfp_runs import V_LIMIT, V_MIN, YFP_MAX, YFP_MIN, values

BANDS = {"low": (1e-6, 8.0), "high": (8.0, numpy.inf), "real": (-1.0, 1e-6)}
KAPPA_GRID = numpy.geomspace(YFP_MIN, YFP_MAX, 61)
# The loads of the envelope of section IV.E, F* <= 2 (F* = 0 lifts a wheel off).
ENVELOPE_LOADS = numpy.round(numpy.arange(0.1, 2.0001, 0.05), 3)


def growth(Fstar: float, yfp: float, V: float, scaling: str = "fixed",
           parameter_set: str = "figures", **model: Any) -> Dict[str, float]:
    """{band: largest real part of the eigenvalues of straight rolling whose
    frequency |Im|/2pi lies in the band} (-inf if none), and "any": the
    largest real part of all.  `model` overrides parameters or constants by
    name (e.g. strut_variant=1, c_psi=410, a side-stay geometry).  Where
    straight rolling has ended at a fold in y_fp (side-stay angles: the
    links jump across the freeplay, a real eigenvalue has crossed zero)
    "real" and "any" are +inf, the oscillatory bands -inf."""
    try:
        u = rolling_state(Fstar, yfp, scaling, parameter_set, **model)
    except rolling.NoRollingState:
        return {"any": numpy.inf, **{band: -numpy.inf for band in BANDS}, "real": numpy.inf}
    model = mlgmodel.Model(parameter_set, **values(scaling, yfp, Fstar, V=V, **model))
    model.check()
    return spectrum.growth(model, BANDS, u)


def growth_at_speeds(Fstar: float, yfp: float, speeds: Sequence[float], scaling: str = "fixed",
                     parameter_set: str = "figures", **model: Any) -> List[Dict[str, float]]:
    """[growth at each of `speeds`] from one state of straight rolling
    (it does not depend on V)."""
    try:
        u = rolling_state(Fstar, yfp, scaling, parameter_set, **model)
    except rolling.NoRollingState:
        return [{"any": numpy.inf, **{band: -numpy.inf for band in BANDS}, "real": numpy.inf}
                for _ in speeds]
    at = mlgmodel.Model(parameter_set, **values(scaling, yfp, Fstar, V=speeds[0], **model))
    jacobians = []
    for V in speeds:
        at.set(V=V)
        at.check()
        jacobians.append(at.jacobian(u))
    return spectrum.growths(numpy.array(jacobians), BANDS)


def first_crossing(Fstar: float, speeds: Sequence[float], band: str,
                   grid: Sequence[float] = KAPPA_GRID,
                   **model: Any) -> Tuple[float, Optional[float]]:
    """(y_fp, V): the least over `speeds` of the first y_fp at which `band`
    changes stability (yfp_crossings with first_only at each speed; the
    first speed of a tie), or (inf, None).  The grid is climbed once for
    all speeds, and only the speeds that change in the first grid step
    where any does are narrowed (spectrum.root to 1e-10 mm): the others'
    first changes lie beyond it."""
    rates = [g[band] for g in growth_at_speeds(Fstar, 0.0, speeds, **model)]
    unstable = [V for V, rate in zip(speeds, rates) if rate > 0]
    if unstable:   # unstable without freeplay
        return 0.0, unstable[0]
    for lo, hi in zip(numpy.r_[0.0, grid][:-1], grid):
        above = [g[band] for g in growth_at_speeds(Fstar, hi, speeds, **model)]
        changed = [k for k in range(len(speeds)) if (above[k] > 0) != (rates[k] > 0)]
        if changed:
            return min(((spectrum.root(lambda y, V=speeds[k]: growth(Fstar, y, V, **model)[band],
                                       lo, hi, rates[k], above[k], tol=1e-10), speeds[k])
                        for k in changed), key=lambda found: found[0])
        rates = above
    return numpy.inf, None


def yfp_crossings(Fstar: float, V: float, band: str, grid: Sequence[float] = KAPPA_GRID,
                  scaling: str = "fixed", first_only: bool = False, **model: Any) -> List[float]:
    """y_fp values where the growth of `band` changes sign along `grid`
    (bisection to 1e-10 mm); with first_only, only the first of them.  The
    scan starts at zero freeplay, so a band already unstable at grid[0] is
    not missed: its crossing is bisected below grid[0], or is 0 if the band
    is unstable without freeplay (side-stay geometries at light load)."""
    def rate(y):
        return growth(Fstar, y, V, scaling, **model)[band]
    found = spectrum.sign_changes(rate, numpy.r_[0.0, grid], tol=1e-10, first_only=first_only)
    if rate(0.0) > 0:
        found = [0.0] + found[:0 if first_only else None]
    return found


def extreme_yfp_crossing(Fstar: float, band: str, highest: bool = False,
                         speeds: Sequence[float] = numpy.linspace(V_MIN, V_LIMIT, 25),
                         **model: Any) -> Tuple[float, Optional[float]]:
    """(y_fp, V): the smallest (or, with highest, the largest) y_fp at which
    the mode `band` changes stability for some V in [V_MIN, V_LIMIT] -- a
    turning point in y_fp of its Hopf curve or its end at V_LIMIT; optimised
    on a V grid refined three times.  (inf or -inf, None) if it never does
    (no speed: the cache refuses NaN).  The largest is (inf, V) where the
    mode is still unstable at the scan's end YFP_MAX at some speed V: it
    lies beyond the scan, and the scan's end is no value of it.
    `model`: parameter overrides, as for growth."""
    sign = -1.0 if highest else 1.0
    best = (sign * numpy.inf, None)
    for _ in range(4):
        if not highest:
            found = first_crossing(Fstar, speeds, band, **model)
            best = found if found[0] < best[0] else best
        for V in speeds if highest else ():
            found = yfp_crossings(Fstar, V, band, **model)
            if len(found) % 2:   # unstable from its last crossing to YFP_MAX
                return numpy.inf, float(V)
            if found and found[-1] > best[0]:
                best = (found[-1], V)
        if not numpy.isfinite(best[0]):
            return best
        step = speeds[1] - speeds[0]
        speeds = numpy.linspace(max(V_MIN, best[1] - step), min(V_LIMIT, best[1] + step), 9)
    return best


def unstable_windows(Fstar: float, band: str, speeds: numpy.ndarray = numpy.linspace(V_MIN, V_LIMIT, 25),
                     **model: Any) -> List[Tuple[float, float]]:
    """[(start, end)]: the windows of y_fp in which the mode `band` is
    unstable for some V in [V_MIN, V_LIMIT], the union over the speeds of
    each speed's unstable intervals (yfp_crossings; end inf where it is
    still unstable at YFP_MAX), from the lowest.  The edges between two
    windows are refined on a V grid three times around the speed that sets
    each, as extreme_yfp_crossing refines a and b.  A gap between windows is
    a band of y_fp, beyond a and below b, in which straight rolling is
    stable again at every speed."""
    intervals = {}

    def add(Vs):
        for V in Vs:
            ends = list(yfp_crossings(Fstar, V, band, **model))
            ends += [numpy.inf] * (len(ends) % 2)
            intervals[float(V)] = list(zip(ends[::2], ends[1::2]))

    def merged():
        out = []   # [start, end, V of start, V of end]
        for lo, hi, V in sorted((lo, hi, V) for V, spans in intervals.items()
                                for lo, hi in spans):
            if out and lo <= out[-1][1]:
                if hi > out[-1][1]:
                    out[-1][1], out[-1][3] = hi, V
            else:
                out.append([lo, hi, V, V])
        return out
    add(speeds)
    step = speeds[1] - speeds[0]
    for _ in range(3):
        windows = merged()
        inner = [w[3] for w in windows[:-1]] + [w[2] for w in windows[1:]]
        add(V for edge in inner for V in numpy.linspace(max(V_MIN, edge - step),
                                                          min(V_LIMIT, edge + step), 9)
            if float(V) not in intervals)
        step /= 4
    return [(w[0], w[1]) for w in merged()]


def least_unstable(Fstar: float, **model: Any) -> Dict[str, Any]:
    """At one load: the smallest y_fp [mm] with straight rolling unstable for
    some V <= V_LIMIT ("first"), that speed ("V"), the static compression
    eta* [m] there and the band that is unstable just beyond it ("mode";
    None if none is for y_fp up to YFP_MAX): what kappa* minimises (eq. 17;
    studies.criterion, studies.design_map)."""
    y, V = extreme_yfp_crossing(Fstar, "any", **model)
    eta = rolling_state(Fstar, y if numpy.isfinite(y) else YFP_MAX, **model)["eta"]
    mode = None
    if numpy.isfinite(y):   # the band that is unstable just beyond the crossing
        beyond = growth(Fstar, y * (1 + 1e-6), V, **model)
        mode = max(BANDS, key=lambda band: beyond[band])
    return {"Fstar": float(Fstar), "first": float(y), "V": None if V is None else float(V),
            "eta": eta, "mode": mode}


def _least(points, key, floor):
    """The first point of least key (as min), stopping at one that reaches
    `floor`: no later point can lie below it, so the rest are never
    evaluated (points may be a generator)."""
    best = None
    for point in points:
        if best is None or key(point) < key(best):
            best = point
            if key(best) <= floor:
                break
    return best


def refined_minimum(evaluate: Callable[[float], Dict[str, Any]], loads: Sequence[float],
                    key: Callable[[Dict[str, Any]], float],
                    points: Optional[List[Dict[str, Any]]] = None, finer: Sequence[int] = (10,),
                    floor: float = -numpy.inf) -> Dict[str, Any]:
    """The point of least key(point) over F* in the evenly spaced `loads`,
    refined around the minimum: for each k of `finer` in turn, on 2k + 1
    loads spanning one step either side, the step then divided by k.
    evaluate(F*) returns a point (a dict with "Fstar"); `points`: the points
    of `loads` if already evaluated; `floor`: no key lies below it, so a
    point that reaches it ends the search (the same point min() would keep)."""
    best = _least(points or (evaluate(F) for F in loads), key, floor)
    step = loads[1] - loads[0]
    for k in finer:
        if key(best) <= floor:
            break
        fine = numpy.linspace(max(loads[0], best["Fstar"] - step),
                              min(loads[-1], best["Fstar"] + step), 2 * k + 1)
        best = _least([best] + [evaluate(F) for F in fine], key, floor)
        step /= k
    return best


def kappa_star(evaluate: Callable[[float], Dict[str, Any]], loads: Sequence[float],
               model: Mapping[str, Any], points: Optional[List[Dict[str, Any]]] = None,
               finer: Sequence[int] = (10,)) -> Tuple[float, Dict[str, Any]]:
    """Eq. (17)'s kappa*: the least y_fp/eps at which straight rolling is
    unstable below V_LIMIT (eps: `model`'s eps_abs, else 0.1 mm), minimised over the loads (refined_minimum of
    evaluate(F*)["first"], the least unstable y_fp there) and the loads on
    the stage switch of the gear `model` (parameter overrides,
    stage_switch_loads); (kappa*, the evaluation at the minimum).  A load
    unstable without freeplay (y_fp = 0, kappa* = 0) ends the search."""
    best = refined_minimum(evaluate, loads, lambda p: p["first"], points, finer, floor=0.0)
    for Fstar in stage_switch_loads(loads, **model) if best["first"] > 0 else ():
        point = evaluate(Fstar)
        if point["first"] < best["first"]:
            best = point
    return best["first"] / width("fixed", model)[0]["eps_abs"], best


# F* on a grid of 0.1, refined to 0.02 and then 0.005 around the minimum
# (the resolution of Fig. 18's grid refinement, with a third of its loads)
CRITERION_LOADS = ENVELOPE_LOADS[::2]
CRITERION_FINER = (5, 4)


def criterion(model: Mapping[str, Any]) -> Dict[str, Any]:
    """Eq. (17)'s kappa* of the gear `model` (parameter overrides) by the
    criterion's recipe: {kappa, Fstar, V, eta, mode} at the minimum over
    CRITERION_LOADS, refined CRITERION_FINER around it (studies.criterion,
    studies.robustness)."""
    kappa, best = kappa_star(lambda F: least_unstable(F, **model), CRITERION_LOADS, model,
                             finer=CRITERION_FINER)
    return {"kappa": kappa, "Fstar": best["Fstar"], "V": best["V"],
            "eta": best["eta"], "mode": best["mode"]}


def kappa_star_off_switch(evaluate: Callable[[float], Dict[str, Any]], loads: Sequence[float],
                          model: Mapping[str, Any], finer: Sequence[int] = (10,)
                          ) -> Tuple[float, Dict[str, Any], Optional[Tuple[float, float]]]:
    """kappa_star over the loads outside the oleo's stage-switch window
    (stage_switch_window) only: the value that does not hang on how steep
    this model's switch is.  (kappa, the evaluation at the minimum, the
    window or None); loads inside the window are not evaluated."""
    window = stage_switch_window(float(loads[0]), float(loads[-1]), **model)

    def outside(Fstar):
        if window and window[0] <= Fstar <= window[1]:
            return {"Fstar": float(Fstar), "first": numpy.inf}
        return evaluate(Fstar)
    best = refined_minimum(outside, loads, lambda p: p["first"], finer=finer, floor=0.0)
    return best["first"] / width("fixed", model)[0]["eps_abs"], best, window


def window_points(Fstar: float, **model: Any) -> Dict[str, Any]:
    """The points bounding the windows of stable straight rolling up to
    V_LIMIT at this F* (eps = 0.1 mm), as y_fp [mm]:
      a: the smallest y_fp at which the high-frequency mode is unstable for
         some V <= V_LIMIT (the end of R1; at F* = 1 where its Hopf curve
         crosses V = V_LIMIT),
      b: the largest such y_fp (the start of R2; at F* = 1 the second
         crossing of V = V_LIMIT),
      c: the smallest y_fp at which the low-frequency mode is unstable for
         some V <= V_LIMIT (the turning point in y_fp of its Hopf curve; the
         end of R2),
      p: the smallest y_fp with a real eigenvalue > 0 (pitchfork, static yaw;
         independent of V),
      first: the smallest of a, c, p, with its mode and speed.
    y_fp is scanned over KAPPA_GRID (up to YFP_MAX); inf where a mode never
    crosses there.  Also the speeds V_a, V_b, V_c of a, b, c.  `model`:
    parameter overrides, as for growth."""
    a, V_a = extreme_yfp_crossing(Fstar, "high", **model)
    b, V_b = extreme_yfp_crossing(Fstar, "high", highest=True, **model)
    c, V_c = extreme_yfp_crossing(Fstar, "low", **model)
    real = yfp_crossings(Fstar, 0.5 * V_LIMIT, "real", **model)
    p = real[0] if real else numpy.inf
    first = min((a, "high", V_a), (c, "low", V_c), (p, "real", None), key=lambda t: t[0])
    return {"Fstar": Fstar, "a": a, "b": b, "c": c, "p": p, "V_a": V_a, "V_b": V_b, "V_c": V_c,
            "first": first[0], "first_mode": first[1], "first_V": first[2]}
