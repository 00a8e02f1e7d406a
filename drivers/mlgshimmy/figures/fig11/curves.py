"""Fig. 11's curves from the Fig. 10 special points at F* = 1: Hopf curves,
folds of periodic orbits (and the upper fold curves started from the
slices' folds), the pitchforks and the zero-freeplay Hopf curve."""
from __future__ import annotations

import functools
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

from mlgshimmy.figures.fig11 import ends
from mlgshimmy.figures.fig11.ends import SWITCH_WIDTHS, explained
from mlgshimmy.figures.fig11.orbits import ROLLING, slice_rundir
from mlgshimmy.figures.fig11.plane import (GEOMETRY, MODEL, F_MAX, F_MIN, ON_CURVE_TOL, SLICES,
                                           STOP, V_SCAN, on_curves)
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import jobs
from mlgshimmy.shared import paths
from mlgshimmy.shared import spectrum
from mlgshimmy.shared import stationary
from mlgshimmy.shared.stage_switch import stage_switch_window

FOLD_TIME_LIMIT = 120  # s of CPU, guard for a fold-curve run (they take 20-40 s)
MAX_TURNS = 10         # slices back inside the Hopf curves' turns (slice_hopf)


def hopf_curve(rundir: str, name: str, point: Any, sign: float) -> Any:
    """A Hopf curve of Fig. 11 from `point` in (F*, V), first step DS = 0.002
    sign: steps down to 1e-10 (the stage-switch overlay) so that it
    reaches its turning point inside the oleo's stage switch."""
    return ct.hopf_curve(rundir, name, point, ("Fstar", "V"), stop=STOP, overlay="stage_switch",
                         DS=0.002 * sign, DSMAX=0.02, NMX=5000, allow_mx=True)


def fold_curve(rundir: str, name: str, point: Any, sign: float, **kw: Any) -> Any:
    """A fold curve of Fig. 11 from the LP `point`, first step DS = 0.05
    sign.  An MX end that nothing explains (ends.explained: not inside the
    stage switch, not on the Hopf locus) sends it up the retry ladder
    (continuation.LADDER), each rung tried from the stop first
    (continuation.PROBE_STEPS); if every rung stops too, the last run is
    kept and the stop reported."""
    return ct.fold_curve(rundir, name, point, ("V", "Fstar"), stop=STOP, DS=0.05 * sign,
                         DSMAX=1.0, NMX=400, allow_mx=FOLD_ENDS, **kw)


def fold_end_explained(point: Any, _parameter: str) -> bool:
    """Whether a fold curve's MX point is an end ends.explained accounts for
    (on the Hopf locus counts: the GH points are located after the curves)."""
    stop = {"V": point["V"], "Fstar": point["Fstar"], "curve": "fold"}
    return not explained([stop], stage_switch(), None, at_gh=ends.on_hopf_locus)["open"]


FOLD_ENDS = ct.Ends(fold_end_explained, "neither inside the stage switch nor on the Hopf "
                    "locus", keep=True, probe=True)


@functools.lru_cache(maxsize=None)
def stage_switch() -> Optional[Tuple[float, float]]:
    """The stage-switch window of the plane's loads (ends.inside)."""
    return stage_switch_window(F_MIN, F_MAX, SWITCH_WIDTHS, **GEOMETRY)


