"""Fig. 11's torus curve (the edge of the quasi-periodic region) and the
edges of the tongues of instability left of it, continued by AUTO from
torus points of the large family (shared.torus)."""
from __future__ import annotations

import os
from typing import Any, Collection, Dict, List, Mapping, Sequence, Tuple

import numpy

from mlgshimmy.figures.fig11 import ends
from mlgshimmy.figures.fig11.curves import stage_switch
from mlgshimmy.figures.fig11.orbits import large_upwards, slice_rundir
from mlgshimmy.figures.fig11.plane import MODEL, SLICES, V_MAX, V_MIN, on_curves
from mlgshimmy.shared import runerror
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import jobs
from mlgshimmy.shared import paths
from mlgshimmy.shared import stationary
from mlgshimmy.shared import torus

# the torus curve bounding the quasi-periodic region, continued from its
# point on this load; the loads whose other torus points (narrow tongues of
# instability below the curve, F* ~ 0.65-1.1) are marked; the tongue edges
# continued, {part: (load, index of the crossing on it, torus_curve's
# options)}: the two ends of the window at F* = 0.8125 (471.1, 483.3 m/s)
# and at 0.9375 (540.24, 542.28 m/s).  The first edge needs 300 steps down
# to where it meets the second (docs/reproduction.md).  The pair at 540.24
# (theta = 0.17) is ill-conditioned (eigenvalue condition number ~550,
# against ~140 at 542.28): the seeded first Newton solve fails on the
# orbit's mesh (NTST 80) and converges on a finer one.
TORUS_START = 0.5625
TORUS_POINT_LOADS = (0.6875, 0.8125, 0.9375)
TONGUE_EDGES = {"tongue": (0.8125, 0, {"steps": 300}), "tongue2": (0.8125, 1, {}),
                "tongue3": (0.9375, 0, {"ntst": 120}), "tongue4": (0.9375, 1, {})}
TORUS_COLUMNS = ("V", "Fstar", "freq", "PAR(12)")
# The starts above were chosen at the paper's gear and stay there, so that
# its reference set stays bit for bit; with side-stay angles the driver
# finds its starts on the slices (found_curves), at most MAX_CURVES curves.
PINNED = stationary.symmetric(MODEL)
MAX_CURVES = 10   # a cost guard: 8 before the edge slice (plane.EDGE_SLICE) took 2
# A tongue edge started inside the oleo's stage switch (ends.inside) is
# followed this many steps each way, not torus.CURVE_STEPS: there its course
# is set by the switch's steepness k_stage, and AUTO's steps stay near their
# first size (0.05) however far it goes, so 150 steps move it a few m/s.
SWITCH_CURVE_STEPS = 30


def tongue_parts() -> Dict[str, Any]:
    """The tongue-edge parts (TONGUE_EDGES at the paper's gear; none with
    side-stay angles, where the torus part finds them)."""
    return TONGUE_EDGES if PINNED else {}
TONGUE_TOL = 0.002     # on_curves distance of a point on the tongue edge (~1 m/s in V)


def placed_tr(rundir: str, found: Tuple[Any, Sequence[Any]], index: int = 0,
              tr_name: str = "tr") -> Any:
    """AUTO's TR label at a torus point of an orbit diagram in V (found:
    (diagram, crossings); the first, or crossings[index]): torus.tr_point as
    run tr_name."""
    orbits, torus_points = found
    return torus.tr_point(rundir, tr_name, orbits, torus_points[index]["value"],
                          torus_points[index]["slope_per_unit"],
                          torus_points[index].get("between"))


def first_torus_curve(rundir: str, name: str, found: Tuple[Any, Sequence[Any]], index: int = 0,
                      tr_name: str = "tr", **options: Any) -> Any:
    """A torus point of an orbit diagram in V (placed_tr) continued both
    ways by AUTO (torus.torus_curve with its options: steps, ntst)."""
    return torus.torus_curve(rundir, name, placed_tr(rundir, found, index, tr_name), **options)


def stored_curve(curve: Sequence[Any]) -> List[Any]:
    """A torus curve's runs as stored branches of TORUS_COLUMNS, each MX end
    with how near its orbit comes to the stage switch (ends.orbit_at_switch)."""
    return [branch for run in curve
            for branch in jobs.stored(run, TORUS_COLUMNS, ends.orbit_at_switch)]


def crossing_kinds(crossings: Sequence[Any]) -> List[str]:
    """"tongue" for each crossing that opens or closes a window (a loss of
    stability regained further up, torus.windows), "torus" for a loss never
    regained (the edge of the quasi-periodic region)."""
    paired = {id(c) for pair in torus.windows(crossings) for c in pair}
    return ["tongue" if id(c) in paired else "torus" for c in crossings]


def diagrams_on(Fstar: float, large_loads: Collection[float]) -> List[Tuple[Any, List[Any]]]:
    """[(diagram, torus crossings)] on a slice load: the large part's
    diagram in V upwards (if the family reaches the load; one that stops
    short of V_MAX gives the crossings below its end) and the slice's own
    orbit runs (slice_diagram: the orbits born at its Hopf points)."""
    out = [large_upwards(Fstar, complete=False)] if Fstar in large_loads else []
    rundir = slice_rundir(Fstar)
    for name in sorted(f[2:] for f in os.listdir(rundir) if f.startswith("d.po")):
        out.append((ct.load(rundir, name), torus.torus_crossings(rundir, name)))
    return out


