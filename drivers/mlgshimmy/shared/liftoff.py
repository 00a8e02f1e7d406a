"""Wheel lift-off by time simulation: where the shimmy the model settles
into grows until a tyre load turns negative (the model's domain ends).

Beyond the torus curve the attractor is quasi-periodic, so no AUTO orbit
tells where lift-off starts (the minimum tyre load over the unstable
periodic orbit is not that of the torus); the edge is found by simulation.
A run starts next to straight rolling (psi + 1e-4 rad, the atlas's
"rolling" start, which is unstable there and grows onto the shimmy by
itself; a large kick lifts a wheel off as a transient at light loads where
the small starts settle) and counts as a lift-off if the simulator stops on
a negative tyre load within T_END.

    lifts_off(csv, 580.0, 0.3)                        # True / False
    edge_speed(csv, 0.3, 450.0, 600.0)                # lowest V, or None
"""
from __future__ import annotations

import os
from typing import Any, Callable, Mapping, Optional

from mlgshimmy.shared import freeplay
from mlgshimmy.shared import simulator
from mlgshimmy.shared import spectrum

T_END = 120.0             # s: a run that lifts no wheel off within it does not count
PSI0 = simulator.STARTS["rolling"]
LIFT_OFF = "a wheel lifts off"    # c/parameters.c mlg_status_text
TOL_V = 2.0               # m/s: the edge speed's bisection interval
TOL_F = 0.005             # the edge's ends in F* (on V = V_MAX)
LOWER_BY, LOWEST_V = 100.0, 100.0   # m/s: edge_speed's bracket moves down this way
# Where each cut of the bisection lies, as a fraction of the bracket from its
# end without lift-off: a run that lifts a wheel off stops there (0.1-0.4 s
# of CPU near the edge), one that does not runs the whole T_END (5-7 s), so
# cuts towards the lift-off end are cheap more often.  For an edge anywhere
# in the bracket, 0.75 makes 2.0-2.2 runs without lift-off in 100 m/s to
# TOL_V where halving makes 3.0-3.2 (and 7.6 runs in all against 6.0).
LIFT_SIDE_SPLIT = 0.75


def lifts_off(csv: str, V: float, Fstar: float, case: Mapping[str, float] = freeplay.NOMINAL,
              t_end: float = T_END, params: Optional[Mapping[str, float]] = None,
              rolling: Optional[Callable[[float], Mapping[str, float]]] = None) -> bool:
    """Whether the run from straight rolling (psi + PSI0) at (V, F*) stops
    on a negative tyre load within t_end; a stop for another reason raises
    SimulationError naming it.  params: more model parameters for the
    simulator ({name: value}, e.g. gear.simulator_params()); rolling:
    rolling(F*) is straight rolling's state (default: the simulator's own
    Newton solve, which can miss it at side-stay angles)."""
    if not (V > 0 and Fstar > 0 and t_end > 0):
        raise ValueError(f"liftoff: V = {V}, Fstar = {Fstar} and t_end = {t_end} must be > 0")
    proc = simulator.run(csv, "--set", "figures", "--V", V, "--Fstar", Fstar,
                         *simulator.freeplay_args(case), "--t-end", t_end, "--dt-out", 1.0,
                         "--psi0", PSI0,
                         *simulator.state_args(rolling(Fstar) if rolling else None),
                         params=params)
    if os.path.exists(csv):
        os.remove(csv)
    if proc.returncode == 0:
        return False
    reason = simulator.left_domain(proc)
    if reason is None or LIFT_OFF not in reason:
        raise simulator.SimulationError(
            f"liftoff: at V = {V:g}, F* = {Fstar:g} the simulator stopped otherwise: "
            f"{proc.stderr.strip()}")
    return True


class HoldsAtLow(ValueError):
    """The bisection's test holds at its low end already."""


def bisected(test: Callable[[float], bool], lo: float, hi: float, tol: float, what: str,
             checked: bool = False) -> Optional[float]:
    """The value between lo and hi (either order) nearest lo where test()
    starts to hold, bisected to tol (test must fail at lo and hold at hi),
    or None if it fails at hi.  lo is run only when the value comes out
    within tol of it: were test to hold there, every step would have moved
    towards lo (one full run saved per edge point; a test that holds at lo
    and fails above it is not seen: the bisection finds one crossing).
    checked: the caller has run test at both ends already, with that
    outcome (they are not run again)."""
    if not checked and not test(hi):
        return None
    sign = 1.0 if hi >= lo else -1.0   # spectrum.bisect wants lo < hi
    found = sign * spectrum.bisect(lambda x: not test(sign * x), sign * lo, sign * hi, tol=tol,
                                   split=LIFT_SIDE_SPLIT)
    if not checked and abs(found - lo) <= tol and test(lo):
        raise HoldsAtLow(f"liftoff: a wheel lifts off already at {what} = {lo:g} "
                         "(move the bracket)")
    return found


def edge_speed(csv: str, Fstar: float, lo: float, hi: float, tol: float = TOL_V,
               **options: Any) -> Optional[float]:
    """The lowest speed in [lo, hi] at which a wheel lifts off (within
    T_END) at load F*, or None if none does up to hi (one crossing: lift-off
    within a fixed time need not be monotone in V).  Where a wheel lifts
    off at lo already (a side-stay geometry can move the edge), the bracket
    moves down by LOWER_BY, to lo no lower than LOWEST_V."""
    test = lambda V: lifts_off(csv, V, Fstar, **options)
    try:
        return bisected(test, lo, hi, tol, "V")
    except HoldsAtLow:
        while lo - LOWER_BY >= LOWEST_V:
            lo, hi = lo - LOWER_BY, lo
            if not test(lo):
                return bisected(test, lo, hi, tol, "V", checked=True)
        raise


def edge_load(csv: str, V: float, lo: float, hi: float, tol: float = TOL_F, checked: bool = False,
              **options: Any) -> Optional[float]:
    """The load between lo (no lift-off) and hi (lift-off) where lift-off
    starts at speed V, or None if none at hi (checked: as for bisected)."""
    return bisected(lambda f: lifts_off(csv, V, f, **options), lo, hi, tol, "F*", checked)
