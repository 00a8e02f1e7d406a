"""AUTO recipes on the MLG model: runs started at given parameters,
straight rolling, Hopf points (scanned by `spectrum`, located by AUTO),
periodic orbits followed across Hopf points with one collapse rule, and
curves of Hopf points and folds of cycles.

    start = Start("figures", Fstar=1.0)              # parameters + equilibrium
    eq = equilibria(rundir, "eq_F1", start)          # straight rolling in V
    po = periodic_from(rundir, "po_F1", eq("HB1"), stop={"V": 600})
    d = speed_diagram(rundir, "figures", {"Fstar": 1.0, "yfp": 1.0, "eps_rel": 0.1})
"""
from __future__ import annotations

import functools
import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy
from numpy.typing import ArrayLike

from mlgshimmy.shared import autoglue, autosession, diagrams, rundirs, runerror
from mlgshimmy.shared import branches
from mlgshimmy.shared import domain
from mlgshimmy.shared import gear
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import naming
from mlgshimmy.shared import paths
from mlgshimmy.shared import rolling
from mlgshimmy.shared import spectrum

MODEL = os.path.join(paths.BUILD, "models", "mlg")
# constants/c.mlg with the names of the states and PAR slots, built by make
# from the library's tables (models/models.mk)
CONSTANTS = os.path.join(paths.BUILD, "models", "c.mlg")
RUN_CONSTANTS = os.path.join(paths.ROOT, "constants", "runs")
# m/s: the paper's speeds (V = 0 is degenerate: the tyre states are undetermined)
V_MIN, V_MAX = 0.5, 600.0
SPEED_SCAN = numpy.linspace(V_MIN, V_MAX, 3000)   # the eigenvalue scan of straight rolling in V
COLLAPSED = 1e-8      # rad: an orbit with a smaller psi amplitude is straight rolling
SHRUNK = 0.3          # an orbit below this part of its branch's largest amplitude has shrunk
SAME_FREQUENCY = 0.05  # relative: an orbit this close to a Hopf frequency may collapse there
COLLAPSING = 0.01     # a least amplitude below this part of the branch's largest: collapsed
# relative: a Hopf point this near where orbits shrink onto straight rolling
# is the one they join (AUTO's branch point lies up to 1 m/s from it: I_psi
# x0.9, at 29.03 m/s for H2 at 27.97 m/s)
JOIN_WINDOW = 0.05
FIRST_STEP_FLOOR = 1e-5   # first_step cuts a jumping first step's DS down to this
FIRST_STEP_TRIAL = 2      # steps of the run that tries a first step (first_step)
VERTICAL = 0.1   # of DSMAX: a branch that has moved less along its parameter leaves it vertically
CORNER, CORNER_STEPS = 0.01, 300   # the steps (of DS, DSMAX) and their number at such a corner


class Start:
    """Parameters of a run and the straight-rolling equilibrium there,
    validated by the c/ library before AUTO starts; near: a state
    ({name: value}) to solve from instead (Newton, rolling.solve), for the
    equilibrium near it where there are several (side-stay angles)."""

    def __init__(self, parameter_set: str = "figures", near: Optional[dict] = None,
                 **values: float):
        self.model = mlgmodel.Model(parameter_set, **values)
        self.model.check()
        if near is None:
            self.U = self.model.equilibrium()
        else:
            u = rolling.solve(self.model, [near[n] for n in mlgmodel.UNAMES])
            if u is None:
                raise RuntimeError(f"no equilibrium found by Newton near the state {near} "
                                   f"at {values}")
            self.U = dict(zip(mlgmodel.UNAMES, u))
        self.PAR = self.model.par()
        mlgmodel.register_constants(self.model)


def ends_branch(point: Any, parameter: str) -> bool:
    """An MX point that is an end, not a failure: a wheel lifts off there
    (the model's domain ends), or the orbits approach a connection of
    saddles (their period grows without bound: domain.stop_reason), or a
    periodic orbit has
    shrunk onto straight rolling at a Hopf point (zero amplitude, and a pair
    of straight rolling's eigenvalues crosses the axis within JOIN_WINDOW of
    it along `parameter`: the branch joins that Hopf point, where AUTO finds
    a branch point and cannot go on).  Zero amplitude elsewhere is AUTO
    landing on the equilibrium: a failure."""
    if point["psi_amp"] <= COLLAPSED and point["freq"] > 0.0:   # an orbit, not an equilibrium
        model = domain.solution_model(point)
        value = point[parameter]
        width = JOIN_WINDOW * max(1.0, abs(value))

        def unstable_pairs(at):
            lam = spectrum.eigenvalues(model.set(**{parameter: at}))
            return int(numpy.sum((lam.real > 0) & (numpy.abs(lam.imag) > 1e-9)))
        return unstable_pairs(value - width) != unstable_pairs(value + width)
    return domain.stop_reason(point) != "numerical"