def curves(rundir: str, parameter_set: str = "figures") -> Dict[str, Any]:
    """Hopf and fold curves continued from the F* = 1 points of Fig. 10, the
    zero-freeplay Hopf curve and the pitchfork loads (at three speeds: they
    do not depend on V), or with side-stay angles the loads of the folds
    of the yawed states (shared.stationary), "stationary_folds"."""
    out = {"hopf": [], "fold": [], "zero": []}
    points = ct.hopf_points(rundir, "hb", parameter_set, "V", V_SCAN, Fstar=1.0, **MODEL)
    for k, point in enumerate(points):
        for sign in (1, -1):
            name = f"hopf{k + 1}{'+-'[sign < 0]}"
            out["hopf"].append(ct.reported(f"fig11 {name}",
                                           lambda: hopf_curve(rundir, name, point, sign)))
    # the fold S, located on an orbit run with the base step sizes (the fold
    # located on Fig. 10's finer-stepped run does not start the fold curve)
    high = ct.periodic_from(rundir, "po_fold", points[-1], stop={"V": [30.0, 200.0]},
                            NMX=400, expect=["LP"])
    for k, point in enumerate(high("LP")):
        for sign in (1, -1):
            name = f"fold{k + 1}{'+-'[sign < 0]}"
            out["fold"].append(ct.reported(f"fig11 {name}",
                                           lambda: fold_curve(rundir, name, point, sign)))
    zero, = ct.hopf_points(rundir, "hb_zero", parameter_set, "V", V_SCAN, Fstar=1.0, yfp=0.0,
                           **GEOMETRY)
    for sign in (1, -1):
        name = f"hopf_zero{'+-'[sign < 0]}"
        out["zero"].append(ct.reported(f"fig11 {name}", lambda: ct.hopf_curve(
            rundir, name, zero, ("Fstar", "V"), stop=STOP, DS=0.02 * sign, allow_mx=True)))
    out = {kind: [d for d in found if d is not None] for kind, found in out.items()}
    if not stationary.symmetric(MODEL):
        # the pitchforks are imperfect: the folds of the yawed states bound
        # where they exist (at every V: the states do not depend on it)
        found = stationary.states(paths.rundir("fig11/stationary"), parameter_set,
                                  (F_MIN, F_MAX), V=50.0, **MODEL)
        out["stationary_folds"] = [f for f, _, _ in found.folds()]
        print("fig11: folds of the yawed states at F* = "
              + (", ".join(f"{f:.6f}" for f in out["stationary_folds"]) or "none"))
        out["pitchfork"] = [[], [], []]
        return out
    out["pitchfork"] = []
    for V in (5.0, 50.0, 300.0):
        loads = [f for f, kind, _ in spectrum.stability_changes(
            parameter_set, "Fstar", numpy.linspace(F_MIN, F_MAX, 800), V=V, **MODEL)
            if kind == "BP"]
        print(f"fig11: pitchforks at V = {V:g}: F* = " + ", ".join(f"{f:.6f}" for f in loads))
        out["pitchfork"].append(loads)
    return out


def upper_folds(rundir: str, first: Mapping[str, Any],
                folds: Mapping[float, Sequence[Tuple[str, int]]]) -> List[Any]:
    """Curves of folds of periodic orbits (of LOW_FREQUENCY_HZ or more) that
    the curves from the fold S (`first`, stored) do not pass: continued
    both ways from each fold of a slice, lightest load first (folds:
    {slice load: [(run name, label)]}), that no curve computed so far
    passes through.  At the paper's gear these are the folds of the slices
    above the top of the S curves (its others all lie on them); with
    side-stay angles also folds below it (the small orbits inside the
    freeplay that the family born above 9.3 Hz has there).  A direction
    that fails (or stalls: FOLD_TIME_LIMIT) is reported and left out; a
    fold on no curve at the end (a curve stopped short) is reported.  The
    part and run names keep "upper" (the reference set's)."""
    first = [jobs.loaded(diagram) for diagram in first]
    out, k = [], 0
    points = [ct.load(slice_rundir(Fstar), name)(lab) for Fstar in SLICES
              for name, lab in folds[Fstar]]
    for point in points:
        if on_curves(point, first) or on_curves(point, out):
            continue
        k += 1
        for sign in (1, -1):
            name = f"fold_upper{k}{'+-'[sign < 0]}"
            curve = ct.reported(name, lambda: fold_curve(rundir, name, point, sign,
                                                         time_limit=FOLD_TIME_LIMIT))
            out += [] if curve is None else [curve]
    missed = [p for p in points if not (on_curves(p, first) or on_curves(p, out))]
    for p in missed:
        print(f"REPORTED: fig11 slice fold at V = {p['V']:.4g}, F* = {p['Fstar']:.4g} "
              "lies on no fold curve")
    print(f"fig11: {len(points) - len(missed)} of {len(points)} slice folds lie on the "
          f"fold curves ({k} started from them)")
    return out