def found_curves(large_loads: Collection[float]) -> Dict[str, Any]:
    """With side-stay angles: the torus curves from the crossings on every
    slice's diagrams in V (diagrams_on; large_loads: the loads the large
    part reached).  From the lightest load up, each crossing that no curve
    so far passes through (on_curves, TONGUE_TOL) starts one, a "torus" or
    "tongue" curve by its kind (crossing_kinds), up to MAX_CURVES (a
    tongue edge inside the stage switch SWITCH_CURVE_STEPS each way); a start
    that fails is reported.  The crossings on no curve are returned as
    points."""
    rundir = paths.rundir("fig11/torus")
    out = {"torus": [], "tongue": []}
    points, k = [], 0

    def drawn():
        return [run for curves in out.values() for curve in curves for run in curve]
    for Fstar in SLICES:
        for found in diagrams_on(Fstar, large_loads):
            for index, (c, kind) in enumerate(zip(found[1], crossing_kinds(found[1]))):
                point = {"V": c["value"], "Fstar": Fstar, "angle": c["angle"],
                         "direction": c["direction"]}
                if not V_MIN <= c["value"] <= V_MAX:
                    continue   # interpolated across a step that left the plane
                if on_curves(point, drawn(), TONGUE_TOL):
                    continue
                if k < MAX_CURVES:
                    k += 1
                    steps = (SWITCH_CURVE_STEPS if kind == "tongue"
                             and ends.inside(stage_switch(), Fstar) else torus.CURVE_STEPS)
                    try:
                        tr = placed_tr(rundir, found, index, f"tr{k}")
                        if on_curves({"V": tr["V"], "Fstar": Fstar}, drawn(), TONGUE_TOL):
                            # AUTO's TR lies on a curve already continued (two
                            # crossings of one step, placed at one label)
                            print(f"fig11: {kind} start tr{k} at V = {tr['V']:.4g}, F* = "
                                  f"{Fstar:g} lies on a curve found already", flush=True)
                            continue
                        out[kind].append(torus.torus_curve(rundir, f"{kind}{k}", tr,
                                                           steps=steps))
                        continue
                    except (runerror.RunError, ValueError) as exc:
                        print(f"REPORTED: fig11 {kind} curve from V = {c['value']:.4g}, "
                              f"F* = {Fstar:g} left out: {getattr(exc, 'brief', exc)}",
                              flush=True)
                points.append(point)
    print(f"fig11: {len(out['torus'])} torus and {len(out['tongue'])} tongue curves found; "
          f"{len(points)} torus points on none", flush=True)
    stored = {kind: [stored_curve(curve) for curve in curves] for kind, curves in out.items()}
    return {"curves": stored["torus"], "tongue": stored["tongue"], "points": points}


def torus_curves(large: Mapping[str, Any]) -> Dict[str, Any]:
    """A part, after the large part (`large`: its result): the torus
    (Neimark-Sacker) curve of the
    large-amplitude family in (V, F*) and the torus points off it:
    {"curves": [[stored branches]], "points": [{"V", "Fstar", "angle",
    "direction"}]}: the curve from the first torus point on TORUS_START,
    the points of the TORUS_POINT_LOADS that it does not pass through (the
    large part's diagrams in V, large_upwards); with side-stay angles the
    curves found_curves finds (their tongue edges too, "tongue")."""
    if not PINNED:
        return found_curves({float(f) for f in large})
    found = {Fstar: large_upwards(Fstar) for Fstar in (TORUS_START,) + TORUS_POINT_LOADS}
    curve = first_torus_curve(paths.rundir("fig11/torus"), "torus", found[TORUS_START])
    points = [{"V": c["value"], "Fstar": Fstar, "angle": c["angle"],
               "direction": c["direction"]}
              for Fstar in TORUS_POINT_LOADS for c in found[Fstar][1]
              if not on_curves({"V": c["value"], "Fstar": Fstar}, curve)]
    return {"curves": [stored_curve(curve)], "points": points}


def tongue_curve(part: str) -> Dict[str, Any]:
    """A part, after the large part: the torus curve of another Floquet
    pair, an edge of a tongue of instability left of the torus curve,
    continued from the torus point TONGUE_EDGES[part] of the large part's
    diagram in V on that load (large_upwards, first_torus_curve):
    {"curves": [[stored branches]]}."""
    Fstar, index, options = TONGUE_EDGES[part]
    curve = first_torus_curve(paths.rundir(f"fig11/{part}"), "tongue", large_upwards(Fstar),
                              index, **options)
    return {"curves": [stored_curve(curve)]}


BEYOND = 1.1 * V_MAX   # a slice that no torus curve crosses below V_MAX


def torus_speed(edge_curves: Sequence[Mapping[str, Any]], Fstar: float) -> float:
    """The lowest speed at which a torus curve crosses the load Fstar (where
    the last stable large-amplitude orbit is lost, at the lightest loads),
    BEYOND if none does."""
    speeds = [BEYOND]
    for curve in edge_curves:
        if curve["kind"] != "torus":
            continue
        V, F = numpy.asarray(curve["V"]), numpy.asarray(curve["Fstar"])
        for k in numpy.flatnonzero((F[:-1] - Fstar) * (F[1:] - Fstar) <= 0):
            if F[k + 1] != F[k]:
                speeds.append(V[k] + (Fstar - F[k]) / (F[k + 1] - F[k]) * (V[k + 1] - V[k]))
    return min(speeds)
