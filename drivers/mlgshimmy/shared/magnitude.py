"""Shared pieces of the freeplay-magnitude figures (Figs. 13-19, sections
IV.D-IV.E): the two ways of varying the freeplay y_fp, one-parameter
diagrams in V at a given y_fp, the orbits at fixed V continued in y_fp, and
the curves of Hopf points and folds of cycles in (y_fp, V).

    d = diagram_in_V(rundir, "y1", "ratio", 1.0)     # Hopf points + orbits
    for point in stable_orbits(d, 50.0): ...         # UZ labels at V = 50
    curves = hopf_curves(rundir, "fixed")            # in (y_fp, V)

Scalings (section III): shared.freeplay.  Everything is at
F* = 1 unless Fstar is passed.  `**model` (where a function takes it)
overrides parameters or constants of every model it builds by name, e.g.
strut_variant=1, or a side-stay geometry (shared.gear.parameters()).
"""
import functools
import os

import numpy

from mlgshimmy.shared import runerror
from mlgshimmy.shared import branches
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import jobs
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import paths
from mlgshimmy.shared import rolling
from mlgshimmy.shared import spectrum
from mlgshimmy.shared.freeplay import EPSILON, SCALINGS

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


def values(scaling, yfp, Fstar=FSTAR, **more):
    return {"Fstar": Fstar, "yfp": yfp, **SCALINGS[scaling], **more}


def progress(figure, text):
    print(f"{figure}: {text}", flush=True)


def diagram_in_V(rundir, tag, scaling, yfp, Fstar=FSTAR, uzr=V_ORBITS, figure="magnitude",
                 **model):
    """continuation.speed_diagram over V_SCAN at this y_fp (runs
    <tag>_hb<i>, <tag>_po<i>, i from 0), with UZ labels at the speeds `uzr`
    and the weighted small first steps the orbits here need."""
    return ct.speed_diagram(rundir, "figures", values(scaling, yfp, Fstar, **model), V_SCAN,
                            tag=f"{tag}_", first=0, gap=HOPF_GAP, figure=f"{figure}: {tag}",
                            about={"scaling": scaling, "yfp": yfp},
                            UZR={"V": list(uzr)} if uzr else {}, DS=1e-4, DSMAX=DSMAX_V,
                            DSMIN=1e-9, NMX=2000, THU=THU)


def stable_orbits(diagram, V):
    """[(run, label)] of the stable orbits carrying a UZ label at speed V."""
    found = []
    for run in diagram.branches:
        for branch in run:
            stable = branches.stable_mask(branch)
            for index, lab, _ in branches.labelled_points(branch, "UZ"):
                if abs(branch["V"][index] - V) < 1e-3 and stable[index]:
                    found.append((run, lab))
    return found


def yfp_thresholds(scaling, V, Fstar=FSTAR, **model):
    """[(y_fp, kind, freq_hz)]: where straight rolling changes stability in y_fp
    at speed V (eigenvalue scan over YFP_MIN..YFP_MAX)."""
    grid = numpy.geomspace(YFP_MIN, YFP_MAX, 241)
    return spectrum.stability_changes("figures", "yfp", grid, V=V, Fstar=Fstar,
                                      **SCALINGS[scaling], **model)


def orbit_in_yfp(rundir, tag, point, scaling, V, figure="magnitude", **model):
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


def hopf_curves(rundir, tag, scaling, seeds=(1.0, 0.15), Fstar=FSTAR, figure="magnitude",
                **model):
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


def fold_curve(rundir, tag, run, label, figure="magnitude"):
    """The fold of cycles at `label` of the periodic run `run` (in V)
    continued in (y_fp, V) both ways, y_fp up to FOLD_YFP_MAX
    (continuation.fold_curve), with the arclength weights THU on the starting
    run too: without them it stops (MX) on the fold of y_fp = 0.15 mm."""
    pair = ct.fold_curve(rundir, tag, run(label), ("yfp", "V"), both_ways=True, start={},
                         stop={"V": [V_MIN, V_MAX], "yfp": [YFP_MIN, FOLD_YFP_MAX]},
                         DS=0.01, DSMAX=0.5, NMX=1000, THU=THU)
    progress(figure, f"{tag}: fold-of-cycles curve, {sum(len(r[0]) for r in pair)} points")
    return pair


