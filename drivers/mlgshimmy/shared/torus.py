"""Torus (TR) points of periodic orbit branches and their curves in
(V, F*): the recipes that Fig. 11 and the torus check
(mlgshimmy.studies.torus_check) share.

  - torus_crossings: where a complex Floquet pair crosses |mu| = 1 along an
    orbit branch (floquet.py says why steps that cross in one go count);
  - speeds: the torus points of a diagram's high-frequency orbits;
  - tr_point: AUTO's TR label at such a crossing (placed by fixed steps
    across it when AUTO does not label it);
  - torus_curve: the TR point continued in (V, F*) (AUTO ISW = 2), its
    start seeded with the critical Floquet eigenfunction (seeded);
  - multiplier_check, monodromy_path: |mu| - 1 from AUTO and from the
    monodromy matrix integrated along the orbit;
  - simulated_rate: the growth of the psi peaks' spread in a simulation,
    which the critical pair's rate ln|mu| / T predicts.
"""
from __future__ import annotations

import math
import os
import tempfile
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy

from mlgshimmy.shared import attractor
from mlgshimmy.shared import branches
from mlgshimmy.shared import runerror
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import floquet
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared.naming import HIGH_HZ
from mlgshimmy.shared import simulator
from mlgshimmy.shared import spectrum

V_MAX = ct.V_MAX
SIM_T = (20.0, 80.0)   # s: fit the log of the peak spread over this span
GIVEN_AS_OPTIONS = ("V", "Fstar", "yfp", "eps_abs", "eps_rel")   # the rest: --param
SPAN = 2.0             # s: one peak-spread sample per SPAN
CURVE_FSTAR = (0.02, 3.5)
CURVE_STEPS = 150      # AUTO steps of a torus curve each way
CURVE_TIME_LIMIT = 120  # s of CPU per direction (the main curve of Fig. 11: ~25 s each)
# least step of a torus curve: where a tongue's edges stop (MX), AUTO halves
# the step down to it, each try a failed Newton solve on the 3 x 10-dimensional
# system (~0.7 s); on Fig. 11's curves no step below 1e-3 ever converged
CURVE_DSMIN = 5e-4
CLOSE_TOL = 0.05       # closes(): a point this many chords from the curve lies on it


def orbit_branch(rundir: str, name: str, values: Mapping[str, float], mesh: Tuple[int, int],
                 dsmax: float) -> Any:
    """The orbits born at the last Hopf point of straight rolling below
    V_MAX (zero freeplay: the only one; with freeplay: H3, whose branch folds
    back at S and then carries the large-amplitude orbits), continued in V."""
    hopfs = [v for v, kind, _ in spectrum.stability_changes("figures", "V", ct.SPEED_SCAN,
                                                                **values)
             if kind == "HB"]
    if not hopfs:
        raise RuntimeError(f"torus: no Hopf point below {V_MAX:g} m/s at {values}")
    hb = ct.hopf_point(rundir, f"{name}_hb", "figures", "V", hopfs[-1], **values)
    return ct.periodic_from(rundir, name, hb, stop={"V": [0.5, V_MAX]}, DS=0.05, DSMAX=dsmax,
                            NMX=3000, NTST=mesh[0], NCOL=mesh[1])


def torus_crossings(rundir: str, name: str) -> List[Dict[str, Any]]:
    """Where the orbit run <name> in rundir has a complex Floquet pair cross
    the unit circle (floquet.torus_crossings of its d-file)."""
    return floquet.torus_crossings(floquet.read(os.path.join(rundir, f"d.{name}")))


def speeds(rundir: str, diagram: Any, min_hz: float = HIGH_HZ) -> List[Tuple[float, int]]:
    """The torus points of a Diagram in V (continuation.speed_diagram) on
    its orbit runs born at a Hopf point of at least min_hz: [(V, +1 loses
    or -1 regains stability)] in branch order, each at AUTO's TR label
    where it has one (labelled_tr), else where |mu| - 1 is interpolated
    to zero."""
    out = []
    for (point, run), name in zip(diagram.parts, diagram.names):
        if 1.0 / point["T"] < min_hz:
            continue
        for c in torus_crossings(rundir, name):
            label = labelled_tr(run, c["value"], c["between"])
            out.append((float(label["V"]) if label else float(c["value"]), c["direction"]))
    return out