def run(rundir: str, name: str, kind: Optional[str] = None, overlay: Optional[str] = None,
        model: str = MODEL, **kw: Any) -> Any:
    """autoglue.run on the MLG model (or another equations file of models/:
    model, its executable's path without .exe): the base constants, then the run-type
    file constants/runs/c.<kind> if given, then the overlay file
    constants/runs/c.<overlay> if given, then the keyword overrides.  A run
    that does not converge (MX, or the model stops it at a non-finite
    solution) where that is an error goes up the retry ladder
    (with_ladder), its time_limit scaled by each rung's cost; with
    allow_mx=True it is kept as it ends; with allow_mx=Ends(...) an MX
    that the Ends explains is kept and any other goes up the ladder
    (EDGE: the ends of the model's domain and of the orbits)."""
    if not os.path.exists(CONSTANTS):
        raise runerror.RunError(f"{CONSTANTS} is missing: run `make -C {paths.ROOT} "
                                f"{os.path.relpath(CONSTANTS, paths.ROOT)}` (the make target "
                                "of a figure or study builds it too)")
    files = [CONSTANTS] + [os.path.join(RUN_CONSTANTS, f"c.{k}") for k in (kind, overlay) if k]
    rundir = rundirs.claim(rundir)            # emptied on first use: claim, then write
    mlgmodel.write_constants_files(rundir)    # constants set from Python (PAR(15))
    ends = kw["allow_mx"] if isinstance(kw.get("allow_mx"), Ends) else None

    def own():
        merged = autoglue.read_constants(files)
        return {key: kw.get(key, merged[key]) for key in STEP_CONSTANTS}

    def options(allow_mx, rung):
        """The run's keywords with a rung's constants, its CPU guard scaled
        by the rung's cost."""
        out = {**kw, "allow_mx": allow_mx, **rung}
        if rung and kw.get("time_limit"):
            out["time_limit"] = kw["time_limit"] * rung_cost(own(), rung)
        return out

    def attempt(mx, **rung):
        bd = autoglue.run(rundir, name, constants=files, e=model,
                          **options(mx or ends is not None, rung))
        stops = [p for p in bd("MX") if not ends.explains(p, kw["ICP"][0])] if ends else []
        if stops and not mx:
            error = runerror.RunError(
                f"run {name} in {rundir}: no convergence (MX) at {kw['ICP'][0]} = "
                f"{stops[0][kw['ICP'][0]]:.6g}, {ends.unexplained}", kind=runerror.MX)
            error.diagram, error.stop = bd, stops[0]
            raise error
        if ends:
            nmx = kw.get("NMX", autoglue.read_constants(files)["NMX"])
            for branch in bd:
                if len(branch) >= nmx and branch[-1]["TY name"] == "EP":
                    print(f"REPORTED: run {name} in {rundir} stops at its step budget (NMX = "
                          f"{nmx}) at " + ", ".join(f"{p} = {branch[-1][p]:.6g}"
                                                     for p in kw["ICP"]
                                                     if p in mlgmodel.PARNAMES)
                          + "; kept up to there", flush=True)
        return bd

    def passes(error, **rung):
        """Whether the rung's constants get past the stop of the run that
        raised `error` (AUTO's last converged point there), PROBE_STEPS
        steps from it (run <name>_probe)."""
        try:
            bd = autoglue.run(rundir, f"{name}_probe", constants=files, e=model,
                              **{**options(True, rung), "data": error.stop, "NMX": PROBE_STEPS})
        except runerror.RunError:
            return False
        return all(ends.explains(p, kw["ICP"][0]) for p in bd("MX"))   # an end it explains passes
    probe = passes if ends is not None and ends.probe else None
    return with_ladder(attempt, own, f"run {name}", keep_mx=kw.get("allow_mx") is True,
                       keep_last=ends is not None and ends.keep, passes=probe)


def reported(what: str, make: Callable[[], Any],
             errors: Tuple[type, ...] = (runerror.RunError,)) -> Any:
    """make() (a run or a curve), or None with one REPORTED line naming
    `what` and why when it fails: a figure draws the curves it has and says
    which it left out."""
    try:
        return make()
    except errors as exc:
        print(f"REPORTED: {what} left out: {getattr(exc, 'brief', exc)}", flush=True)
        return None


def load(rundir: str, name: str) -> Any:
    """A run saved by run() (b./s./d.<name> in rundir) read back as a
    diagram, checked as run() checks it (MX allowed: such runs are kept)."""
    files = [os.path.join(rundir, f"{kind}.{name}") for kind in "bsd"]
    missing = [f for f in files if not os.path.exists(f)]
    if missing:
        raise runerror.RunError(f"run {name} in {rundir}: missing {', '.join(missing)}")
    bd = autosession.init().bifDiag.bifDiag(*files)
    try:
        diagrams.check_diagram(bd, f"run {name} in {rundir}")
    except runerror.RunError as exc:
        if exc.kind != runerror.MX:
            raise
    return bd