def linear_fit(x, y):
    """Least squares y = s x through the origin and y = s x + c:
    (s0, max relative residual of the first, s, c)."""
    x, y = numpy.asarray(x), numpy.asarray(y)
    s0 = float(x @ y / (x @ x))
    residual = float(numpy.max(numpy.abs(y - s0 * x) / numpy.abs(y)))
    s, c = numpy.polyfit(x, y, 1)
    return s0, residual, float(s), float(c)


def orbits_in_yfp(rundir, diagram, figure="magnitude", **model):
    """{V: (run down, run up)}: the stable orbit at each of V_ORBITS in
    `diagram` continued in y_fp.  Raises RunError unless exactly one stable
    orbit carries the UZ label at that speed."""
    result = {}
    for V in V_ORBITS:
        found = stable_orbits(diagram, V)
        if len(found) != 1:
            raise runerror.RunError(f"{figure}: {len(found)} stable orbits at V = {V:g} "
                                    f"(y_fp = {diagram.yfp:g}), expected one")
        run, lab = found[0]
        result[V] = orbit_in_yfp(rundir, f"orbit_V{V:g}", run(lab), diagram.scaling, V, figure,
                                 **model)
    return result


def orbit_curve(runs, measure):
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


def stored_orbits(orbits):
    """The orbits of orbits_in_yfp for the cache: [(V, {"yfp", "psi_amp",
    "freq", "stable"})], each joined by orbit_curve."""
    out = []
    for V, runs in orbits.items():
        ys, amp, stable = orbit_curve(runs, "psi_amp")
        out.append((V, {"yfp": ys, "psi_amp": amp, "freq": orbit_curve(runs, "freq")[1],
                        "stable": stable}))
    return out


COLUMNS = ("V", "psi_amp", "freq")


def stored_diagram(diagram):
    """A Diagram in V for the cache: y_fp, scaling, Hopf points, folds
    (V, psi_amp), the orbit branches (jobs.stored) and per orbit run its
    first and smallest V (a turn AUTO may not label LP)."""
    return {"yfp": diagram.yfp, "scaling": diagram.scaling, "hopf": diagram.hopf,
            "hopf_names": [p["name"] for p in diagram.named],
            "folds": [(V, amp) for _, _, V, amp in diagram.folds()],
            "branches": [b for run in diagram.branches for b in jobs.stored(run, COLUMNS)],
            "turns": [(run[0]["V"][0], min(run[0]["V"])) for run in diagram.branches]}


def diagram_jobs(figure, scaling, freeplays, prefix="", orbits_at=None, uzr=V_ORBITS, **model):
    """The parts of a figure made of diagrams in V (jobs.Parts): one per
    y_fp, named <prefix>y<y_fp>, computing the stored diagram (runs
    <prefix>y<y_fp>_hb<i>, _po<i>, in the part's own run directory
    $MLG_RUN_ROOT/<figure>/<part>/); the one at y_fp = orbits_at (named
    ..._orbits) also continues its stable orbits at V_ORBITS in y_fp."""
    def job(y, name):
        def run():
            rundir = paths.rundir(os.path.join(figure, name))
            d = diagram_in_V(rundir, f"{prefix}y{y:g}", scaling, y, uzr=uzr, figure=figure,
                             **model)
            out = {"diagram": stored_diagram(d)}
            if y == orbits_at:
                out["orbits"] = stored_orbits(orbits_in_yfp(rundir, d, figure, **model))
            return out
        return run
    names = {y: f"{prefix}y{y:g}" + ("_orbits" if y == orbits_at else "") for y in freeplays}
    return {names[y]: job(y, names[y]) for y in freeplays}


