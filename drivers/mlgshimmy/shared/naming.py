"""Hopf points of straight rolling named by what they are, the same in
every figure, table and regression, never by the order they were found in.

A Hopf point's mode is its frequency band (below HIGH_HZ: the low-frequency
pair of the paper's H1 and H2; above: the high-frequency pair of H3), the
degree of freedom that dominates its eigenvector, and the way it crosses
(straight rolling loses or regains stability as the parameter grows).  The
paper's names then follow from the mode (Fig. 10, section IV.B):
- H1: the low-frequency pair loses stability (the first such crossing);
- H2: the low-frequency pair regains stability (the first after H1);
- H3: the high-frequency pair loses stability (the first such crossing).
Any other Hopf point is named by its band and its rank in that band
(Hlf3: the third low-frequency one; Hhf2: the second high-frequency one),
so a point that no longer exists at a changed gear is reported as
vanished instead of lending its name to another.

Criticality from the sign of the first Lyapunov coefficient l1
(shared.lyapunov: supercritical where l1 < 0), checked three ways
(verdicts): against the orbit branch at the point (criticality:
supercritical where the orbits lie on the side where the crossing mode
is unstable and are stable there, subcritical where they lie on the other
side and are unstable; the paper's H3: its orbits run down in V towards
the fold S, while straight rolling is stable below H3), and, where the
two disagree, no branch tells or |l1| is small (weak), against short
simulations on each side (simulated).  Where they disagree, the
description says so.
"""
from __future__ import annotations

from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

import numpy
from numpy.typing import ArrayLike

from mlgshimmy.shared import branches, lyapunov, mlgmodel, simulator, spectrum

HIGH_HZ = 8.0   # Hz: between the paper's low (1.7-3.3 Hz) and high (13 Hz) pairs
DEGREES_OF_FREEDOM = {"psi": "torsional", "delta": "lateral", "beta": "longitudinal"}
NEAR = 0.05     # relative: orbit points this close to a Hopf value tell its side
ZERO_AMPLITUDE = 1e-8   # rad: below, an "orbit" is straight rolling (continuation.COLLAPSED)
# Simulations (simulated): at the distance d from the Hopf point where the
# pair's real part is RATE omega (at most SPAN of the value, and half the
# distance to the next Hopf point), on each side, each run lasting
# SETTLE / |real part|.  On the unstable side from straight rolling moved
# by PSI0 in psi: the motion settles on the attractor there (a small orbit
# may lie below PSI0); on the stable side from straight
# rolling moved by that attractor's amplitude: it decays (below DECAYED of
# it) if no orbit surrounds straight rolling there (supercritical), and
# persists (above PERSISTS) on the orbits that do (subcritical: the
# unstable ones born at the point fold back into stable ones).
RATE = 0.02
SPAN = 0.1
SETTLE = 12.0
PSI0 = 1e-6            # rad: a push, small beside the orbits near the Hopf points
LEFT = 1e-3            # of PSI0: an end amplitude below is straight rolling, no attractor
# Where f has a kink on the critical plane (lyapunov.kink_coefficient: the
# oleo's |eta'| eta' when the mode moves eta', at side-stay angles) the
# quadratic a2 decides up to the psi amplitude where its r^2 term meets the
# cubic one, 2 |q_psi| |Re a2| / (omega |l1|); past SEEN, an amplitude both
# AUTO's first orbits and the simulations' push reach, a2 decides, else l1.
SEEN = PSI0
# below, a2 is the rounding of f (the modes of the symmetric gear do not move
# eta': a2 ~ 1e-17, kink_psi ~ 1e-20 rad at H1-H3) and is not written
KINK_NOISE = 1e-12   # rad
DECAYED, PERSISTS = 0.1, 0.5
# |l1| is weak where the normal form's orbit at real part 0.01 omega,
# 2 |q_psi| sqrt(0.01 / |l1|), exceeds the angle over which the field stays
# cubic: the freeplay angle y_fp / r_tlk, or WEAK_ZERO_FREEPLAY without freeplay.
WEAK_ZERO_FREEPLAY = 0.05   # rad: simulator.STARTS["shimmy"], a large swing