def equilibria(rundir: str, name: str, start: Start, parameter: str = "V",
               stop: Optional[dict] = None, overlay: Optional[str] = None, **kw: Any) -> Any:
    """Straight rolling continued in `parameter` from `start` (overlay: a
    constants/runs/c.<overlay> on top of c.equilibria)."""
    return run(rundir, name, "equilibria", overlay, PAR=start.PAR, U=start.U,
               ICP=[parameter] + mlgmodel.MEASURES, UZSTOP=stop or {}, **kw)


def periodic_from(rundir: str, name: str, point: Any, parameter: str = "V",
                  stop: Optional[dict] = None, overlay: Optional[str] = None, **kw: Any) -> Any:
    """The periodic orbits born at the Hopf point `point` (or through the
    orbit `point`), continued in `parameter` (overlay as for equilibria)."""
    return run(rundir, name, "periodic", overlay, data=point,
               ICP=[parameter, 11] + mlgmodel.MEASURES,
               UZSTOP=stop or {}, **kw)


def hopf_point(rundir: str, name: str, parameter_set: str, parameter: str, value: float,
               width: Optional[float] = None, state: Optional[Callable[[float], Any]] = None,
               **values: float) -> Any:
    """AUTO's HB solution at the Hopf point near `value` (from a spectrum
    scan): straight rolling continued through a narrow window around it with
    steps small enough for AUTO's Hopf test (state(value): straight rolling
    there, as for spectrum.stability_changes)."""
    width = width or 0.01 * max(abs(value), 1.0)
    start = Start(parameter_set, near=state(value - width) if state else None,
                  **{**values, parameter: value - width})
    bd = equilibria(rundir, name, start, parameter, stop={parameter: value + width},
                    DS=width / 100, DSMAX=width / 100, NMX=1000, expect=["HB"])
    # the HB nearest the scan's: two Hopf points may share the window
    # (rho = -10, mu = 20 deg, Fig. 12: F* = 0.6947 and 0.6996)
    point = min(bd("HB"), key=lambda p: abs(p[parameter] - value))
    if abs(point[parameter] - value) > 1e-4 * max(abs(value), 1.0):
        raise runerror.RunError(f"run {name}: AUTO's HB at {parameter} = {point[parameter]:.6g}, "
                                f"the eigenvalue scan's at {value:.6g}")
    return point


def hopf_points(rundir: str, name: str, parameter_set: str, parameter: str,
                grid: Sequence[float], limit: Optional[int] = None, **values: float) -> list:
    """Every Hopf point of straight rolling along `grid` (at most `limit`,
    from the lowest): scanned by spectrum.hopf_scan, each located by AUTO in
    run <name><k>, k = 1, 2, ..."""
    found = spectrum.hopf_scan(parameter_set, parameter, grid, **values)[:limit]
    return [hopf_point(rundir, f"{name}{k}", parameter_set, parameter, v, **values)
            for k, (v, _) in enumerate(found, 1)]


