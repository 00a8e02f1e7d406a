"""Where Fig. 11's drawn curves end inside the plane (AUTO's MX stops):
two curves of one kind meeting at one point (mx_ends), an end inside the
oleo's stage switch, an orbit curve's end where its orbit reaches the
switch, a fold curve's end at a generalised Hopf point, a torus curve's
end on a fold curve, an end at the lift-off edge (explained), and the
others, drawn as MX crosses."""
from __future__ import annotations

from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

from mlgshimmy.figures.fig11.plane import (F_MAX, F_MIN, FREEPLAY, GEOMETRY, MODEL, V_MAX,
                                           V_MIN, on_curves)
from mlgshimmy.shared import branches
from mlgshimmy.shared import jobs
from mlgshimmy.shared import kappa_criterion
from mlgshimmy.shared import stage_switch

# MX ends of two curves of one kind closer than this (in V/V_MAX and
# F*/F_MAX) are one point where they meet: the Hopf curves from H1 and H2
# reach their common turning point inside the oleo stage switch from both
# sides (3e-4 m/s apart); a tongue's two edges stop short of where they
# meet (2.5 m/s apart at F* = 0.863)
JOIN_TOL = {"hopf": 1e-3, "tongue": 5e-3}
JOIN_LABELS = {"hopf": "two Hopf curves meet inside the oleo's stage switch (at the "
                       "paper's gear those from H1 and H2)",
               "hopf_elsewhere": "one Hopf curve turns in F* here, outside the stage "
                                 "switch; AUTO's continuation cannot pass such a turn, so it "
                                 "is drawn as two curves meeting",
               "tongue": "the two edges of a tongue meet: its tip"}


def in_plane(point: Mapping[str, float]) -> bool:
    """Whether (V, F*) lies inside the plane's edges: a curve started on the
    edge F* = F_MIN (a Hopf or torus point of the edge's slice) that steps
    out of it crosses no stop there and ends beyond it."""
    return V_MIN <= point["V"] <= V_MAX and F_MIN <= point["Fstar"] <= F_MAX


def mx_ends(drawn: Mapping[str, Any]) -> Tuple[List[Dict[str, Any]], List[Dict[str, Any]]]:
    """(joins, open): the MX ends of the drawn curves inside the plane
    (in_plane), those where two curves of one kind meet (JOIN_TOL) as
    [{"V", "Fstar", "kind", "curves"}], and the others [{"V", "Fstar",
    "curve"}]."""
    ends = [{"V": branch["V"][i], "Fstar": branch["Fstar"][i], "kind": kind,
             "curve": f"{kind}{n + 1}",
             **({"switch": branch.at_mx[i]} if i in getattr(branch, "at_mx", {}) else {})}
            for kind in ("hopf", "fold", "torus", "tongue")
            for n, diagram in enumerate(drawn.get(kind, []))
            for branch in jobs.loaded(diagram)
            for i, _, _ in branches.labelled_points(branch, "MX")
            if in_plane({"V": branch["V"][i], "Fstar": branch["Fstar"][i]})]
    joins, used = [], set()
    for a, p in enumerate(ends):
        for b in range(a + 1, len(ends)):
            q = ends[b]
            if a not in used and b not in used and p["kind"] == q["kind"] in JOIN_TOL \
                    and numpy.hypot((p["V"] - q["V"]) / V_MAX,
                                    (p["Fstar"] - q["Fstar"]) / F_MAX) < JOIN_TOL[p["kind"]]:
                used |= {a, b}
                joins.append({"V": 0.5 * (p["V"] + q["V"]), "Fstar": 0.5 * (p["Fstar"] + q["Fstar"]),
                              "kind": p["kind"], "curves": [p["curve"], q["curve"]]})
    return joins, [{k: e[k] for k in ("V", "Fstar", "curve", "switch") if k in e}
                   for n, e in enumerate(ends) if n not in used]


# The stage switch as Fig. 11 marks it: eta* of straight rolling within
# this many 1/k_stage of eta_s, where the switch's stiffness is above 1 %
# of its peak (stage_switch.stage_switch_window; F* 0.627-0.700 at the three
# geometries run).  AUTO's step falls below DSMIN there: the H3 Hopf curve
# stops at F* = 0.6949 (rho = mu = 10 deg, |eta* - eta_s| = 3.0 / k_stage)
SWITCH_WIDTHS = 10.0