def on_branch(bd: Any, v: float, key: str) -> float:
    """A measure of the orbit branch at speed v (the stable large-amplitude
    part: the last pass of the branch through v)."""
    V, y = numpy.asarray(bd[0]["V"]), numpy.asarray(bd[0][key])
    k = numpy.nonzero((V[:-1] - v) * (V[1:] - v) <= 0)[0][-1]
    s = (v - V[k]) / (V[k + 1] - V[k])
    return float(y[k] + s * (y[k + 1] - y[k]))


def predicted_rate(steps: Sequence[Any], bd: Any, v: float) -> float:
    """ln|mu| / T of the critical complex pair at the step nearest v [1/s]."""
    values = numpy.array([s[0] for s in steps])
    g, _ = floquet.critical(steps[int(numpy.argmin(numpy.abs(values - v)))][1])
    return math.log1p(g) * on_branch(bd, v, "freq")


def simulated_rate(values: Mapping[str, float], v: float, psi0: float, span: float = SIM_T,
                   rtol: Optional[float] = None) -> Tuple[float, float, float]:
    """Growth rate [1/s] of the psi peaks' relative spread in a simulation
    from psi0 (log-linear fit over span, one sample per SPAN seconds; rtol:
    the simulator's tolerance, atol 1e-2 of it, default its own)."""
    eps = 0.1 * values["yfp"]
    tolerance = ("--rtol", rtol, "--atol", 1e-2 * rtol) if rtol else ()
    with tempfile.TemporaryDirectory() as tmp:
        csv = os.path.join(tmp, "run.csv")
        simulator.simulate(csv, "--set", "figures", "--V", v, "--Fstar", values["Fstar"],
                           "--yfp", values["yfp"], "--eps-abs", eps, "--eps-rel", 0,
                           "--t-end", span[1], "--psi0", psi0, *tolerance,
                           params={k: repr(v) for k, v in values.items() if k not in GIVEN_AS_OPTIONS})
        data = numpy.loadtxt(csv, delimiter=",", skiprows=1, usecols=(0, 1))
    fit = attractor.spread_trend(data[:, 0], data[:, 1], span[0], span[1], SPAN)
    return fit["rate"], fit["first"], fit["last"]


def labelled_tr(bd: Any, v: float, between: Optional[int] = None) -> Optional[int]:
    """AUTO's TR label of the branch bd within 0.5 m/s of the crossing at
    speed v, or inside (0.5 m/s around) its step `between`; None if none."""
    labelled = [p for p in bd("TR") if abs(p["V"] - v) < 0.5]
    if not labelled and between:
        # AUTO located it inside the crossing's step `between`, farther
        # than 0.5 m/s from the interpolated v (long steps, curved |mu|)
        labelled = [p for p in bd("TR") if min(between) - 0.5 <= p["V"] <= max(between) + 0.5]
    return labelled[0] if labelled else None


