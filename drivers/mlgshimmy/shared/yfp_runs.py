"""AUTO recipes of the freeplay-magnitude figures (Figs. 13-19, sections
IV.D-IV.E): one-parameter diagrams in V at a given y_fp, the orbits at fixed
V continued in y_fp, and the curves of Hopf points and folds of cycles in
(y_fp, V).  Their cached forms: yfp_stored; the allowed freeplay kappa*:
kappa_criterion.

    d = diagram_in_V(rundir, "y1", "ratio", 1.0)     # Hopf points + orbits
    for point in stable_orbits(d, 50.0): ...         # UZ labels at V = 50
    curves = hopf_curves(rundir, "fixed")            # in (y_fp, V)

Scalings (section III): shared.freeplay.  Everything is at
F* = 1 unless Fstar is passed.  `**model` (where a function takes it)
overrides parameters or constants of every model it builds by name, e.g.
strut_variant=1, or a side-stay geometry (shared.gear.parameters()).
"""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Sequence, Tuple

import numpy
from numpy.typing import ArrayLike

from mlgshimmy.shared import branches
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import runerror
from mlgshimmy.shared import spectrum
from mlgshimmy.shared.freeplay import SCALINGS

FSTAR = 1.0
V_MIN, V_MAX = 0.5, 200.0    # V = 0 is degenerate (tyre states undetermined)
V_LIMIT = 120.0              # the speed limit of section IV.E
V_ORBITS = (15.0, 50.0, 80.0, 110.0)
V_SCAN = numpy.linspace(V_MIN, V_MAX, 161)
YFP_MIN, YFP_MAX = 0.005, 2.0
FOLD_YFP_MAX = 1.0   # fold-of-cycles curves (~0.5 s a point) end here
HOPF_GAP = 0.01      # periodic branches stop this far (m/s) before another Hopf point
# Arclength weights of the oscillating states (psi, delta and their rates):
# the orbits are 1e-4..1e-2 rad wide beside a static eta ~ 0.4 m, and without
# weights a step across a sharp fold of cycles overshoots onto a constant
# solution (seen at y_fp = 0.15 mm, eps = 0.1 mm, V ~ 40 m/s).
THU = {1: 1e4, 2: 1e4, 5: 1e4, 6: 1e4}
DSMAX_V = 0.5      # periodic branches in V: larger steps jump past the other Hopf point


def values(scaling: str, yfp: float, Fstar: float = FSTAR, **more: float) -> Dict[str, float]:
    """The freeplay case's parameters; `more` overrides, the scaling's eps_abs
    or eps_rel among them (criterion at another smoothing width)."""
    return {"Fstar": Fstar, "yfp": yfp, **SCALINGS[scaling], **more}


def progress(figure: str, text: str) -> None:
    print(f"{figure}: {text}", flush=True)


def diagram_in_V(rundir: str, tag: str, scaling: str, yfp: float, Fstar: float = FSTAR,
                 uzr: Sequence[float] = V_ORBITS, figure: str = "magnitude", **model: Any) -> Any:
    """continuation.speed_diagram over V_SCAN at this y_fp (runs
    <tag>_hb<i>, <tag>_po<i>, i from 0), with UZ labels at the speeds `uzr`
    and the weighted small first steps the orbits here need."""
    return ct.speed_diagram(rundir, "figures", values(scaling, yfp, Fstar, **model), V_SCAN,
                            tag=f"{tag}_", first=0, gap=HOPF_GAP, figure=f"{figure}: {tag}",
                            about={"scaling": scaling, "yfp": yfp},
                            UZR={"V": list(uzr)} if uzr else {}, DS=1e-4, DSMAX=DSMAX_V,
                            DSMIN=1e-9, NMX=2000, THU=THU)


def stable_orbits(diagram: Any, V: float) -> List[Tuple[Any, int]]:
    """[(run, label)] of the stable orbits carrying a UZ label at speed V."""
    found = []
    for run in diagram.branches:
        for branch in run:
            stable = branches.stable_mask(branch)
            for index, lab, _ in branches.labelled_points(branch, "UZ"):
                if abs(branch["V"][index] - V) < 1e-3 and stable[index]:
                    found.append((run, lab))
    return found


