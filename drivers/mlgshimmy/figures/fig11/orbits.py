"""Fig. 11's periodic orbits on the slice loads: one diagram in V per slice,
the large-amplitude family (not Hopf-born in range) followed from F* = 1,
the eigenvalue grid of straight rolling, and which orbits are stable."""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Sequence, Tuple

import numpy

from mlgshimmy.figures.fig11.plane import (FREEPLAY, GEOMETRY, MODEL, F_GRID, F_MAX, F_MIN, SLICES, V_GRID, V_MAX, V_MIN, V_SCAN)
from mlgshimmy.shared import runerror
from mlgshimmy.shared import branches
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import gear
from mlgshimmy.shared import jobs
from mlgshimmy.shared import paths
from mlgshimmy.shared import spectrum
from mlgshimmy.shared import stationary
from mlgshimmy.shared import torus
from mlgshimmy.shared import yawed

# An orbit family is low-frequency if it is born at a Hopf point below this:
# the slices' Hopf frequencies fall in two groups, 1.7-8.3 Hz and 10.3-14.6
# Hz (the large family, 16-47 Hz, is not Hopf-born in range); a fixed split
# of each orbit's own frequency cut one family (5-14 Hz at F* > 2) in two.
FAMILY_SPLIT_HZ = 9.3
LOW_FREQUENCY_HZ = 8.0   # folds above it start fold curves (curves.upper_folds)


def large_seed(rundir: str, parameter_set: str = "figures") -> Any:
    """The large-amplitude shimmy orbit at F* = 1: the orbits born at the
    last Hopf point of straight rolling there, continued to V = 300 m/s
    (its UZ1 label), where they are stable."""
    hopf = spectrum.hopf_scan(parameter_set, "V", V_SCAN, Fstar=1.0, **MODEL)
    point = ct.hopf_point(rundir, "large_hb", parameter_set, "V", hopf[-1][0], Fstar=1.0,
                          **MODEL)
    return ct.periodic_from(rundir, "large_seed", point, stop={"V": [V_MIN, 300.0]})


def large_orbits(rundir: str, parameter_set: str = "figures") -> Dict[float, List[Any]]:
    """{slice load: orbit diagrams in V} of the large-amplitude shimmy family.
    Away from F* = 1 it need not be connected to a Hopf point of straight
    rolling inside V <= 600, so it is followed from its stable orbit at
    F* = 1, V = 300 m/s (large_seed): continued both ways in F* to every
    slice load, then both ways in V (large_run)."""
    seed = large_seed(rundir, parameter_set)
    out = {}
    for sign in (1, -1):
        family = ct.periodic_from(rundir, f"large_F{'+-'[sign < 0]}", seed("UZ1"), "Fstar",
                                  stop={"Fstar": [F_MIN, F_MAX]}, UZR={"Fstar": list(SLICES)},
                                  DS=0.02 * sign, DSMAX=0.1, allow_mx=True)
        for start in family("UZ"):
            Fstar = min(SLICES, key=lambda f: abs(f - start["Fstar"]))
            if abs(Fstar - start["Fstar"]) > 1e-4 or Fstar in out:
                continue
            out[Fstar] = [ct.periodic_from(rundir, large_run(Fstar, d), start,
                                           stop={"V": [V_MIN, V_MAX]}, DS=2.0 * d, DSMAX=5.0,
                                           allow_mx=True) for d in (1, -1)]
    return out


def large_run(Fstar: float, direction: int) -> str:
    """The name of the large part's diagram in V at a slice load, upwards
    (direction 1) or downwards (-1)."""
    return f"large_{Fstar:.3f}{'+-'[direction < 0]}"


def large_upwards(Fstar: float, complete: bool = True) -> Tuple[Any, List[Dict[str, Any]]]:
    """(diagram, torus crossings) of the large part's diagram in V upwards
    at a slice load (it must reach V_MAX unless not `complete`); its torus
    points are the crossings of a Floquet pair through |mu| = 1
    (floquet.torus_crossings)."""
    if Fstar not in SLICES:
        raise ValueError(f"fig11: F* = {Fstar} is no slice load: the large part has no "
                         "diagram in V there")
    rundir, name = paths.rundir("fig11/large"), large_run(Fstar, 1)
    orbits = ct.load(rundir, name)
    if complete and abs(orbits()[-1]["V"] - V_MAX) > 1e-3:   # AUTO's UZ stop: V_MAX
        raise runerror.RunError(f"run {name} in {rundir} stops at V = {orbits()[-1]['V']:.6g}, "
                                f"not V = {V_MAX:g}: its torus points are not all found")
    return orbits, torus.torus_crossings(rundir, name)