def follow_orbits(rundir: str, names: Callable[[int], str], start: Any, parameter: str,
                  hopf: Mapping[float, float], gap: Callable[[float], float],
                  bounds: Sequence[float], allow_failed: Any = False, figure: str = "orbits",
                  **kw: Any) -> Tuple[List[Any], Dict[float, bool]]:
    """The periodic orbits from `start` (an HB point or an orbit) continued
    in `parameter` within `bounds`, across the Hopf points of straight
    rolling on the way, `hopf` = {value: frequency in Hz}.

    Each run stops gap(h) either side of every Hopf value h not yet passed.
    The one collapse rule: where a run stops next to h, the branch has
    collapsed onto straight rolling there if its last orbit of non-zero
    amplitude has shrunk (below SHRUNK of the branch's largest amplitude)
    and has h's frequency (within SAME_FREQUENCY); it ends there.  Otherwise
    it only passes h and is continued past it from the stop, as a further
    run.  A run whose orbits reach straight rolling at a Hopf point before
    its end (one passed before: collapse_within) is run again up to there,
    and the branch ends there.  names(n) names the n-th run.  With
    allow_failed a run ending in MX is kept up to the MX and a run that
    fails is reported and the branch ends; with allow_failed=EDGE only an
    MX that ends the branch (run's EDGE) is kept; else RunError.  A step longer
    than 2 DSMAX in the parameter raises RunError (AUTO switched to another
    branch), except on the first step from `start` alone: DS is cut first
    (first_step).  Returns (runs, {h: True if the branch collapsed there})."""
    runs, left, ends, origin = [], dict(hopf), {}, start
    while origin is not None:
        name = names(len(runs))
        stops = list(bounds) + [h + s * gap(h) for h in left for s in (-1, 1)]
        if not runs:
            kw = first_step(rundir, name, start, parameter, stops, figure, kw)
        try:
            orbits = periodic_from(rundir, name, origin, parameter, stop={parameter: stops},
                                   allow_mx=allow_failed, **kw)
        except runerror.RunError as exc:
            if allow_failed is not True:
                raise
            print(f"{figure}: orbits {name} left out: {exc.brief}", flush=True)
            break
        values = numpy.asarray(orbits[0][parameter])
        jump = _leaving_jump(values, kw) if not runs else None
        corner = jump is not None and jump > 0
        if corner:
            # a later step jumped: the orbits leave the Hopf point vertically
            # and turn sharply; AUTO's steps grow past that corner however
            # small DS is (hertz: step 13 with DS = 5e-5), so the corner is
            # its own run with CORNER of the steps, and the branch goes on from its end
            print(f"{figure}: orbits {name}: step {jump + 1} jumped by "
                  f"{abs(values[jump + 1] - values[jump]):.3g} in {parameter}: its corner "
                  f"first, with DSMAX = {CORNER * kw['DSMAX']:.3g}", flush=True)
            orbits = periodic_from(rundir, name, origin, parameter, stop={parameter: stops},
                                   allow_mx=allow_failed,
                                   **{**kw, "DS": CORNER * kw["DS"],
                                      "DSMAX": CORNER * kw["DSMAX"], "NMX": CORNER_STEPS})
            values = numpy.asarray(orbits[0][parameter])
        before = max((numpy.max(r[0]["psi_amp"]) for r in runs), default=0.0)
        inside = collapse_within(orbits[0], parameter, hopf, gap, before)
        if inside is not None:
            # AUTO went on through the Hopf point, back along the same orbits
            # (half a period shifted): the run again, up to the collapse
            index, h = inside
            print(f"{figure}: orbits {name} reach straight rolling at the Hopf point "
                  f"{parameter} = {h:.5g} (point {index + 1}), and AUTO goes on back along "
                  "them: run again up to there", flush=True)
            full = orbits[0]
            orbits = periodic_from(rundir, name, origin, parameter, stop={parameter: stops},
                                   allow_mx=allow_failed, **{**kw, "NMX": index + 1})
            _same_start(orbits[0], full, index, parameter, name)
            left.pop(h, None)
            ends[h] = True
        runs.append(orbits)
        last = orbits[0]
        values = numpy.asarray(last[parameter])
        if _jumps(values, kw).any():
            raise runerror.RunError(f"run {name}: a step jumped by more than {2 * kw['DSMAX']} "
                                    f"in {parameter} (switched to another branch)")
        # the last orbit of non-zero amplitude (an MX run may go on along
        # straight rolling after collapsing onto it)
        amp = numpy.asarray(last["psi_amp"])
        alive = numpy.flatnonzero(amp > COLLAPSED)
        i = alive[-1] if len(alive) else len(amp) - 1
        end, freq = values[i], last["freq"][i]
        largest = max(numpy.max(r[0]["psi_amp"]) for r in runs)
        origin = None
        folds = ", ".join(f"{p[parameter]:.5g}" for p in orbits("LP")) or "none"
        print(f"{figure}: orbits {name} from {parameter} = {last[parameter][0]:.5g}: "
              f"{len(values)} points, ends at {end:.5g}, folds at {folds}", flush=True)
        for h in [] if inside else [h for h in left if abs(end - h) < 2 * gap(h)]:
            del left[h]
            ends[h] = bool(amp[i] < SHRUNK * largest
                           and abs(freq - hopf[h]) <= SAME_FREQUENCY * hopf[h])
            if not ends[h]:
                print(f"{figure}: orbits {name} pass the Hopf point {parameter} = {h:.5g} "
                      f"(amplitude {numpy.degrees(amp[i]):.3g} deg, {freq:.4g} Hz there)",
                      flush=True)
                # a run kept up to an MX short of the stop has no UZ to go on
                # from (the `table` set with the cubic law: MX at 0.614 m/s,
                # 0.02 above H1): the branch ends there, its MX reported
                origin = (orbits("UZ") or [None])[-1]
                if origin is None:
                    print(f"{figure}: orbits {name} stop (MX) short of it: the branch ends "
                          "there", flush=True)
        if corner and inside is None and origin is None and len(values) >= CORNER_STEPS:
            origin = orbits()[-1]     # past the corner: on with the run's own steps
    return runs, ends