def yfp_thresholds(scaling: str, V: float, Fstar: float = FSTAR,
                   **model: Any) -> List[Tuple[float, str, float]]:
    """[(y_fp, kind, freq_hz)]: where straight rolling changes stability in y_fp
    at speed V (eigenvalue scan over YFP_MIN..YFP_MAX)."""
    grid = numpy.geomspace(YFP_MIN, YFP_MAX, 241)
    return spectrum.stability_changes("figures", "yfp", grid, V=V, Fstar=Fstar,
                                      **{**SCALINGS[scaling], **model})


def orbit_in_yfp(rundir: str, tag: str, point: Any, scaling: str, V: float,
                 figure: str = "magnitude", **model: Any) -> Tuple[List[Any], List[Any]]:
    """A periodic orbit at fixed V continued in y_fp both ways over
    [YFP_MIN, YFP_MAX], across the Hopf points of straight rolling in y_fp
    (continuation.follow_orbits; runs stop 0.1% either side of them).
    Returns (down, up): the lists of runs in each direction, in order."""
    hopf = {y: hz for y, kind, hz in yfp_thresholds(scaling, V, **model)
            if kind == "HB"}
    return tuple(ct.follow_orbits(rundir, lambda n, d=direction: f"{tag}_{d}{n}", point, "yfp",
                                  hopf, lambda y: 1e-3 * y, (YFP_MIN, YFP_MAX),
                                  figure=f"{figure}: {tag}", DS=ds, DSMAX=1.0, NMX=1000,
                                  THU=THU)[0]
                 for direction, ds in (("down", -0.005), ("up", 0.005)))


def hopf_curves(rundir: str, tag: str, scaling: str, seeds: Sequence[float] = (1.0, 0.15),
                Fstar: float = FSTAR, figure: str = "magnitude",
                **model: Any) -> List[Tuple[Any, Any]]:
    """Curves of Hopf points of straight rolling in (y_fp, V), V in
    [V_MIN, V_MAX], y_fp in [YFP_MIN, YFP_MAX], each continued both ways
    from a Hopf point found at one of the seed y_fp values; a seed Hopf point
    already on a computed curve is skipped.  [(run_down, run_up)]; the
    frequency along a curve is 1/T (PAR(11), printed)."""
    curves = []
    for yfp in seeds:
        vals = values(scaling, yfp, Fstar, **model)
        for V, _ in spectrum.hopf_scan("figures", "V", V_SCAN, **vals):
            if any(_on_curve(c, yfp, V) for c in curves):
                continue
            name = f"{tag}_y{yfp:g}_V{V:.0f}"
            hb = ct.hopf_point(rundir, f"{name}_hb", "figures", "V", V, **vals)
            pair = _hopf_runs(rundir, name, hb, figure)
            progress(figure, f"{name}: Hopf curve through (y_fp, V) = ({yfp:g}, {V:.3f}), "
                             f"{sum(len(r[0]) for r in pair)} points")
            curves.append(pair)
    return curves


def _hopf_runs(rundir, name, hb, figure):
    """Both directions of a Hopf curve in (y_fp, V) from the point hb.  AUTO
    0.9.2 stops (MX) where the curve turns back in its first parameter (seen
    at the turn in V of the high-frequency curve, y_fp ~ 0.10 mm, and at the
    turn in y_fp of the low-frequency one, y_fp ~ 0.32 mm), so if one
    direction fails both are repeated with the parameters swapped.  The steps
    are bounded in the first parameter (AUTO's steps on these curves follow
    it): 0.005 mm in y_fp, 0.1 m/s in V."""
    for order, step in ((["yfp", "V"], 0.005), (["V", "yfp"], 0.1)):
        try:
            return tuple(ct.hopf_curve(rundir, f"{name}_{d}", hb, order, with_period=True,
                                       stop={"V": [V_MIN, V_MAX], "yfp": [YFP_MIN, YFP_MAX]},
                                       DS=sign * step / 5, DSMAX=step, NMX=4000)
                         for d, sign in (("a", 1), ("b", -1)))
        except runerror.RunError as exc:
            progress(figure, f"{name}: Hopf curve with ICP {order} stops ({exc.brief})"
                     + ("; repeating with the parameters swapped" if order[0] == "yfp" else ""))
    raise runerror.RunError(f"{name}: Hopf curve failed with both parameter orders")