def tr_point(rundir: str, name: str, bd: Any, v: float, slope: float,
             between: Optional[Tuple[float, float]] = None) -> Any:
    """AUTO's TR label near speed v, a crossing of the branch bd (which ends
    at V_MAX, or in MX at a side-stay geometry): the branch's own label if
    it has one within 0.5 m/s (or inside the crossing's step, `between`);
    else back from the end to v + 3h, then fixed steps of -2h, one of them
    across, h such that |mu| - 1 changes by 4e-5 or more over a step (AUTO's
    count of stable multipliers, tolerance 1e-5, then changes with the
    sign; AUTO tests nothing on the first step after a restart).  Where
    AUTO still does not label it, h is doubled (twice)."""
    labelled = labelled_tr(bd, v, between)
    if labelled:
        return labelled
    # the branch's end, past every crossing on it: V = V_MAX (UZ, EP) or,
    # where it stopped short, its MX point (AUTO's last converged orbit);
    # a labelled orbit before the end can lie before the crossing, and the
    # run back from it never reaches v
    end = bd()[-1]
    for factor in (1, 2, 4):
        h = factor * max(2e-5 / abs(slope), 0.05)
        # back along a branch already computed: a run that does not reach v
        # started on the wrong side of a fold, and no retry rung changes that
        back = ct.run(rundir, f"{name}_back{factor}", "periodic", data=end,
                      ICP=["V", 11] + mlgmodel.MEASURES, DS=-1.0, DSMAX=5.0,
                      UZSTOP={"V": v + 3 * h}, allow_mx=True)
        if not back("UZ"):
            last = back()[-1]
            raise runerror.RunError(f"run {name}_back{factor}: ends ({last['TY name']}) at "
                                    f"V = {last['V']:.6g}, short of V = {v + 3 * h:.6g}")
        cross = ct.run(rundir, f"{name}_cross{factor}", "periodic", data=back("UZ")[-1],
                       ICP=["V", 11] + mlgmodel.MEASURES, DS=-2 * h, DSMIN=1e-4, DSMAX=2 * h,
                       IADS=0, NMX=4)
        if cross("TR"):
            return cross("TR")[0]
    raise runerror.RunError(f"run {name}: AUTO labelled no TR near V = {v:.3f} "
                            f"(steps up to {4 * h:.3g} m/s across it)")


def windows(found: Sequence[dict]) -> List[Tuple[dict, dict]]:
    """The windows of instability among the crossings found (in branch
    order): [(loses, regains)], consecutive."""
    return [(a, b) for a, b in zip(found, found[1:]) if a["direction"] > 0 > b["direction"]]


def multiplier_check(rundir: str, name: str, tr: Any, v: float,
                     mesh: Tuple[int, int]) -> Dict[str, Any]:
    """|mu| - 1 of the critical pair at speed v on the orbit continued from
    the TR label tr on mesh (NTST, NCOL), two ways: AUTO's Floquet
    multipliers and the eigenvalues of the monodromy matrix integrated along
    the orbit (monodromy_path); each with its error on the trivial
    multiplier 1, a measure of its accuracy."""
    sign = 1.0 if v > tr["V"] else -1.0
    bd = ct.run(rundir, name, "periodic", data=tr, ICP=["V", 11] + mlgmodel.MEASURES, NTST=mesh[0],
                NCOL=mesh[1], DS=0.05 * sign, DSMAX=0.2, NMX=1000, UZR={"V": [v]},
                UZSTOP={"V": [v + 0.05 * sign]}, expect=["UZ"])
    steps = floquet.read(os.path.join(rundir, f"d.{name}"))
    mults = min((s for s in steps if s[0] is not None), key=lambda s: abs(s[0] - v))[1]
    _, phi = monodromy_path(bd("UZ")[0])
    mu = numpy.linalg.eigvals(phi[-1])
    return {"NTST": mesh[0], "NCOL": mesh[1], "auto": floquet.critical(mults)[0],
            "auto_trivial_error": float(numpy.min(numpy.abs(mults - 1))),
            "monodromy": floquet.critical(mu)[0],
            "monodromy_trivial_error": float(numpy.min(numpy.abs(mu - 1)))}


SUBSTEPS = 8           # RK4 steps per stored mesh interval of the orbit (monodromy)


def torus_icp() -> List[Union[str, int]]:
    """ICP of a torus curve in (V, F*): the period, the torus angle PAR(12), the measures."""
    return ["V", "Fstar", 11, 12] + mlgmodel.MEASURES