# The one retry ladder of a continuation that stops with no convergence (MX):
# each rung changes the run's constants (relative to its own) and the run is
# made again from the same start; the first rung that ends without MX is
# kept.  Smaller steps first (a sharp fold, a switch or a nearly degenerate
# point needs them), then a finer mesh (an orbit whose profile steepens),
# then both, then a much finer mesh (at rho = mu = 10 deg Fig. 11's 42 Hz
# fold curve turns in V at (473.79 m/s, F* = 0.981) only with NTST = 400).
# A run from a Hopf point has no other end to restart from.
LADDER = (("smaller steps", {"DS": 0.1, "DSMIN": 1e-4}),
          ("a finer mesh", {"NTST": 2.0}),
          ("a finer mesh and smaller steps", {"NTST": 2.0, "DS": 0.1, "DSMIN": 1e-4,
                                              "DSMAX": 0.5}),
          ("a five times finer mesh", {"NTST": 5.0}))
STEP_CONSTANTS = ("DS", "DSMIN", "DSMAX", "NTST")


class Ends:
    """run(allow_mx=Ends(explains, unexplained, keep, probe)): an MX point p
    where explains(p, parameter) holds is an end of the branch and kept; any
    other sends the run up the LADDER.  If every rung stops where nothing
    explains it, RunError, or with keep the last rung's run is kept and the
    stop reported (a figure draws what it has and says so).  With probe,
    each rung is first tried from the stop (PROBE_STEPS steps) and run
    from the start only if it gets past it there."""

    def __init__(self, explains, unexplained: str, keep: bool = False, probe: bool = False):
        self.explains, self.unexplained, self.keep = explains, unexplained, keep
        self.probe = probe


# A rung tried from a stop (Ends.probe) gets past it if it makes this many
# steps from there without an MX the Ends does not explain (or ends on the
# run's stops, UZ).  A rung that stops where the run stopped costs a few
# steps instead of the whole branch up to there (at rho = -20, mu = -10 deg
# a fold curve of Fig. 11 needs the five times finer mesh: 81 s on the
# three rungs before it).  The last rung is not probed (with_ladder).
PROBE_STEPS = 10


# an MX kept only where it ends the branch (ends_branch)
EDGE = Ends(ends_branch, "inside the model's domain")


def rung_constants(own: Mapping[str, float], factors: Mapping[str, float]) -> Dict[str, float]:
    """A rung's AUTO constants: each factor times the run's own value
    (own: {constant: value}), NTST as a whole number."""
    out = {}
    for key, factor in factors.items():
        value = factor * own[key]
        out[key] = int(round(value)) if key == "NTST" else value
    return out


def rung_cost(own: Mapping[str, float], rung: Mapping[str, float]) -> float:
    """How many times its own run a rung costs: collocation work grows
    with NTST, the number of steps with 1/DSMAX."""
    return (rung.get("NTST", own["NTST"]) / own["NTST"]) * (own["DSMAX"]
                                                            / rung.get("DSMAX", own["DSMAX"]))


def with_ladder(attempt: Callable[..., Any], own: Callable[[], Mapping[str, float]], what: str,
                keep_mx: bool = False, keep_last: bool = False,
                passes: Optional[Callable[..., bool]] = None) -> Any:
    """attempt(mx, **constants) -> diagram; own() -> the run's own
    STEP_CONSTANTS.  With keep_mx (the caller draws a branch up to an MX
    and reports where it stopped) the run as given, MX allowed.  Else the
    run as given, then up LADDER while it does not converge (RunError
    .unconverged); if every rung fails too, the first RunError, or with
    keep_last the last rung's diagram (the error's .diagram), reported.
    passes(error, **constants): whether a rung gets past the stop of the
    last run that failed (an error with .stop), tried from there; a rung
    that does not is skipped, except the last, which always runs from the
    start (a run from the stop can fail where one from the start passes:
    at rho = mu = 10 deg NTST 400 stops 10 steps from the stop of the
    fold curve at (473.5 m/s, F* = 0.980), and from its start turns there
    in V and goes on to V = 600).  Other errors are raised."""
    if keep_mx:
        return attempt(True)
    try:
        return attempt(False)
    except runerror.RunError as exc:
        if not exc.unconverged:
            raise
        first = exc
    steps = own()
    last = first
    for k, (rung, factors) in enumerate(LADDER):
        constants = rung_constants(steps, factors)
        if passes is not None and getattr(last, "stop", None) is not None \
                and k < len(LADDER) - 1 and not passes(last, **constants):
            print(f"{what}: {rung} stops where the run stopped too (tried from there): "
                  "not run again", flush=True)
            continue
        try:
            bd = attempt(False, **constants)
        except runerror.RunError as exc:
            if not exc.unconverged:
                raise
            last = exc
            continue
        print(f"{what}: no convergence (MX) at first; complete with {rung} "
              f"({', '.join(f'{k} = {v:g}' for k, v in constants.items())})", flush=True)
        return bd
    if keep_last and getattr(last, "diagram", None) is not None:
        print(f"REPORTED: {last.brief} with every rung of the retry ladder; "
              "kept up to there", flush=True)
        return last.diagram
    raise first