def diagrams_of(done, prefix=""):
    """(stored diagrams in order, stored orbits or None) from the computed
    parts {name: data} of diagram_jobs(..., prefix)."""
    done = [data for name, data in done.items() if name.startswith(prefix + "y")]
    orbits = [p["orbits"] for p in done if "orbits" in p]
    return [p["diagram"] for p in done], (orbits[0] if orbits else None)


def diagram_numbers(diagrams, prefix=""):
    """{quantity: value}: the Hopf and fold speeds of stored diagrams, as
    "<prefix>y_fp = <y>: <name> [m/s]" (the Hopf points named by their mode,
    shared.naming) and "...: S<k> [m/s]"."""
    out = {}
    for d in diagrams:
        for name, (V, _) in zip(d["hopf_names"], d["hopf"]):
            out[f"{prefix}y_fp = {d['yfp']:g}: {name} [m/s]"] = V
        for k, (V, _) in enumerate(d["folds"]):
            out[f"{prefix}y_fp = {d['yfp']:g}: S{k + 1} [m/s]"] = V
    return out


BANDS = {"low": (1e-6, 8.0), "high": (8.0, numpy.inf), "real": (-1.0, 1e-6)}
KAPPA_GRID = numpy.geomspace(YFP_MIN, YFP_MAX, 61)
# The loads of the envelope of section IV.E, F* <= 2 (F* = 0 lifts a wheel off).
ENVELOPE_LOADS = numpy.round(numpy.arange(0.1, 2.0001, 0.05), 3)


@functools.lru_cache(maxsize=1024)
def straight_rolling(parameter_set, Fstar, overrides):
    """The straight-rolling state at load F* with the parameter overrides
    ((name, value) pairs).  It is the same for every V > 0 (docs/model.md
    4.20), and at rho = mu = 0 for every freeplay (the torque links carry
    no load at psi = 0), so the scans below solve it once per load there
    (rolling_state)."""
    return mlgmodel.Model(parameter_set, Fstar=Fstar, **dict(overrides)).equilibrium()


def rolling_state(Fstar, yfp, scaling="fixed", parameter_set="figures", **model):
    """straight_rolling at this freeplay.  At rho = mu = 0 it is solved once
    per load.  With side-stay angles (rho or mu in `model` non-zero)
    straight rolling twists the links (docs/model.md 8.7): its state depends
    on the freeplay, and at light load several equilibria coexist, so it is
    the one continued from zero freeplay (shared.rolling; NoRollingState
    beyond a fold in y_fp)."""
    if model.get("rho", 0.0) or model.get("mu", 0.0):
        return rolling.state(parameter_set, Fstar, yfp, SCALINGS[scaling], **model)
    return straight_rolling(parameter_set, Fstar, tuple(sorted(model.items())))


def growth(Fstar, yfp, V, scaling="fixed", parameter_set="figures", **model):
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
    model = mlgmodel.Model(parameter_set, **values(scaling, yfp, Fstar, V=V), **model)
    model.check()
    return spectrum.growth(model, BANDS, u)


def growth_at_speeds(Fstar, yfp, speeds, scaling="fixed", parameter_set="figures", **model):
    """[growth at each of `speeds`] from one state of straight rolling
    (it does not depend on V)."""
    try:
        u = rolling_state(Fstar, yfp, scaling, parameter_set, **model)
    except rolling.NoRollingState:
        return [{"any": numpy.inf, **{band: -numpy.inf for band in BANDS}, "real": numpy.inf}
                for _ in speeds]
    at = mlgmodel.Model(parameter_set, **values(scaling, yfp, Fstar, V=speeds[0]), **model)
    jacobians = []
    for V in speeds:
        at.set(V=V)
        at.check()
        jacobians.append(at.jacobian(u))
    return spectrum.growths(numpy.array(jacobians), BANDS)


def first_crossing(Fstar, speeds, band, grid=KAPPA_GRID, **model):
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


def yfp_crossings(Fstar, V, band, grid=KAPPA_GRID, scaling="fixed", first_only=False, **model):
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


def extreme_yfp_crossing(Fstar, band, highest=False, speeds=numpy.linspace(V_MIN, V_LIMIT, 25),
                     **model):
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


def least_unstable(Fstar, **model):
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