def monodromy_path(sol: Any,
                   parameter_set: str = "figures") -> Tuple[numpy.ndarray, List[numpy.ndarray]]:
    """The fundamental matrix Phi(t) of the orbit `sol` (an AUTO solution,
    time scaled to [0, 1]) at its stored points: dPhi/dt = T J(u(t)) Phi,
    Phi(0) = I, by RK4 on u interpolated linearly between the points (the
    mesh is adapted, so the freeplay's sharp corners are resolved)."""
    names = [n for n in mlgmodel.PARNAMES if n and n != mlgmodel.CONSTANTS_FILE]
    if sol.PAR[mlgmodel.CONSTANTS_FILE]:
        raise ValueError("torus: an orbit run with changed constants (PAR(15) != 0) is not "
                         "supported by monodromy_path")
    model = mlgmodel.Model(parameter_set, **{n: sol.PAR[n] for n in names})
    t = numpy.asarray(sol["t"])
    U = numpy.array([sol[n] for n in mlgmodel.UNAMES]).T
    period = sol.PAR["T"]

    def rate(u):
        return period * numpy.array(model.jacobian(list(u)))
    phi = numpy.eye(len(mlgmodel.UNAMES))
    out = [phi]
    for k in range(len(t) - 1):
        h = (t[k + 1] - t[k]) / SUBSTEPS
        du = (U[k + 1] - U[k]) / SUBSTEPS
        for j in range(SUBSTEPS):
            a, b, c = rate(U[k] + j * du), rate(U[k] + (j + 0.5) * du), rate(U[k] + (j + 1) * du)
            k1 = a @ phi
            k2 = b @ (phi + 0.5 * h * k1)
            k3 = b @ (phi + 0.5 * h * k2)
            k4 = c @ (phi + h * k3)
            phi = phi + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        out.append(phi)
    return t, out


ANGLE_TOL = 0.05       # rad: the seeded pair's argument against the TR label's angle


def seeded(start: Any, angle: float, parameter_set: str = "figures") -> Any:
    """The first point of a torus curve with the critical Floquet
    eigenfunction filled in.  AUTO's start from a TR label (periodic.f90,
    STPNTR) guesses the eigenfunction as 1e-4 (cos, sin)(theta t) in every
    component; on the freeplay orbits its Newton solve then converges to
    the trivial v = 0 (norm PAR(NPAR) ~ 1e-20) and the continuation after it
    is singular (MX at the first step, any DS).  Here v1 + i v2 = Phi(t) w0,
    w0 the eigenvector of the monodromy matrix whose multiplier is nearest
    exp(i angle) (BCTR: v(1) = exp(i theta) v(0)), scaled to norm 1
    (ICTR: the integral of |v|^2 equals PAR(NPAR)).  angle: the crossing
    pair's argument at the TR label (AUTO sets PAR(12) there from the
    multiplier nearest the unit circle, TPSPBV; the start run's own PAR(12)
    drifts in its degenerate solve), so a tongue's point gets its own pair,
    not the main curve's; a pair whose argument is off it by more than
    ANGLE_TOL is an error."""
    t, phi = monodromy_path(start, parameter_set)
    mu, vectors = numpy.linalg.eig(phi[-1])
    k = int(numpy.argmin(numpy.abs(mu - numpy.exp(1j * angle))))
    if abs(abs(numpy.angle(mu[k])) - abs(angle)) > ANGLE_TOL:
        raise ValueError(f"torus: no Floquet pair at angle {angle:.4f} rad (nearest: "
                         f"{numpy.angle(mu[k]):.4f} rad, |mu| = {abs(mu[k]):.6f})")
    w = numpy.array([p @ vectors[:, k] for p in phi])
    w /= math.sqrt(numpy.trapz(numpy.sum(numpy.abs(w) ** 2, axis=1), t))
    n = len(mlgmodel.UNAMES)
    for i in range(n):
        start[f"U({n + i + 1})"] = w[:, i].real
        start[f"U({2 * n + i + 1})"] = w[:, i].imag
    start.PAR["PAR(12)"] = float(abs(numpy.angle(mu[k])))
    start.PAR[start.PAR.coordnames[-1]] = 1.0          # PAR(NPAR): the norm
    return start