def slice_hopf(rundir: str, first: Mapping[str, Any], folds: Sequence[Any] = (),
               parameter_set: str = "figures") -> List[Any]:
    """Hopf curves of straight rolling that the curves from F* = 1 (`first`,
    stored) do not pass: continued both ways from each Hopf point of a
    slice (an eigenvalue scan in V at the slice load, lightest first) that
    no curve computed so far passes through.  At the paper's gear every one
    lies on them (56 of 56, so no run is made); with side-stay angles the
    H3 curve stops inside the oleo stage switch, and the curves below the
    switch and of other modes start here.  Then a short slice at each end of
    the fold curves `folds` (stored) on the Hopf locus (ends.on_locus) that
    no Hopf curve passes, and
    while a Hopf curve stops where it turns in F* (ends.turns), one back
    inside the turn, start the curves found there (at most MAX_TURNS such
    slices).  A start or direction that fails is reported and left out."""
    first = [jobs.loaded(diagram) for diagram in first]
    out: List[Any] = []
    k = 0

    def start(Fstar, window, tol):
        nonlocal k
        state = ROLLING and (lambda V, F=Fstar: ROLLING(F, parameter_set))
        for V, _ in spectrum.hopf_scan(parameter_set, "V", window, state=state, Fstar=Fstar,
                                       **MODEL):
            at = {"V": V, "Fstar": Fstar}
            if on_curves(at, first, tol) or on_curves(at, out, tol):
                continue
            k += 1
            point = ct.reported(f"fig11 Hopf point at V = {V:.4g}, F* = {Fstar:.4g}",
                                lambda: ct.hopf_point(rundir, f"hb_slice{k}", parameter_set,
                                                      "V", V, state=state, Fstar=Fstar,
                                                      **MODEL))
            for sign in (1, -1) if point is not None else ():
                name = f"hopf_slice{k}{'+-'[sign < 0]}"
                curve = ct.reported(name, lambda: hopf_curve(rundir, name, point, sign))
                if curve is not None:
                    out.append(curve)

    for Fstar in SLICES:
        start(Fstar, V_SCAN, ON_CURVE_TOL)
    print(f"fig11: {k} Hopf curves started from the slices' Hopf points")
    scanned: List[Tuple[float, float]] = []
    fold_ends = ends.on_locus(folds, stage_switch())
    while len(scanned) < MAX_TURNS:
        lone = [(F, V) for F, V in fold_ends
                if not on_curves({"V": V, "Fstar": F}, first + out, ends.TURN_TOL)]
        new = [(F, V) for F, V in lone + ends.turns(first + out, stage_switch())
               if not any(abs(F - f) < 0.5 * ends.TURN_DF and abs(V - v) < ends.TURN_WINDOW
                          for f, v in scanned)]
        if not new:
            break
        Fstar, V = new[0]
        scanned.append((Fstar, V))
        before = k
        start(Fstar, V_SCAN[abs(V_SCAN - V) < ends.TURN_WINDOW], ends.TURN_TOL)
        print(f"fig11: a slice at F* = {Fstar:.5g} near V = {V:.4g} (a fold curve's end on "
              f"the Hopf locus, or a Hopf curve's turn): {k - before} Hopf point(s) started")
    return out


def slice_hopf_curves(parts: Mapping[str, Any]) -> Dict[str, Any]:
    """A part: the Hopf curves from the slices' Hopf points (slice_hopf),
    stored: {"curves": [stored diagrams]}."""
    folds = [jobs.loaded(d) for d in parts["curves"]["fold"] + parts["upper_folds"]["curves"]]
    found = slice_hopf(paths.rundir("fig11/slice_hopf"), parts["curves"]["hopf"], folds)
    return {"curves": [jobs.stored(d, ("V", "Fstar")) for d in found]}


def stored_curves() -> Dict[str, Any]:
    out = curves(paths.rundir("fig11/curves"))
    return {**{kind: [jobs.stored(d, ("V", "Fstar"), ends.orbit_at_switch if kind == "fold"
                                  else None) for d in out[kind]]
               for kind in ("hopf", "fold", "zero")},
            **{k: out[k] for k in ("pitchfork", "stationary_folds") if k in out}}


def upper_fold_curves(parts: Mapping[str, Any]) -> Dict[str, Any]:
    """A part: the fold curves from the slices' folds (upper_folds),
    stored: {"curves": [stored diagrams]}."""
    upper = upper_folds(paths.rundir("fig11/upper_folds"), parts["curves"]["fold"],
                        {Fstar: parts[f"slice_{Fstar:.4f}"]["folds"] for Fstar in SLICES})
    return {"curves": [jobs.stored(d, ("V", "Fstar"), ends.orbit_at_switch) for d in upper]}