def _on_curve(curve, yfp, V):
    """True if (yfp, V) lies within 2% (relative) of the polyline of a curve."""
    ys, Vs = curve_points(curve, "yfp", "V")
    p = numpy.c_[ys / yfp, Vs / max(V, 1.0)]
    q = numpy.array([1.0, V / max(V, 1.0)])
    a, b = p[:-1], p[1:]
    t = numpy.clip(numpy.sum((q - a) * (b - a), axis=1)
                   / numpy.maximum(numpy.sum((b - a) ** 2, axis=1), 1e-300), 0.0, 1.0)
    return numpy.min(numpy.hypot(*(a + t[:, None] * (b - a) - q).T)) < 0.02


def fold_curve(rundir: str, tag: str, run: Any, label: int,
               figure: str = "magnitude") -> Tuple[Any, Any]:
    """The fold of cycles at `label` of the periodic run `run` (in V)
    continued in (y_fp, V) both ways, y_fp up to FOLD_YFP_MAX
    (continuation.fold_curve), with the arclength weights THU on the starting
    run too: without them it stops (MX) on the fold of y_fp = 0.15 mm."""
    pair = ct.fold_curve(rundir, tag, run(label), ("yfp", "V"), both_ways=True, start={},
                         stop={"V": [V_MIN, V_MAX], "yfp": [YFP_MIN, FOLD_YFP_MAX]},
                         DS=0.01, DSMAX=0.5, NMX=1000, THU=THU)
    progress(figure, f"{tag}: fold-of-cycles curve, {sum(len(r[0]) for r in pair)} points")
    return pair


def linear_fit(x: ArrayLike, y: ArrayLike) -> Tuple[float, float, float, float]:
    """Least squares y = s x through the origin and y = s x + c:
    (s0, max relative residual of the first, s, c)."""
    x, y = numpy.asarray(x), numpy.asarray(y)
    s0 = float(x @ y / (x @ x))
    residual = float(numpy.max(numpy.abs(y - s0 * x) / numpy.abs(y)))
    s, c = numpy.polyfit(x, y, 1)
    return s0, residual, float(s), float(c)


def orbits_in_yfp(rundir: str, diagram: Any, figure: str = "magnitude",
                  **model: Any) -> List[Tuple[float, Tuple[List[Any], List[Any]]]]:
    """[(V, (run down, run up))]: each stable orbit at each of V_ORBITS in
    `diagram` continued in y_fp (runs orbit_V<V>, orbit_V<V>_<k> for the
    k-th).  The paper's gear has one at each speed; a changed gear may have
    none (at rho = 20, mu = 5 deg no low-frequency shimmy: straight rolling
    is stable at 15 m/s), which is said, or several."""
    result = []
    for V in V_ORBITS:
        found = stable_orbits(diagram, V)
        if not found:
            progress(figure, f"no stable orbit at V = {V:g} m/s (y_fp = {diagram.yfp:g} mm): "
                             "none continued in y_fp there")
        for k, (run, lab) in enumerate(found):
            result.append((V, orbit_in_yfp(rundir, f"orbit_V{V:g}" + (f"_{k + 1}" if k else ""),
                                           run(lab), diagram.scaling, V, figure, **model)))
    return result


def orbit_curve(runs: Tuple[Sequence[Any], Sequence[Any]],
                measure: str) -> Tuple[numpy.ndarray, numpy.ndarray, numpy.ndarray]:
    """(y_fp, measure, stable mask) along the orbits of orbits_in_yfp, joined
    at the starting orbit and sorted along the continuation."""
    def joined(pieces, column):
        return numpy.concatenate([numpy.asarray(r[0][column])[1:] for r in pieces])
    down, up = runs

    def stable(pieces):
        return numpy.concatenate([branches.stable_mask(r[0])[1:] for r in pieces])
    first = up[0][0]
    ys = numpy.r_[joined(down, "yfp")[::-1], first["yfp"][0], joined(up, "yfp")]
    ms = numpy.r_[joined(down, measure)[::-1], first[measure][0], joined(up, measure)]
    st = numpy.r_[stable(down)[::-1], branches.stable_mask(first)[0], stable(up)]
    return ys, ms, st