def closes(V: Sequence[float], Fstar: Sequence[float]) -> bool:
    """Whether a curve in (V, F*), once away from its start, passes back
    through its first two points (within CLOSE_TOL of a step's chord, in
    V/V_MAX and F*/F* span): a closed curve, which the other direction
    would only trace again."""
    x = numpy.c_[numpy.asarray(V) / V_MAX, numpy.asarray(Fstar) / (CURVE_FSTAR[1] - CURVE_FSTAR[0])]
    if len(x) < 4:
        return False
    lengths = numpy.linalg.norm(numpy.diff(x, axis=0), axis=1)
    to_first, to_second = (branches.chord_distances(x, x[i]) for i in (0, 1))

    def near(to, k):   # within CLOSE_TOL chords of the chord k -> k + 1
        return to[k] <= CLOSE_TOL * lengths[k]
    away = False
    for k in range(2, len(x) - 1):
        away = away or numpy.linalg.norm(x[k] - x[0]) > 5 * lengths[k]
        if away and near(to_first, k) and any(near(to_second, j)
                                              for j in range(k, min(k + 3, len(x) - 1))):
            return True
    return False


def torus_curve(rundir: str, name: str, tr: Any, parameter_set: str = "figures",
                steps: int = CURVE_STEPS, ntst: Optional[int] = None) -> Tuple[Any, ...]:
    """The TR point continued in (V, F*) both ways, within CURVE_FSTAR and
    V <= V_MAX: the runs (<name>_up, <name>_down), or (<name>_up,) alone
    where that run closes (closes); a direction whose run fails is left out
    and reported (RunError if both fail); ntst: their mesh, if not
    the orbit's (a finer one: see fig11.TONGUE_EDGES).  AUTO's first ISW = 2
    run from a TR label only builds the extended system's data (its last
    point, EP, or MX where its degenerate Newton solve fails: the orbit is
    kept, the eigenfunction is replaced); the curve is continued from there
    with the eigenfunction filled in (seeded).  Its angle theta (PAR(12))
    may pass pi: past it the pair is on the unit circle at 2 pi - theta
    (the orbits' multipliers, docs/reproduction.md), so the curve goes on."""
    first = ct.run(rundir, f"{name}_start", "periodic", data=tr, ISW=2, ICP=torus_icp(),
                   DS=0.001, DSMAX=0.01, NMX=2, allow_mx=True)
    seed = seeded(first()[-1], tr.PAR["PAR(12)"], parameter_set)
    stop = {"Fstar": list(CURVE_FSTAR), "V": [0.5, V_MAX]}
    mesh = {"NTST": ntst} if ntst else {}
    runs, failed = [], []
    for sign, part in ((1, "up"), (-1, "down")):
        try:
            run = ct.run(rundir, f"{name}_{part}", "periodic", data=seed, ISW=2,
                         ICP=torus_icp(), DS=sign * 0.05, DSMIN=CURVE_DSMIN, DSMAX=5.0,
                         NMX=steps, UZSTOP=stop, allow_mx=True, time_limit=CURVE_TIME_LIMIT,
                         **mesh)
        except runerror.RunError as exc:
            failed.append(exc)
            continue
        runs.append(run)
        if part == "up" and closes(run[0]["V"], run[0]["Fstar"]):
            print(f"torus: {name} is a closed curve in (V, F*): not run the other way",
                  flush=True)
            break
    if not runs:
        raise failed[0]
    for exc in failed:   # the other direction is kept and drawn
        print(f"REPORTED: torus curve {name}: one direction left out: {exc.brief}", flush=True)
    return tuple(runs)


def curve_arrays(runs: Sequence[Any]) -> List[Dict[str, Any]]:
    """A torus curve's runs as arrays for result.json: [{"V", "Fstar",
    "freq", "angle", "ends"}] per run."""
    return [{"V": list(map(float, bd[0]["V"])), "Fstar": list(map(float, bd[0]["Fstar"])),
             "freq": list(map(float, bd[0]["freq"])), "angle": list(map(float, bd[0]["PAR(12)"])),
             "ends": [p["TY name"] for p in bd() if p["TY name"] in ("EP", "MX", "UZ")]}
            for bd in runs]