def mode(parameter_set: str, parameter: str, value: float,
         state: Optional[Callable[[float], Any]] = None, **values: float) -> Dict[str, object]:
    """The mode crossing the imaginary axis at the Hopf point `value`:
    {"freq_hz", "band" ("low"/"high"), "dof" (DEGREES_OF_FREEDOM's word for
    the largest angle of its eigenvector), "loses" (True where straight
    rolling loses stability in that pair as the parameter grows), "l1" (the
    first Lyapunov coefficient, shared.lyapunov), "mu_slope" (d Re lambda /
    d parameter), "weak" (|l1| small: weak()), "a2" (Re of the kink's
    quadratic coefficient, 0 where f is smooth), "kink_psi" (the psi
    amplitude up to which a2 decides: SEEN)}."""
    def spectrum_at(at):
        model = mlgmodel.Model(parameter_set, **{**values, parameter: at})
        u = state(at) if state else model.equilibrium()
        return numpy.linalg.eig(numpy.array(model.jacobian(u)))
    here = mlgmodel.Model(parameter_set, **{**values, parameter: value})
    u = state(value) if state else here.equilibrium()
    hopf = lyapunov.first_lyapunov(here, u)
    a2 = lyapunov.kink_coefficient(here, u, hopf)
    meet = lyapunov.kink_amplitude(hopf, a2)
    lam, vec = spectrum_at(value)
    k = int(numpy.argmin(numpy.abs(lam.real) + (numpy.abs(lam.imag) < 1e-6) * 1e9))
    lam, vec = lam[k], vec[:, k]
    step = 1e-4 * max(1.0, abs(value))

    def followed(at):   # the same eigenvalue a small step away
        near = spectrum_at(at)[0]
        return near[int(numpy.argmin(numpy.abs(near - lam)))]
    before, after = followed(value - step), followed(value + step)
    names = mlgmodel.UNAMES
    size = {dof: abs(vec[names.index(dof)]) for dof in DEGREES_OF_FREEDOM}
    freq = abs(lam.imag) / (2 * numpy.pi)
    return {"freq_hz": float(freq), "band": "high" if freq >= HIGH_HZ else "low",
            "dof": DEGREES_OF_FREEDOM[max(size, key=size.get)],
            "loses": bool(after.real > before.real), "l1": float(hopf.l1),
            "mu_slope": float((after.real - before.real) / (2 * step)),
            "weak": bool(weak(here, u, hopf)), "a2": float(a2.real), "kink_psi": float(meet)}


def names(modes: Sequence[Dict[str, object]]) -> List[str]:
    """The name of each Hopf point, given their modes in the order of the
    parameter (rules in the module's doc)."""
    out: List[Optional[str]] = [None] * len(modes)

    def first(band, loses, after=-1):
        return next((k for k, m in enumerate(modes) if k > after and out[k] is None
                     and m["band"] == band and m["loses"] == loses), None)
    h1 = first("low", True)
    h2 = first("low", False, -1 if h1 is None else h1)
    h3 = first("high", True)
    for name, k in (("H1", h1), ("H2", h2), ("H3", h3)):
        if k is not None:
            out[k] = name
    rank = {"low": 0, "high": 0}
    for k, m in enumerate(modes):
        rank[m["band"]] += 1
        if out[k] is None:
            out[k] = f"H{'lf' if m['band'] == 'low' else 'hf'}{rank[m['band']]}"
    return out


def fold_names(folds: Sequence[Tuple[float, float]]) -> List[Tuple[str, float]]:
    """[(name, value)] of folds of periodic orbits [(value, Hz)], named by
    their family, not by the order found: those of the high-frequency
    orbits (HIGH_HZ or more) S1, S2, ... in increasing value (S1 is the
    paper's S), then the others "low-frequency fold 1", ... (Figs. 10, 13,
    14 and 16 name their folds so)."""
    high = sorted(v for v, hz in folds if hz >= HIGH_HZ)
    low = sorted(v for v, hz in folds if hz < HIGH_HZ)
    return ([(f"S{k + 1}", v) for k, v in enumerate(high)]
            + [(f"low-frequency fold {k + 1}", v) for k, v in enumerate(low)])


def weak(model: mlgmodel.Model, u: ArrayLike, hopf: lyapunov.Hopf) -> bool:
    """|l1| small: the normal form's orbit where the pair's real part is
    0.01 omega would reach beyond the angle over which the field is cubic
    (module constants)."""
    u = [u[name] for name in mlgmodel.UNAMES] if isinstance(u, dict) else u
    angle = (1e-3 * model["yfp"] / model.r_tlk(u[mlgmodel.UNAMES.index("eta")])
             if model["yfp"] > 0 else WEAK_ZERO_FREEPLAY)
    return 2 * abs(hopf.q[0]) * numpy.sqrt(0.01 / abs(hopf.l1)) > angle


