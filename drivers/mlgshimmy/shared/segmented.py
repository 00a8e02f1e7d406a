"""Periodic orbits of the non-smooth freeplay law (14) as segmented
boundary-value problems in AUTO (models/mlg_segmented.c; docs/model.md
9.6): one segment per mode visited, each with its duration as an unknown,
glued by continuity and h = 0 at the switches.

    orbit = simulated(values, 100.0)       # event-located, settled (mlg_simulate)
    runs = follow(rundir, "up", values, orbit, 100.0, stop={"V": 600}, DS=0.5)
    stability(model, runs[0](2))            # the monodromy's multipliers
    grazing(runs[-1]("LP")[-1], orbit["modes"])   # the contacts that graze there
    past = gap_orbits(rundir, "gap", values, 144.545, 144.5441)   # beyond the grazing

The start is an event-located simulation: its last full period gives the
sequence of modes and their durations, and its samples the segments'
profiles.
"""
from __future__ import annotations

import os
import tempfile
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import autoglue, mlgmodel, paths, rundirs, simulator

MODEL = os.path.join(paths.BUILD, "models", "mlg_segmented")
DURATION, MODE = 30, 40       # T_k is PAR(DURATION + k), its mode PAR(MODE + k)
SEG_MAX = 8
GAP, CONTACT_POS, CONTACT_NEG = 0, 1, 2    # enum mlg_freeplay_mode
MODE_NAMES = {GAP: "gap", CONTACT_POS: "contact+", CONTACT_NEG: "contact-"}
# the settled orbit: 16 s from psi = 0.01 rad at CVODE rtol 1e-10 (as
# studies/smoothing), then DENSE s more (at least DENSE_PERIODS periods)
# sampled every 10 us with its switches
TOLERANCES = ("--rtol", 1e-10, "--atol", 1e-12)
SETTLE = ("--t-end", 16, "--dt-out", 1e-3, *TOLERANCES)
DENSE, DENSE_PERIODS = 0.5, 4
SAMPLES = 201       # points of each segment in AUTO's starting data
GRAZED = 1e-4   # s: a fold where a contact lasts less than this is a grazing


def law14(values: Dict[str, float]) -> Dict[str, float]:
    """The model values with eq. (14) as the freeplay law."""
    return {**values, "freeplay_law": mlgmodel.LAWS.index("nonsmooth")}


def durations(n: int) -> List[int]:
    """The PAR numbers of the n segments' durations."""
    if not 2 <= n <= SEG_MAX:
        raise ValueError(f"segments: {n} segments, must be 2 to {SEG_MAX} "
                         "(models/mlg_segmented.c SEG_MAX)")
    return [DURATION + k + 1 for k in range(n)]


def duration_names(n: int) -> Dict[int, str]:
    return {par: f"T{k + 1}" for k, par in enumerate(durations(n))}