def orbit_at_switch(solution: Any) -> float:
    """How near the orbit `solution` of the plane's model comes to the
    stage switch with an extreme of its compression, in switch widths
    (stage_switch.extremes_from_switch): stored with each MX end of an
    orbit curve (jobs.stored's at_mx).  Within SWITCH_WIDTHS the orbit
    grazes the switch there (rho = -20, mu = -10 deg: a tongue edge stops
    at (462.86 m/s, F* = 0.9423) with its largest compression 0.6 widths
    into the switch; along V from there the orbit leaves the switch within
    0.17 m/s and its critical Floquet pair falls from |mu| = 1.000 to 0.944
    within 0.12 m/s)."""
    return stage_switch.extremes_from_switch(solution, **MODEL)
# An MX end this close (in V/V_MAX, F*/F_MAX) to the lift-off edge is the
# curve reaching it: at rho = mu = 10 deg the torus curve stops 5 m/s short
# of the edge, its orbit's least tyre load 2.5 kN (beyond the edge the
# wheel lifts off); a torus curve's end is joined to the edge, closing the
# quasi-periodic region against the high-frequency one beside it
CLOSE_TOL = 0.02
# A fold curve's MX end where straight rolling has a complex pair with a
# real part below this [1/s] lies on the Hopf locus: the fold's orbits
# shrink onto straight rolling there and AUTO cannot go on (rho = mu = 10
# deg, F* = 0.0263 and 1.444: psi amplitude 1e-6 at the ends, the pair's
# real part -0.017 and +0.017 /s 0.5 m/s either side).  While the curve is
# continued this ends it (curves.FOLD_ENDS); the figure names such an end a
# generalised Hopf point only where one is located (located.at_gh)
GH_RATE = 1e-3
# A torus curve's MX end this close (in V/V_MAX, F*/F_MAX) to a fold curve
# lies on it: where the orbits' complex Floquet pair meets the fold's
# multiplier +1 (at the plane's lower edge both geometries run: 0.0005 and
# 0.00004 from the fold curve, the pair's angle 0.19 and 0.008 rad there)
FOLD_TOL = 0.002
# the point this many steps back from a curve's end tells the side it came from
BACK = 3


def on_hopf_locus(stop: Mapping[str, float]) -> bool:
    """Whether straight rolling at the end's (V, F*) has a complex pair of
    eigenvalues within GH_RATE of the imaginary axis."""
    rates = kappa_criterion.growth(stop["Fstar"], FREEPLAY["yfp"], stop["V"], scaling="ratio",
                             **GEOMETRY)
    return min(abs(rates["low"]), abs(rates["high"])) < GH_RATE


# A Hopf curve of straight rolling that turns in F* (F* extremal along it)
# runs along V alone there.  Straight rolling does not depend on V, so only
# the eigenvalue problem moves, and AUTO's Hopf continuation, with V out of
# its arclength (constants/runs/c.hopf_curve), cannot step on: it stops (MX).
# The curve goes on past the turn: a slice this far back inside the turn
# crosses it twice, within TURN_WINDOW of the end (rho = 5, mu = -15 deg: a
# turn at F* = 2.8452, V = 11.96 m/s, crossed at 11.96 +- 3.1 m/s), and the
# crossing on no curve so far (closer than TURN_TOL in V/V_MAX, F*/F_MAX:
# the curves' steps shrink to millimetres per second at the turn) starts
# the curve past it (curves.slice_hopf).
TURN_DF = 1e-3
TURN_WINDOW = 30.0   # m/s
TURN_TOL = 1e-3


def turns(curves: Sequence[Sequence[Any]],
          switch: Optional[Tuple[float, float]]) -> List[Tuple[float, float]]:
    """[(F*, V)]: a load TURN_DF back inside each MX end of the Hopf curves
    `curves` (lists of branches) that lies in the plane and outside the
    stage-switch window `switch` (the side the curve came from: its point
    BACK steps before the end), and the end's V."""
    out = []
    for end, branch, i in _mx_ends(curves, switch):
        if i >= BACK:
            side = numpy.sign(branch["Fstar"][i - BACK] - end["Fstar"])
            load = end["Fstar"] + side * TURN_DF
            if side and F_MIN <= load <= F_MAX:
                out.append((load, end["V"]))
    return out


def on_locus(folds: Sequence[Sequence[Any]],
             switch: Optional[Tuple[float, float]]) -> List[Tuple[float, float]]:
    """[(F*, V)] of the MX ends of the fold curves `folds` (lists of
    branches) in the plane, outside the stage-switch window `switch`, on
    the Hopf locus (on_hopf_locus): a fold curve of orbits ends at a GH
    point of a Hopf curve, which a slice at that load finds where no slice
    of the grid did (rho = 20, mu = 5 deg: a Hopf curve of 17.7 Hz within
    F* 1.3315-1.3475 and V < 0.812 m/s)."""
    return [(end["Fstar"], end["V"]) for end, _, _ in _mx_ends(folds, switch)
            if on_hopf_locus(end)]