def criticality(value: float, loses: bool, orbits: Sequence[Any], parameter: str = "V",
                others: Sequence[float] = ()) -> Optional[str]:
    """"supercritical" or "subcritical" from the orbit branches `orbits`
    (runs of AUTO diagrams, or stored branches) where they come nearest to
    straight rolling at `value`: their side (the side where the crossing
    mode is unstable: supercritical) and their stability there (stable:
    supercritical); "inconsistent" where side and stability disagree; None
    if no branch comes within NEAR of it, or within half the distance to the
    nearest of the other Hopf points `others` (their orbits are theirs)."""
    window = min([NEAR * max(1.0, abs(value))] + [0.5 * abs(value - o) for o in others
                                                  if o != value])
    best = None
    for run in orbits:
        for branch in run:
            v = numpy.asarray(branch[parameter])
            amp = numpy.asarray(branch["psi_amp"])
            near = numpy.abs(v - value) <= window
            # a branch born at the point: its first step tells the side, however long
            near[1:2] |= len(v) > 1 and abs(v[0] - value) <= 1e-6 * max(1.0, abs(value))
            near = numpy.flatnonzero(near & (amp > ZERO_AMPLITUDE) & (v != value))
            stable = branches.stable_mask(branch)
            for i in near:
                if best is None or amp[i] < best[0]:
                    best = (amp[i], v[i] - value, bool(stable[i]))
    if best is None:
        return None
    unstable_side = 1.0 if loses else -1.0
    side = "supercritical" if best[1] * unstable_side > 0 else "subcritical"
    return side if best[2] == (side == "supercritical") else "inconsistent"


def by_l1(l1: float) -> str:
    """The criticality the first Lyapunov coefficient's sign gives."""
    return "supercritical" if l1 < 0 else "subcritical"


def kink_decides(m: Dict[str, object]) -> bool:
    """Whether the kink's a2, not l1, decides at the amplitudes seen (SEEN)."""
    return m.get("kink_psi", 0.0) > SEEN


def by_coefficients(m: Dict[str, object]) -> str:
    """The criticality the normal form gives: Re a2's sign where the kink
    decides, else l1's."""
    return by_l1(m["a2"]) if kink_decides(m) else by_l1(m["l1"])


def _amplitude(parameter_set, parameter, value, psi0, t_end, state, values):
    """psi amplitude [rad] over the last second of a simulation at
    `value`, from straight rolling with psi moved by psi0; inf where the
    model leaves its domain (the motion went far from straight rolling)."""
    model = mlgmodel.Model(parameter_set, **{**values, parameter: value})
    u = dict(state(value) if state else model.equilibrium())
    u["psi"] += psi0
    params = {name: repr(float(v)) for name, v in {**values, parameter: value}.items()}
    proc = simulator.run(None, "--set", parameter_set, "--t-end", t_end,
                         *simulator.state_args(u), params=params)
    if simulator.left_domain(proc):
        return numpy.inf
    if proc.returncode != 0:
        raise simulator.SimulationError(f"naming: mlg_simulate failed at {parameter} = "
                                        f"{value:.6g}: {proc.stderr.strip()}")
    return simulator.summary(proc.stdout)["psi_amplitude_rad"]


def simulated(parameter_set: str, parameter: str, value: float, m: Dict[str, object],
              state: Optional[Callable[[float], Any]] = None, others: Sequence[float] = (),
              **values: float) -> Dict[str, object]:
    """The criticality short simulations on each side give (module
    constants): {"verdict": "supercritical", "subcritical" or "unsettled"
    (the motion died out on the unstable side, or neither decayed nor
    persisted on the stable one), "distance" d, "amplitude" [rad] on the
    unstable side, "decay" (the stable side's end amplitude over its start)}.
    others: the other Hopf points' values; d stays below half the distance
    to the nearest (else the stable side may not be stable)."""
    d = min([RATE * 2 * numpy.pi * m["freq_hz"] / abs(m["mu_slope"]), SPAN * abs(value)]
            + [0.5 * abs(value - o) for o in others if o != value])
    unstable = 1.0 if m["mu_slope"] > 0 else -1.0
    t_end = SETTLE / (abs(m["mu_slope"]) * d)

    def amplitude(at, psi0):
        return _amplitude(parameter_set, parameter, at, psi0, t_end, state, values)
    grown = amplitude(value + unstable * d, PSI0)
    start = min(grown, WEAK_ZERO_FREEPLAY)
    decay = amplitude(value - unstable * d, start) / start
    verdict = ("unsettled" if grown < LEFT * PSI0 else
               "supercritical" if decay < DECAYED else
               "subcritical" if decay > PERSISTS else "unsettled")
    return {"verdict": verdict, "distance": float(d), "amplitude": float(grown),
            "decay": float(decay)}