def straight_rolling(Fstar: float, parameter_set: str = "figures") -> Dict[str, float]:
    """Straight rolling at this load as {name: value} for the solvers to start
    from, the state continued from zero freeplay (shared.yawed.straight:
    with side-stay angles Newton from psi = 0 can miss it or land on a
    yawed state)."""
    u = yawed.straight(parameter_set, Fstar, FREEPLAY, **GEOMETRY)
    if u is None:
        raise RuntimeError(f"fig11: straight rolling from zero freeplay ends before "
                           f"y_fp = {FREEPLAY['yfp']:g} mm at F* = {Fstar:g}")
    return u


# what the solvers start from: None at the paper's gear (each its own
# Newton solve from psi = 0, as the reference set was made)
ROLLING = None if stationary.symmetric(MODEL) else straight_rolling


def straight_rolling_stable(parameter_set: str = "figures") -> numpy.ndarray:
    """[F*, V] on F_GRID x V_GRID: True where straight rolling is stable."""
    return spectrum.stable_on_grid(parameter_set, "Fstar", F_GRID, "V", V_GRID, ROLLING,
                                   **MODEL)


ORBIT_COLUMNS = ("V", "freq", "psi_amp")


def slice_rundir(Fstar: float) -> str:
    return paths.rundir(f"fig11/slice_{Fstar:.4f}")


def slice_diagram(Fstar: float, parameter_set: str = "figures") -> Dict[str, Any]:
    """The diagram in V at one slice load: its orbit branches (stored) and
    its folds of high-frequency orbits [(run name, label)] (to start fold
    curves from)."""
    print(f"fig11: slice F* = {Fstar:.4f}")
    diagram = ct.speed_diagram(slice_rundir(Fstar), parameter_set, {"Fstar": Fstar, **MODEL},
                               V_SCAN, allow_failed=True, figure="fig11",
                               state=ROLLING and (lambda V: ROLLING(Fstar, parameter_set)),
                               **{**ct.SPEED_ORBIT_STEPS,
                                  **ct.geometry_orbit_steps(gear.current().geometry.baseline)})
    return {"branches": [b for run in diagram.branches
                         for b in jobs.stored(run, ORBIT_COLUMNS)],
            "folds": [(diagram.name_of(run), lab) for run, lab, _, _ in diagram.folds()
                      if run(lab)["freq"] >= LOW_FREQUENCY_HZ]}


def large_family(parameter_set: str = "figures") -> Dict[str, List[Dict[str, Any]]]:
    """large_orbits stored: {slice load as "%.4f": [stored branches]}."""
    return {f"{Fstar:.4f}": [b for run in runs for b in jobs.stored(run, ORBIT_COLUMNS)]
            for Fstar, runs in large_orbits(paths.rundir("fig11/large"), parameter_set).items()}


def stable_orbits(stored: Sequence[Mapping[str, Any]]) -> Dict[str, List[Tuple[float, float]]]:
    """{"low"|"high": [(V0, V1), ...]}: the V-intervals of stable orbits on
    stored branches of one slice load, by family: a branch is low-frequency
    if its frequency where its amplitude is smallest (its Hopf point) is
    below FAMILY_SPLIT_HZ, whatever the frequency of its stable part."""
    found = {"low": [], "high": []}
    for branch in jobs.loaded(stored):
        V, amplitude = branch["V"], branch["psi_amp"]
        kind = "low" if branch["freq"][numpy.argmin(amplitude)] < FAMILY_SPLIT_HZ else "high"
        # stable orbits of non-zero amplitude
        keep = branches.stable_mask(branch) & (amplitude > ct.COLLAPSED)
        for run in branches.runs_of(keep, overlap=False):
            if keep[run.start]:
                found[kind].append((V[run].min(), V[run].max()))
    return found