def _jumps(values, kw):
    """Where a step of a run moved more than 2 DSMAX in its parameter."""
    if "DSMAX" not in kw or len(values) < 2:
        return numpy.zeros(0, dtype=bool)
    return numpy.abs(numpy.diff(values)) > 2 * kw["DSMAX"]


def first_step(rundir: str, name: str, start: Any, parameter: str, stops: Sequence[float],
               figure: str, kw: Dict[str, Any]) -> Dict[str, Any]:
    """The orbit run's constants kw with DS cut to a tenth (down to
    FIRST_STEP_FLOOR) while the first step from `start` alone jumps
    (_leaving_jump): the Hopf point is nearly degenerate, the orbits grow
    slowly in amplitude along the parameter.  Each DS is tried on a run of
    FIRST_STEP_TRIAL steps, not on the whole branch (at a side-stay geometry a
    slice's branch of 14-50 s was run twice).  A trial that fails leaves
    kw as it is: the run itself then fails the same way, and says so."""
    while abs(kw.get("DS", 0.0)) > FIRST_STEP_FLOOR:
        try:
            trial = periodic_from(rundir, name, start, parameter, stop={parameter: stops},
                                  allow_mx=True, **{**kw, "NMX": FIRST_STEP_TRIAL})
        except runerror.RunError:
            break
        values = numpy.asarray(trial[0][parameter])
        if _leaving_jump(values, kw) != 0:
            break
        kw = {**kw, "DS": 0.1 * kw["DS"]}
        print(f"{figure}: orbits {name}: the first step jumped by "
              f"{abs(values[1] - values[0]):.3g} in {parameter}: DS = {kw['DS']:.3g}",
              flush=True)
    return kw


def _leaving_jump(values, kw):
    """The index of the one step that jumped (_jumps) while the branch had
    not yet moved VERTICAL DSMAX along its parameter from its start, or
    None: the orbits leave the Hopf point nearly vertically and the step cut
    the corner where they turn (the first step, or a later one: the cubic
    law, exactly zero in the gap, leaves H3's orbits vertical, 4e-4 m/s
    over three steps, up to the contact, then a step jumped 11.3 m/s)."""
    jumps = numpy.flatnonzero(_jumps(values, kw))
    if len(jumps) != 1 or numpy.any(numpy.abs(values[:jumps[0] + 1] - values[0])
                                    > VERTICAL * kw["DSMAX"]):
        return None
    return int(jumps[0])


def collapse_within(branch: Any, parameter: str, hopf: Mapping[float, float],
                    gap: Callable[[float], float],
                    largest: float = 0.0) -> Optional[Tuple[int, float]]:
    """(index, h): the first point after the run's start where its orbits
    reach straight rolling at the Hopf point h of `hopf` ({value: frequency
    in Hz}), or None.  There the amplitude has a least value below COLLAPSING
    of the branch's largest (`largest` before this run, or this run's), the
    parameter is within gap(h) of h (the window of follow_orbits' stops) and
    the frequency h's (SAME_FREQUENCY).  AUTO does not stop there but goes on
    through the Hopf point, back along the same orbits: between two Hopf
    points (rho = -10, mu = 20 deg, Fig. 12: F* = 0.700 and 0.876) until
    NMX.  Points of zero amplitude (COLLAPSED: an MX run going on along
    straight rolling) are left to the collapse rule at the run's end.  A
    least value farther than gap(h) from h is not taken: Fig. 14's orbits
    at V = 80 m/s step through the Hopf point y_fp = 0.0705 mm with their
    least amplitude 1.7e-4 mm from it (docs/reproduction.md, Fig. 14)."""
    values = numpy.asarray(branch[parameter])
    amp, freq = numpy.asarray(branch["psi_amp"]), numpy.asarray(branch["freq"])
    for i in range(1, len(amp) - 1):
        if not (COLLAPSED < amp[i] < amp[i - 1] and amp[i] <= amp[i + 1]
                and amp[i] < COLLAPSING * max(largest, numpy.max(amp[:i + 1]))):
            continue
        near = [h for h in hopf if abs(values[i] - h) <= gap(h)
                and abs(freq[i] - hopf[h]) <= SAME_FREQUENCY * hopf[h]]
        if near:
            return i, min(near, key=lambda h: abs(values[i] - h))
    return None