def window_point_curve(rundir, tag, yfp, Fstar, stop, dsmax=0.02, **model):
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


def refined_minimum(evaluate, loads, key, points=None, finer=(10,), floor=-numpy.inf):
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


def kappa_star(evaluate, loads, model, points=None, finer=(10,)):
    """Eq. (17)'s kappa*: the least y_fp/eps at which straight rolling is
    unstable below V_LIMIT, minimised over the loads (refined_minimum of
    evaluate(F*)["first"], the least unstable y_fp there) and the loads on
    the stage switch of the gear `model` (parameter overrides,
    stage_switch_loads); (kappa*, the evaluation at the minimum).  A load
    unstable without freeplay (y_fp = 0, kappa* = 0) ends the search."""
    best = refined_minimum(evaluate, loads, lambda p: p["first"], points, finer, floor=0.0)
    for Fstar in stage_switch_loads(loads, **model) if best["first"] > 0 else ():
        point = evaluate(Fstar)
        if point["first"] < best["first"]:
            best = point
    return best["first"] / EPSILON, best


# F* on a grid of 0.1, refined to 0.02 and then 0.005 around the minimum
# (the resolution of Fig. 18's grid refinement, with a third of its loads)
CRITERION_LOADS = ENVELOPE_LOADS[::2]
CRITERION_FINER = (5, 4)


def criterion(model):
    """Eq. (17)'s kappa* of the gear `model` (parameter overrides) by the
    criterion's recipe: {kappa, Fstar, V, eta, mode} at the minimum over
    CRITERION_LOADS, refined CRITERION_FINER around it (studies.criterion,
    studies.robustness)."""
    kappa, best = kappa_star(lambda F: least_unstable(F, **model), CRITERION_LOADS, model,
                             finer=CRITERION_FINER)
    return {"kappa": kappa, "Fstar": best["Fstar"], "V": best["V"],
            "eta": best["eta"], "mode": best["mode"]}


SWITCH_WIDTHS = 3.0    # the stage switch: eta* within this many 1/k_stage of eta_stage
SWITCH_LOADS = 5       # loads evaluated across it


def zero_freeplay_eta(Fstar, parameter_set="figures", **model):
    """eta* [m] of straight rolling without freeplay at this load."""
    return rolling_state(Fstar, 0.0, parameter_set=parameter_set, **model)["eta"]


def stage_switch_window(lo, hi, widths=SWITCH_WIDTHS, parameter_set="figures", **model):
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


def stage_switch_loads(loads, parameter_set="figures", **model):
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


def kappa_star_off_switch(evaluate, loads, model, finer=(10,)):
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
    return best["first"] / EPSILON, best, window


def window_points(Fstar, **model):
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


def fold_curves(rundir, tag, diagrams, figure="magnitude"):
    """Curves of folds of cycles in (y_fp, V) through the folds of the given
    Diagrams; a fold already on a computed curve is not started again."""
    curves = []
    for d in diagrams:
        for n, (run, lab, V, _) in enumerate(d.folds()):
            if any(_on_curve(c, d.yfp, V) for c in curves):
                continue
            curves.append(fold_curve(rundir, f"{tag}_y{d.yfp:g}_{n}", run, lab, figure=figure))
    return curves


def curve_points(curve, x, y):
    """The two runs of a curve joined into one (x, y) polyline."""
    a, b = (run[0] for run in curve)
    return (numpy.r_[numpy.asarray(b[x])[::-1], numpy.asarray(a[x])],
            numpy.r_[numpy.asarray(b[y])[::-1], numpy.asarray(a[y])])


def stored_curves(curves, columns=("yfp", "V")):
    """Curves (pairs of runs) for the cache: [{column: polyline}]
    (curve_points); "freq" is 1/T along a curve with the period printed."""
    out = []
    for curve in curves:
        line = {c: curve_points(curve, "yfp", c)[1] for c in columns if c != "freq"}
        if "freq" in columns:
            line["freq"] = 1.0 / curve_points(curve, "yfp", "T")[1]
        out.append(line)
    return out