def simulated(values: Dict[str, float], V: float, psi0: float = 0.01) -> dict:
    """The settled orbit of eq. (14) at speed V by event-located simulation:
    {"modes", "durations", "states" (one array of rows t, u per segment, t
    from its switch), "psi_amplitude_rad", "frequency_hz" (the simulator's
    summary of its last, densely sampled stretch), "period"}: the segments
    of the last full period (the switch that ends it crossed the same way
    as the one that starts it, the sequence repeating)."""
    params = law14(values)
    with tempfile.TemporaryDirectory() as tmp:
        csv, events = os.path.join(tmp, "orbit.csv"), os.path.join(tmp, "events.csv")
        rough = simulator.simulate(csv, "--set", "figures", "--V", V, "--psi0", psi0, *SETTLE,
                                   params=params)
        settled = numpy.loadtxt(csv, delimiter=",", skiprows=1)[-1, 1:]
        dense = max(DENSE, DENSE_PERIODS / rough["frequency_hz"]) if rough["frequency_hz"] \
            else DENSE
        summary = simulator.simulate(csv, "--set", "figures", "--V", V, *simulator.state_args(
            dict(zip(mlgmodel.UNAMES, settled))), "--t-end", dense, "--dt-out", 1e-5,
            *TOLERANCES, "--events", events, params=params)
        samples = numpy.loadtxt(csv, delimiter=",", skiprows=1)
        crossed = numpy.genfromtxt(events, delimiter=",", skip_header=1, dtype=None,
                                   encoding=None)
    if crossed.size < 4:
        raise RuntimeError(f"segmented: at V = {V:g} m/s the simulation crosses "
                           f"{crossed.size} switches: no orbit that reaches contact")
    rows = [(float(r[0]), str(r[1]), int(r[2]), int(r[3]), numpy.array(list(r)[4:], float))
            for r in numpy.atleast_1d(crossed)]
    period = next((back for back in range(2, min(SEG_MAX, len(rows) // 2) + 1)
                   if all(rows[-1 - j][1:4] == rows[-1 - j - back][1:4]
                          for j in range(back))), None)
    if period is None:
        raise RuntimeError(f"segmented: at V = {V:g} m/s the switches do not repeat within "
                           f"{SEG_MAX} segments: no periodic orbit settled")
    cycle = rows[-1 - period:]
    modes, times, states = [], [], []
    for start_row, end_row in zip(cycle[:-1], cycle[1:]):
        t0, t1 = start_row[0], end_row[0]
        inside = samples[(samples[:, 0] > t0) & (samples[:, 0] < t1)]
        states.append(numpy.vstack([numpy.r_[t0, start_row[4]], inside,
                                    numpy.r_[t1, end_row[4]]]))
        states[-1][:, 0] -= t0
        modes.append(start_row[3])
        times.append(t1 - t0)
    return {"modes": modes, "durations": times, "states": states,
            "psi_amplitude_rad": summary["psi_amplitude_rad"],
            "frequency_hz": summary["frequency_hz"], "period": float(sum(times))}


def start_data(orbit: dict) -> numpy.ndarray:
    """AUTO's starting data (dat): rows s, u_1(s), ..., u_n(s), s in [0, 1],
    each segment's samples interpolated (cubic) to one grid of s."""
    from scipy.interpolate import CubicSpline
    s = numpy.linspace(0.0, 1.0, SAMPLES)
    columns = [s]
    for rows, T in zip(orbit["states"], orbit["durations"]):
        t = rows[:, 0] / T
        keep = numpy.r_[True, numpy.diff(t) > 1e-12]   # the switch may repeat a sample
        columns.append(CubicSpline(t[keep], rows[keep, 1:])(s).T)
    return numpy.vstack(columns).T


def parameters(values: Dict[str, float], orbit: dict, V: float) -> Dict:
    """PAR of the segmented run: the model's, the modes and the durations."""
    model = mlgmodel.Model("figures", **law14(values), V=V)
    mlgmodel.register_constants(model)
    n = len(orbit["modes"])
    par = {**model.par()}
    par.update({par_T: T for par_T, T in zip(durations(n), orbit["durations"])})
    par.update({MODE + k + 1: float(m) for k, m in enumerate(orbit["modes"])})
    return par


def follow(rundir: str, name: str, values: Dict[str, float], orbit: dict, V: float,
           parameter: str = "V", stop: Optional[dict] = None, at: Sequence[float] = (),
           **kw: Any) -> list:
    """The segmented orbits through the simulated `orbit` at speed V,
    continued in `parameter` (its direction: the sign of kw DS), labelled
    (UZ) at the values `at` of the parameter, as a list of runs (diagrams)
    <name>, <name>_1, ...: each run stops at its first fold (LP) or where a
    contact segment's duration reaches zero (a UZ: a grazing, grazing()).
    A fold whose contact segments last (a turning point of the orbits) is
    passed by the next run, started there.  At a grazing the
    boundary-value problem is singular (the orbits that meet h = 0
    anywhere with a contact of duration 0 solve it too), and AUTO may flag
    it as a fold instead: a fold with a contact shorter than GRAZED is a
    grazing too, and ends the branch."""
    rundir = rundirs.claim(rundir)
    dat = os.path.join(rundir, f"{name}.dat")
    numpy.savetxt(dat, start_data(orbit), fmt="%.17e")
    common = _constants(orbit["modes"], parameter, stop, at)
    runs = [ct.run(rundir, name, "segmented", model=MODEL, dat=dat,
                   PAR=parameters(values, orbit, V), **common, **kw)]
    while True:
        end = runs[-1][-1][-1]
        folds = runs[-1]("LP")
        if end["TY name"] != "LP" or not folds or grazing(folds[-1], orbit["modes"]):
            return runs
        runs.append(ct.run(rundir, f"{name}_{len(runs)}", "segmented", model=MODEL,
                           data=folds[-1], **common, **kw))   # DS's sign: on, not back


def resampled(rundir: str, name: str, solution: Any, parameter: str, stop: dict,
              at: Sequence[float], **kw: Any) -> Any:
    """One run (<name>) from the segmented orbit `solution` (an AUTO
    solution; on in its run's direction: kw DS with that run's sign) to
    `stop`, labelled (UZ) at the values `at` of `parameter`: the orbits
    between two saved ones, sampled as finely as `at`."""
    return ct.run(rundir, name, "segmented", model=MODEL, data=solution,
                  **_constants(modes_of(solution), parameter, stop, at), **kw)


def _constants(modes: Sequence[int], parameter: str, stop: Optional[dict],
               at: Sequence[float]) -> dict:
    """The AUTO constants of a segmented run: its dimensions, the durations
    free, UZ at `at`, and its stops (`stop`, a contact's duration at zero,
    the first fold)."""
    n = len(modes)
    parnames = {**dict(autoglue.read_constants(ct.CONSTANTS)["parnames"]), **duration_names(n)}
    T_pars = durations(n)
    return dict(NDIM=mlgmodel.NX * n, NBC=(mlgmodel.NX + 1) * n, parnames=parnames,
                ICP=[parameter] + T_pars + mlgmodel.MEASURES, UZR={parameter: list(at)},
                UZSTOP={**(stop or {}), **{p: 0.0 for p, m in zip(T_pars, modes) if m != GAP}},
                STOP=["LP1"])


def grazing(solution: Any, modes: Sequence[int]) -> List[int]:
    """The (1-based) contact segments of a solution whose duration is zero
    (below GRAZED): both, at the grazing of a symmetric orbit."""
    return [k + 1 for k, m in enumerate(modes) if m != GAP and solution[f"T{k + 1}"] < GRAZED]


def gap_orbits(rundir: str, name: str, values: Dict[str, float], hopf: float,
               stop: float, **kw: Any) -> Any:
    """Past a grazing where every contact segment's duration reaches zero:
    the orbits of the sequence without them, the gap mode alone.  Eq. (14)
    is smooth in the gap and the library's field by state is the gap
    mode's there, so they are the standard model's periodic orbits (IPS =
    2), born at straight rolling's Hopf point near `hopf` [m/s] and
    continued to the speed `stop`, short of the grazing (where they meet
    the segmented branch; beyond it the library's field by state has
    contact): run <name> (the Hopf point's <name>_hb), labelled (UZ) at
    kw's UZR.  Their stability is the gap mode's monodromy (stability: one
    segment)."""
    law = law14(values)
    point = ct.hopf_point(rundir, f"{name}_hb", "figures", "V", hopf, **law)
    return ct.periodic_from(rundir, name, point, "V", stop={"V": stop}, **kw)


def one_period(values: Dict[str, float], solution: Any) -> dict:
    """An orbit of the standard model (an AUTO solution, IPS = 2) by the
    event-located simulation over one period T from its first point:
    {"switches": the switches crossed, "psi_amplitude_rad": half the
    peak-to-peak of psi over [0, T], "closes": |psi(T) - psi(0)| over that
    amplitude}: an orbit of eq. (14) returns, whether stable or not."""
    u = numpy.array(solution.coordarray)
    start = dict(zip(mlgmodel.UNAMES, u[:, 0]))
    T = float(solution.PAR[10])                    # PAR(11), the period; PAR is 0-based here
    with tempfile.TemporaryDirectory() as tmp:
        csv, events = os.path.join(tmp, "orbit.csv"), os.path.join(tmp, "events.csv")
        simulator.simulate(csv, "--set", "figures", "--V", solution["V"],
                           *simulator.state_args(start), "--t-end", T, "--dt-out", T / 20000,
                           *TOLERANCES, "--events", events, params=law14(values))
        psi = numpy.loadtxt(csv, delimiter=",", skiprows=1)[:, 1]
        with open(events) as f:
            switches = sum(1 for _ in f) - 1      # a row per switch below the header
    half = 0.5 * float(psi.max() - psi.min())
    return {"switches": switches, "psi_amplitude_rad": half,
            "closes": abs(psi[-1] - psi[0]) / half}


def amplitude(solution: Any, state: str = "psi") -> float:
    """Half the peak-to-peak of a state over a segmented orbit (an AUTO
    solution), each segment's extremes from a cubic spline through its
    collocation points (AUTO's own measure takes the mesh points alone)."""
    from scipy.interpolate import CubicSpline
    t = numpy.array(solution.indepvararray)
    u = numpy.array(solution.coordarray)
    fine = numpy.linspace(0.0, 1.0, 50 * len(t))
    i = mlgmodel.UNAMES.index(state)
    values = numpy.concatenate([CubicSpline(t, u[mlgmodel.NX * k + i])(fine)
                                for k in range(solution["NDIM"] // mlgmodel.NX)])
    return 0.5 * float(values.max() - values.min())


def period(solution: Any) -> float:
    """The sum of a segmented orbit's durations [s]."""
    return float(sum(T for _, T in segments_of(solution)))


def modes_of(solution: Any) -> List[int]:
    """The modes of an AUTO solution's segments."""
    n = solution["NDIM"] // mlgmodel.NX
    return [int(solution.PAR[MODE + k]) for k in range(n)]    # PAR is 0-based here


def segments_of(solution: Any) -> List[Tuple[int, float]]:
    """[(mode, duration)] of an AUTO solution's segments: a segmented orbit's
    (NDIM = 10 n, n >= 2), or a gap orbit of the standard model (NDIM = 10,
    gap_orbits) as one segment in the gap for its period PAR(11)."""
    if solution["NDIM"] == mlgmodel.NX:
        return [(GAP, float(solution.PAR[10]))]
    return [(m, float(solution[f"T{k + 1}"])) for k, m in enumerate(modes_of(solution))]


def monodromy(model: "mlgmodel.Model", solution: Any) -> numpy.ndarray:
    """The monodromy matrix of a segmented orbit (an AUTO solution; or a gap
    orbit, segments_of): the
    product of its segments' (eq. (14) is continuous across h = 0, so the
    saltation matrices are the identity), each the variational equation
    Phi' = T_k J_k(u_k(s)) Phi integrated by RK4 on the collocation points
    (NCOL = 4 equally spaced in each mesh interval: two steps each)."""
    t = numpy.array(solution.indepvararray)
    u = numpy.array(solution.coordarray)
    ncol = solution["NCOL"]
    if ncol % 2:
        raise ValueError(f"monodromy: NCOL = {ncol} must be even (RK4 on its points)")
    total = numpy.eye(mlgmodel.NX)
    for k, (mode, T) in enumerate(segments_of(solution)):
        rows = u[mlgmodel.NX * k:mlgmodel.NX * (k + 1)]
        J = [T * model.jacobian_in_mode(rows[:, j], mode)[1] for j in range(len(t))]
        phi = numpy.eye(mlgmodel.NX)
        for a in range(0, len(t) - 1, 2):
            h = t[a + 2] - t[a]
            k1 = J[a] @ phi
            k2 = J[a + 1] @ (phi + 0.5 * h * k1)
            k3 = J[a + 1] @ (phi + 0.5 * h * k2)
            k4 = J[a + 2] @ (phi + h * k3)
            phi = phi + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
        total = phi @ total
    return total


def stability(model: "mlgmodel.Model", solution: Any) -> dict:
    """{"multipliers", "trivial" (the one nearest 1), "largest" (|mu| of
    the others), "stable"} of a segmented orbit."""
    mu = numpy.linalg.eigvals(monodromy(model, solution))
    trivial = int(numpy.argmin(abs(mu - 1.0)))
    others = numpy.delete(mu, trivial)
    largest = float(max(abs(others)))
    return {"multipliers": mu, "trivial": complex(mu[trivial]), "largest": largest,
            "stable": largest < 1.0}
