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
(shared.lyapunov: supercritical where l1 < 0), checked against the orbit
branch at the point: supercritical where the orbits lie on the side where
the crossing mode is unstable, subcritical on the other (the paper's H3:
its orbits run down in V towards the fold S, while straight rolling is
stable below H3).  Where the two disagree, the description says so.
"""
from typing import Dict, List, Optional, Sequence

import numpy

from mlgshimmy.shared import lyapunov, mlgmodel, spectrum

HIGH_HZ = 8.0   # Hz: between the paper's low (1.7-3.3 Hz) and high (13 Hz) pairs
DEGREES_OF_FREEDOM = {"psi": "torsional", "delta": "lateral", "beta": "longitudinal"}
NEAR = 0.05     # relative: orbit points this close to a Hopf value tell its side
ZERO_AMPLITUDE = 1e-8   # rad: below, an "orbit" is straight rolling (continuation.COLLAPSED)


def mode(parameter_set: str, parameter: str, value: float, state=None,
         **values: float) -> Dict[str, object]:
    """The mode crossing the imaginary axis at the Hopf point `value`:
    {"freq_hz", "band" ("low"/"high"), "dof" (DEGREES_OF_FREEDOM's word for
    the largest angle of its eigenvector), "loses" (True where straight
    rolling loses stability in that pair as the parameter grows), "l1" (the
    first Lyapunov coefficient, shared.lyapunov)}."""
    def spectrum_at(at):
        model = mlgmodel.Model(parameter_set, **{**values, parameter: at})
        u = state(at) if state else model.equilibrium()
        return numpy.linalg.eig(numpy.array(model.jacobian(u)))
    here = mlgmodel.Model(parameter_set, **{**values, parameter: value})
    l1 = lyapunov.first_lyapunov(here, state(value) if state else here.equilibrium()).l1
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
            "loses": bool(after.real > before.real), "l1": float(l1)}


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


def criticality(value: float, loses: bool, orbits, parameter: str = "V") -> Optional[str]:
    """"supercritical" or "subcritical" from the side of `value` on which
    the orbit branches `orbits` (runs of AUTO diagrams, or stored branches)
    come nearest to straight rolling there; None if no branch comes within
    NEAR of it."""
    best = None
    for run in orbits:
        for branch in run:
            v = numpy.asarray(branch[parameter])
            amp = numpy.asarray(branch["psi_amp"])
            near = numpy.abs(v - value) <= NEAR * max(1.0, abs(value))
            # a branch born at the point: its first step tells the side, however long
            near[1:2] |= len(v) > 1 and abs(v[0] - value) <= 1e-6 * max(1.0, abs(value))
            near = numpy.flatnonzero(near & (amp > ZERO_AMPLITUDE) & (v != value))
            for i in near:
                if best is None or amp[i] < best[0]:
                    best = (amp[i], v[i] - value)
    if best is None:
        return None
    unstable_side = 1.0 if loses else -1.0
    return "supercritical" if best[1] * unstable_side > 0 else "subcritical"


def by_l1(l1: float) -> str:
    """The criticality the first Lyapunov coefficient's sign gives."""
    return "supercritical" if l1 < 0 else "subcritical"


def describe(m: Dict[str, object], branch: Optional[str]) -> str:
    """'high-frequency lateral, loses stability, subcritical (l1 = +0.0338;
    the orbit branch agrees)': the verdict of l1, checked against the side
    of the orbit branch (criticality); a disagreement is said, never hidden."""
    verdict = by_l1(m["l1"])
    check = ("no orbit branch near it to check" if branch is None else
             "the orbit branch agrees" if branch == verdict else
             f"DISAGREES with the orbit branch, which is {branch}")
    return (f"{m['band']}-frequency {m['dof']}, "
            f"{'loses' if m['loses'] else 'regains'} stability, {verdict} "
            f"(l1 = {m['l1']:+.4g}; {check})")


def named_points(hopf, orbits, parameter_set: str, parameter: str, state=None,
                 **values: float) -> List[Dict[str, object]]:
    """[{"name", <parameter>, "freq_hz", "band", "dof", "loses", "l1",
    "criticality" (by l1), "branch_criticality" (the side of the orbit
    branches `orbits`: the check), "about"}] of the Hopf points hopf =
    [(value, Hz)] of straight rolling along `parameter`, named by their mode."""
    modes = [mode(parameter_set, parameter, v, state=state, **values) for v, _ in hopf]
    out = []
    for (v, _), m, name in zip(hopf, modes, names(modes)):
        branch = criticality(v, m["loses"], orbits, parameter)
        out.append({"name": name, parameter: v, **m, "criticality": by_l1(m["l1"]),
                    "branch_criticality": branch, "about": describe(m, branch)})
    return out



def scanned(parameter_set: str, parameter: str, grid, **values: float) -> Dict[str, float]:
    """{name: value} of the Hopf points of straight rolling along `grid` of
    `parameter`, found by the eigenvalue scan (spectrum.hopf_scan, no AUTO)
    and named by their mode."""
    hopf = spectrum.hopf_scan(parameter_set, parameter, grid, **values)
    modes = [mode(parameter_set, parameter, v, **values) for v, _ in hopf]
    return {name: v for (v, _), name in zip(hopf, names(modes))}