def verdicts(m: Dict[str, object], branch: Optional[str],
             simulation: Optional[Dict[str, object]]) -> Dict[str, object]:
    """The three checks side by side: {"criticality" (by l1), "branch",
    "simulation" (a verdict or None where not simulated), "agree" (True
    where every check made says what l1 says, and one was made)}."""
    verdict = by_coefficients(m)
    simulation = simulation["verdict"] if simulation else None
    made = [c for c in (branch, simulation) if c is not None]
    return {"criticality": verdict, "branch": branch, "simulation": simulation,
            "agree": bool(made) and all(c == verdict for c in made)}


def needs_simulation(m: Dict[str, object], branch: Optional[str]) -> bool:
    """Where the branch check does not settle l1's verdict, or |l1| is small."""
    return branch != by_coefficients(m) or (m.get("weak", False) and not kink_decides(m))


def describe(m: Dict[str, object], branch: Optional[str],
             simulation: Optional[Dict[str, object]] = None) -> str:
    """'high-frequency lateral, loses stability, subcritical (l1 = +0.0338;
    the orbit branch agrees; simulation agrees)': the verdict of l1,
    checked against the orbit branch (criticality) and the simulations
    (simulated); a disagreement is said, never hidden."""
    verdict = by_coefficients(m)
    checks = ["no orbit branch near it to check" if branch is None else
              "the orbit branch agrees" if branch == verdict else
              f"DISAGREES with the orbit branch, which is {branch}"]
    if simulation is not None:
        said = simulation["verdict"]
        checks.append(("simulation agrees" if said == verdict else
                       f"DISAGREES with simulation, which is {said}")
                      + f" (at {simulation['distance']:.3g} either side: amplitude "
                        f"{simulation['amplitude']:.3g} rad, then decay to "
                        f"{simulation['decay']:.2g} of it)")
    kink = ""
    if m.get("kink_psi", 0.0) > KINK_NOISE:
        kink = (f", a2 = {m['a2']:+.4g} (the oleo's kink) "
                + ("decides" if kink_decides(m) else "yields")
                + f" up to psi {m['kink_psi']:.2g} rad")
    return (f"{m['band']}-frequency {m['dof']}, "
            f"{'loses' if m['loses'] else 'regains'} stability, {verdict} "
            f"(l1 = {m['l1']:+.4g}{', weak' if m.get('weak') else ''}{kink}; "
            f"{'; '.join(checks)})")


def agreement(points: Sequence[Dict[str, object]]) -> str:
    """'criticality: 3 of 3 Hopf points agree three ways' (named_points)."""
    agree = sum(bool(p["agree"]) for p in points)
    return f"criticality: {agree} of {len(points)} Hopf points agree (l1, branch, simulation)"


def named_points(hopf: Sequence[Tuple[float, float]], orbits: Sequence[Any], parameter_set: str,
                 parameter: str, state: Optional[Callable[[float], Any]] = None,
                 **values: float) -> List[Dict[str, object]]:
    """[{"name", <parameter>, "freq_hz", "band", "dof", "loses", "l1",
    "mu_slope", "weak", "a2", "kink_psi", "criticality" (by_coefficients),
    "branch_criticality" (the
    orbit branches `orbits`), "simulated" (simulated(), where
    needs_simulation), "agree", "about"}] of the Hopf points hopf =
    [(value, Hz)] of straight rolling along `parameter`, named by their mode."""
    modes = [mode(parameter_set, parameter, v, state=state, **values) for v, _ in hopf]
    out = []
    for (v, _), m, name in zip(hopf, modes, names(modes)):
        branch = criticality(v, m["loses"], orbits, parameter, others=[h for h, _ in hopf])
        simulation = (simulated(parameter_set, parameter, v, m, state=state,
                                others=[h for h, _ in hopf], **values)
                      if needs_simulation(m, branch) else None)
        checked = verdicts(m, branch, simulation)
        out.append({"name": name, parameter: v, **m, "criticality": checked["criticality"],
                    "branch_criticality": branch, "simulated": simulation,
                    "agree": checked["agree"], "about": describe(m, branch, simulation)})
    return out


def scanned(parameter_set: str, parameter: str, grid: ArrayLike,
            **values: float) -> Dict[str, float]:
    """{name: value} of the Hopf points of straight rolling along `grid` of
    `parameter`, found by the eigenvalue scan (spectrum.hopf_scan, no AUTO)
    and named by their mode."""
    hopf = spectrum.hopf_scan(parameter_set, parameter, grid, **values)
    modes = [mode(parameter_set, parameter, v, **values) for v, _ in hopf]
    return {name: v for (v, _), name in zip(hopf, names(modes))}