def _same_start(branch, full, index, parameter, name):
    """The run repeated up to `index` must be the first run's points."""
    if len(branch) != index + 1 or \
            abs(branch[parameter][-1] - full[parameter][index]) > 1e-9 * max(1.0, abs(
                full[parameter][index])):
        raise runerror.RunError(f"run {name}: repeated up to point {index + 1}, it ends at "
                                f"{parameter} = {branch[parameter][-1]:.9g} after {len(branch)} "
                                f"points, not at the first run's {full[parameter][index]:.9g}")


class Diagram:
    """Straight rolling along one parameter: its Hopf points hopf =
    [(value, frequency in Hz)] and real-eigenvalue crossings bp (spectrum
    scan), parts = [(AUTO's HB point, periodic run)] of the branches born
    there, names = the names of those runs (for load()) and named = the
    Hopf points named by their mode (name_points(), called on first use: its
    criticality checks simulate, up to minutes at a weak Hopf point, and
    Fig. 11's slices never read them).  Keywords (e.g. yfp, scaling) are
    kept as attributes."""

    def __init__(self, parameter, hopf, bp, parts, names,
                 name_points: Callable[[], List[Dict[str, object]]] = list, **about):
        self.parameter, self.hopf, self.bp, self.parts = parameter, hopf, bp, parts
        self.names, self._name_points = names, name_points
        self.__dict__.update(about)

    @functools.cached_property
    def named(self) -> List[Dict[str, object]]:
        return list(self._name_points())

    def name_of(self, run: Any) -> Optional[str]:
        """The name of one of the diagram's runs."""
        return next(name for (_, r), name in zip(self.parts, self.names) if r is run)

    @property
    def branches(self) -> List[Any]:
        return [run for _, run in self.parts]

    def folds(self) -> List[Tuple[Any, int, float, float]]:
        """[(run, label, value, psi_amp)] of every fold of cycles, except LP
        labels within 0.1% of a Hopf value: AUTO's fold test fires spuriously
        on the first steps from a Hopf point (seen at y_fp = 0.35, 0.5 and
        1 mm)."""
        p = self.parameter
        return [(run, lab, run(lab)[p], run(lab)["psi_amp"])
                for run in self.branches for branch in run
                for _, lab, _ in branches.labelled_points(branch, "LP")
                if all(abs(run(lab)[p] - h) > 1e-3 * abs(h) for h, _ in self.hopf)]


# AUTO constants of the orbit runs of a diagram in V (Figs. 10 and 11)
SPEED_ORBIT_STEPS = {"DS": 0.05, "DSMAX": 1.0, "NMX": 2000}


def geometry_orbit_steps(baseline: bool) -> Dict[str, float]:
    """The orbit runs' constants beyond the paper's ({} at the baseline):
    with side-stay angles the links sit off-centre in the freeplay, and the
    low-frequency orbits fold sharply (four folds between H1 and H2 at
    rho = mu = 10 deg) where they first reach its edge on one side: steps
    down to 1e-9 (AUTO's default DSMIN 1e-5 stops there, MX).  The first
    step is smaller, 0.005: a Hopf point can be nearly degenerate (at
    rho = -10, mu = 20 deg H1's orbits grow by 1e-5 rad over 0.02 m/s; at
    rho = mu = 10 deg, F* = 0.1875 the Hopf point at 111.0 m/s), and a first
    step of 0.05 lands 6.8 and 7.6 m/s along the branch."""
    return {} if baseline else {"DSMIN": 1e-9, "DS": 0.005}


def speed_diagram(rundir: str, parameter_set: str, values: Mapping[str, float],
                  grid: ArrayLike = SPEED_SCAN, parameter: str = "V", tag: str = "",
                  first: int = 1, gap: float = 0.01, allow_failed: Any = False,
                  figure: str = "orbits", about: Optional[Mapping[str, Any]] = None,
                  state: Optional[Callable[[float], Any]] = None, **steps: Any) -> Diagram:
    """The Hopf points of straight rolling along `grid` of `parameter` and
    the periodic orbits born at each, followed across the others
    (follow_orbits) within the grid's range; a Hopf point where an earlier
    branch collapsed starts none (AUTO still locates it).  Runs <tag>hb<k>,
    <tag>po<k>[_<n>], k from
    `first`; steps: AUTO constants of the orbit runs; state(value): straight
    rolling there (spectrum.stability_changes)."""
    changes = spectrum.stability_changes(parameter_set, parameter, grid, state=state, **values)
    hopf = [(v, hz) for v, kind, hz in changes if kind == "HB"]
    bp = [v for v, kind, _ in changes if kind == "BP"]
    parts, names, reached = [], [], set()
    for k, (v, _) in enumerate(hopf, first):
        if v in reached:
            # no branch starts here, but it is stored as a labelled HB (run
            # <tag>hb<k>) like every Hopf point the diagram's numbers give
            try:
                hopf_point(rundir, f"{tag}hb{k}", parameter_set, parameter, v, state=state,
                           **values)
            except runerror.RunError as exc:
                print(f"{figure}: Hopf point {k} left unstored: {exc.brief}", flush=True)
            continue
        point = hopf_point(rundir, f"{tag}hb{k}", parameter_set, parameter, v, state=state,
                           **values)

        def name(n, k=k):
            return f"{tag}po{k}" + (f"_{n}" if n else "")
        runs, ends = follow_orbits(rundir, name, point, parameter,
                                   {h: f for h, f in hopf if h != v}, lambda h: gap,
                                   (grid[0], grid[-1]), allow_failed=allow_failed,
                                   figure=figure, **steps)
        reached |= {h for h, collapsed in ends.items() if collapsed}
        parts += [(point, orbits) for orbits in runs]
        names += [name(n) for n in range(len(runs))]
    return Diagram(parameter, hopf, bp, parts, names,
                   lambda: naming.named_points(hopf, [run for _, run in parts], parameter_set,
                                               parameter, state=state, **values),
                   **(about or {}))