def window_point_curve(rundir: str, tag: str, yfp: float, Fstar: float, stop: Sequence[float],
                       dsmax: float = 0.02, **model: Any) -> Dict[str, Any]:
    """The Hopf point of straight rolling at V = V_LIMIT near y_fp = `yfp`
    (eps = 0.1 mm; a window point a or b on V = V_LIMIT) continued by AUTO in
    (F*, y_fp) both ways from `Fstar` to the loads `stop`.  `model`: PAR
    overrides (e.g. strut_variant=1).  {"up"/"down": the run, or the
    RunError that stopped it}.  The stage-switch overlay (DSMIN = 1e-10): with
    the printed strut (variant 1) the curve turns twice in F* while eta
    crosses the 1e-5 m wide stage switch (F* 0.63-0.70); AUTO's default
    1e-5 stops it (MX) there."""
    vals = {"Fstar": Fstar, "V": V_LIMIT, **SCALINGS["fixed"], **model}
    hb = ct.hopf_point(rundir, f"{tag}_hb", "figures", "yfp", yfp, width=0.05 * yfp, **vals)
    out = {}
    for direction, ds in (("up", 0.01), ("down", -0.01)):
        try:
            out[direction] = ct.hopf_curve(rundir, f"{tag}_{direction}", hb, ("Fstar", "yfp"),
                                           stop={"Fstar": list(stop)}, with_period=True, DS=ds,
                                           overlay="stage_switch", DSMAX=dsmax)
        except runerror.RunError as exc:
            out[direction] = exc
    return out


def window_point_values(rundir: str, tag: str, name: str, points: Sequence[Mapping[str, Any]],
                        **model: Any) -> List[Tuple[float, Any, float]]:
    """The window point `name` ("a" or "b") of each scanned point on V =
    V_LIMIT (kappa_criterion.window_points) located by AUTO in y_fp at that
    point's load, one run each (<tag>_<i>): [(F*, AUTO's y_fp or the
    RunError, the scan's y_fp)].  The check where the curve of Hopf points
    (window_point_curve) cannot be continued: AUTO differences its Hopf
    system with a step of 1e-7 (1 + omega^2) in every state
    (equilibrium.f90, FNHBF), 7e-4 rad at omega = 82 rad/s, wider than the
    smoothed freeplay corner when the point's equilibrium sits on it (b at
    rho = 15, mu = -5 deg); a one-parameter run has no such step."""
    out = []
    for i, p in enumerate(p for p in points
                          if p["V_" + name] == V_LIMIT and p[name] is not None
                          and numpy.isfinite(p[name])):
        vals = {"Fstar": p["Fstar"], "V": V_LIMIT, **SCALINGS["fixed"], **model}
        try:
            found = ct.hopf_point(rundir, f"{tag}_{i}", "figures", "yfp", p[name],
                                  width=0.05 * p[name], **vals)["yfp"]
        except runerror.RunError as exc:
            found = exc
        out.append((p["Fstar"], found, p[name]))
    return out


def fold_curves(rundir: str, tag: str, diagrams: Sequence[Any],
                figure: str = "magnitude") -> List[Tuple[Any, Any]]:
    """Curves of folds of cycles in (y_fp, V) through the folds of the given
    Diagrams; a fold already on a computed curve is not started again."""
    curves = []
    for d in diagrams:
        for n, (run, lab, V, _) in enumerate(d.folds()):
            if any(_on_curve(c, d.yfp, V) for c in curves):
                continue
            curves.append(fold_curve(rundir, f"{tag}_y{d.yfp:g}_{n}", run, lab, figure=figure))
    return curves


def curve_points(curve: Tuple[Any, Any], x: str, y: str) -> Tuple[numpy.ndarray, numpy.ndarray]:
    """The two runs of a curve joined into one (x, y) polyline."""
    a, b = (run[0] for run in curve)
    return (numpy.r_[numpy.asarray(b[x])[::-1], numpy.asarray(a[x])],
            numpy.r_[numpy.asarray(b[y])[::-1], numpy.asarray(a[y])])