def _mx_ends(curves, switch):
    """(end {"V", "Fstar"}, branch, index) of each MX end of the curves in
    the plane and outside the stage-switch window."""
    for curve in curves:
        for branch in curve:
            for i, _, _ in branches.labelled_points(branch, "MX"):
                end = {"V": float(branch["V"][i]), "Fstar": float(branch["Fstar"][i])}
                if in_plane(end) and not inside(switch, end["Fstar"]):
                    yield end, branch, i


def inside(switch: Optional[Tuple[float, float]], Fstar: float) -> bool:
    """Whether F* lies in the stage-switch window (F*_enter, F*_leave), or None."""
    return bool(switch) and switch[0] <= Fstar <= switch[1]


def joins_outside(joins: Sequence[Mapping[str, Any]],
                  switch: Optional[Tuple[float, float]]) -> List[Mapping[str, Any]]:
    """The joins (mx_ends) with Hopf joins outside the stage-switch window
    `switch` (or None) of kind "hopf_elsewhere": at side-stay angles Hopf
    curves from the slices also meet in pairs at loads away from it
    (rho = -10, mu = 20 deg: F* = 0.267 and 0.876)."""
    return [{**j, "kind": "hopf_elsewhere"}
            if j["kind"] == "hopf" and not inside(switch, j["Fstar"]) else j for j in joins]


def nearest_point(stop: Mapping[str, float], points: Mapping[str, Any]) -> Tuple[float, int]:
    """(distance in V/V_MAX, F*/F_MAX, index) of the point of `points`
    ({"V": [...], "Fstar": [...]}: the lift-off edge, a curve's columns)
    nearest `stop`."""
    V, F = numpy.asarray(points["V"]), numpy.asarray(points["Fstar"])
    d = numpy.hypot((V - stop["V"]) / V_MAX, (F - stop["Fstar"]) / F_MAX)
    k = int(numpy.argmin(d))
    return float(d[k]), k


def explained(stops: Sequence[Mapping[str, Any]], switch: Optional[Tuple[float, float]],
              lift: Optional[Mapping[str, Any]], folds: Sequence[Any] = (),
              at_gh: Optional[Callable[[Mapping[str, Any]], bool]] = None
              ) -> Dict[str, List[Dict[str, Any]]]:
    """The MX ends that are no two curves' meeting (mx_ends' open list)
    sorted: {"stage_switch": those with F* inside the window `switch`
    ((F*_enter, F*_leave) or None), "generalised_hopf": ends of fold curves
    where the predicate `at_gh` holds (on_hopf_locus while a curve is
    continued; within FOLD_TOL of a located GH point in the figure,
    located.at_gh; None: no fold end is),
    "on_fold": ends of torus curves within FOLD_TOL of a fold curve
    (`folds`: lists of branches), "liftoff": those within CLOSE_TOL of the
    lift-off edge `lift` (liftoff_edge, or None), "orbit_switch": of the
    others, those whose orbit has an extreme of compression within
    SWITCH_WIDTHS of the switch (the end's "switch", orbit_at_switch: a
    cause less particular than those above), "open": the rest}."""
    out = {"stage_switch": [], "orbit_switch": [], "generalised_hopf": [], "on_fold": [],
           "liftoff": [], "open": []}
    for stop in stops:
        if inside(switch, stop["Fstar"]):
            out["stage_switch"].append(stop)
        elif stop["curve"].startswith("fold") and at_gh and at_gh(stop):
            out["generalised_hopf"].append(stop)
        elif stop["curve"].startswith(("torus", "tongue")) and on_curves(stop, folds, FOLD_TOL):
            out["on_fold"].append(stop)
        elif lift and nearest_point(stop, lift)[0] < CLOSE_TOL:
            out["liftoff"].append(stop)
        elif stop.get("switch", numpy.inf) <= SWITCH_WIDTHS:
            out["orbit_switch"].append(stop)
        else:
            out["open"].append(stop)
    return out


def closing_segments(ends: Mapping[str, Sequence[Mapping[str, Any]]],
                     lift: Optional[Mapping[str, Any]]) -> List[Dict[str, Any]]:
    """Straight edges from each torus curve's end at the lift-off edge
    (explained's "liftoff") to the edge's nearest point, as curve_list
    entries."""
    out = []
    for stop in ends:
        if stop["curve"].startswith("torus"):
            _, k = nearest_point(stop, lift)
            out.append({"name": f"{stop['curve']}-liftoff", "kind": "torus",
                        "V": [stop["V"], float(lift["V"][k])],
                        "Fstar": [stop["Fstar"], float(lift["Fstar"][k])]})
    return out