def diagram_from_rest(rundir: str, parameter_set: str, allow_failed: Any = False,
                      figure: str = "fig10", steps: Optional[Mapping[str, Any]] = None,
                      **values: float) -> Tuple[Any, Diagram]:
    """Straight rolling in V from rest (0.5 m/s with side-stay angles:
    gear.start_speed; run eq) to V_MAX and speed_diagram over SPEED_SCAN,
    Fig. 10's recipe: (equilibria, Diagram).  steps: AUTO constants of the
    orbit runs beyond SPEED_ORBIT_STEPS (a finer mesh)."""
    start = Start(parameter_set, V=gear.start_speed(), **values)
    eq = equilibria(rundir, "eq", start, stop={"V": V_MAX})
    # at the paper's geometry a branch may end only at a wheel's lift-off or
    # on straight rolling (EDGE); with side-stay angles any MX is kept
    keep = True if allow_failed or not gear.current().geometry.baseline else EDGE
    return eq, speed_diagram(rundir, parameter_set, values, SPEED_SCAN, allow_failed=keep,
                             figure=figure, **{**SPEED_ORBIT_STEPS,
                                               **geometry_orbit_steps(
                                                   gear.current().geometry.baseline),
                                               **(steps or {})})


def hopf_curve(rundir: str, name: str, point: Any, parameters: Sequence[str] = ("Fstar", "V"),
               stop: Optional[Mapping[str, Sequence[float]]] = None, with_period: bool = False,
               overlay: Optional[str] = None, **kw: Any) -> Any:
    """Continue the Hopf point `point` in two parameters (with_period: the
    period PAR(11) printed too; overlay: constants/runs/c.<overlay> on top
    of c.hopf_curve)."""
    icp = list(parameters) + mlgmodel.MEASURES + ([11] if with_period else [])
    return run(rundir, name, "hopf_curve", overlay, data=point, ICP=icp, UZSTOP=stop or {},
               **kw)


def fold_icp(parameters: Sequence[str]) -> List[Union[str, int]]:
    """ICP of a fold-of-cycles continuation in two parameters: the period
    PAR(11) must come third, or AUTO keeps it fixed (periodic.f90, INITPS:
    the period is free only if ICP(3) = 11 or exactly two parameters are
    listed), and the curve found is one of folds at constant period."""
    return list(parameters) + [11] + mlgmodel.MEASURES


FOLD_START = {"DS": 0.01, "DSMAX": 0.05}


def fold_curve(rundir: str, name: str, point: Any, parameters: Sequence[str] = ("V", "Fstar"),
               stop: Optional[Mapping[str, Sequence[float]]] = None,
               start: Mapping[str, float] = FOLD_START, both_ways: bool = False, **kw: Any) -> Any:
    """Continue the fold of periodic orbits `point` (an LP label of an orbit
    run) in two parameters.  AUTO 0.9.2 first only generates the extended
    system's starting data (5 steps, ending in EP; run <name>_start with the
    constants `start`, and THU if given); the curve is continued from there.
    both_ways: a pair of runs <name>_a, <name>_b, DS as given and reversed."""
    icp = fold_icp(parameters)
    thu = {"THU": kw["THU"]} if "THU" in kw else {}
    first = run(rundir, f"{name}_start", "periodic", data=point, ISW=2, ICP=icp,
                **{**start, **thu})
    if not both_ways:
        return run(rundir, name, "periodic", data=first("EP1"), ISW=2, ICP=icp,
                   UZSTOP=stop or {}, **kw)
    ds = kw.pop("DS")
    return tuple(run(rundir, f"{name}_{d}", "periodic", data=first("EP1"), ISW=2, ICP=icp,
                     DS=sign * ds, UZSTOP=stop or {}, **kw)
                 for d, sign in (("a", 1), ("b", -1)))
