"""The oleo's stage switch seen from the loads: where straight rolling's
static compression eta* crosses it, the loads across it that the kappa*
minimum must also evaluate (its stiffness is steepest there), and how near
an orbit's extremes of compression come to it."""
from __future__ import annotations

from typing import Any, List, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import mlgmodel, spectrum
from mlgshimmy.shared.rolling_state import rolling_state

SWITCH_WIDTHS = 3.0    # the stage switch: eta* within this many 1/k_stage of eta_stage
SWITCH_LOADS = 5       # loads evaluated across it


def zero_freeplay_eta(Fstar: float, parameter_set: str = "figures", **model: Any) -> float:
    """eta* [m] of straight rolling without freeplay at this load."""
    return rolling_state(Fstar, 0.0, parameter_set=parameter_set, **model)["eta"]


def stage_switch_window(lo: float, hi: float, widths: float = SWITCH_WIDTHS,
                        parameter_set: str = "figures",
                        **model: Any) -> Optional[Tuple[float, float]]:
    """(F*_enter, F*_leave): the loads within [lo, hi] where straight
    rolling's eta* enters and leaves the oleo's stage switch, |eta* - eta_s|
    up to `widths` / k_stage (c/strut.h: the switch's stiffness falls as
    1 / (1 + x^2) in x = k_stage (eta - eta_s)); None if eta* does not
    cross it there.  `model`: parameter overrides."""
    constants = mlgmodel.Model(parameter_set, **model)
    eta_s, width = constants["eta_stage"], widths / constants["k_stage"]

    def eta(Fstar):
        return zero_freeplay_eta(Fstar, parameter_set, **model)
    edges = []
    for target in (eta_s - width, eta_s + width):
        below = eta(lo) < target
        if below == (eta(hi) < target):
            return None
        edges.append(spectrum.bisect(lambda F, b=below: (eta(F) < target) == b, lo, hi,
                                     tol=1e-6))
    return min(edges), max(edges)


def stage_switch_loads(loads: Sequence[float], parameter_set: str = "figures",
                       **model: Any) -> List[float]:
    """SWITCH_LOADS loads, evenly across the oleo's stage switch
    (stage_switch_window) within [loads[0], loads[-1]]; [] if eta* does not
    cross it there.  On the switch the spring's local
    stiffness is steepest (k_stage = 1e5 /m), over a window of F* narrower
    than an envelope grid's step (F* 0.64-0.68 at rho = mu = 10 deg, where
    a 19-33 Hz strut-torsion mode is unstable without freeplay), so
    kappa_star evaluates these loads as well."""
    window = stage_switch_window(float(loads[0]), float(loads[-1]), SWITCH_WIDTHS,
                                 parameter_set, **model)
    if window is None:
        return []
    loads = [float(F) for F in numpy.linspace(*window, SWITCH_LOADS)]
    try:
        etas = [zero_freeplay_eta(F, parameter_set, **model) for F in loads]
    except RuntimeError:
        etas = []
    if len(etas) < len(loads) or numpy.any(numpy.diff(etas) <= 0):
        # straight rolling folds on the switch (the printed strut): loading
        # up jumps across it, and Newton lands on either side or fails there
        return []
    return loads


def extremes_from_switch(solution: Any, parameter_set: str = "figures", **model: Any) -> float:
    """How near an orbit (an AUTO solution: its first states those of the
    model, in mlgmodel.UNAMES order) comes to the oleo's stage switch at its
    largest or smallest strut compression: the lesser |k_stage (eta - eta_s)|
    of the two, in switch widths 1 / k_stage.  Where an extreme lies within
    a few widths, the spring's stiffness changes by orders of magnitude over
    the part of the cycle near it, and a small change of the parameters
    moves the orbit into or out of the switch (a grazing)."""
    constants = mlgmodel.Model(parameter_set, **model)
    eta = numpy.asarray(solution.coordarray[mlgmodel.UNAMES.index("eta")], dtype=float)
    return float(min(abs(constants["k_stage"] * (x - constants["eta_stage"]))
                     for x in (eta.max(), eta.min())))
