"""Off-centre yaw: the stationary states of the gear other than straight
rolling at one load, and where in V they are stable (ctypes and numpy, no
AUTO).  What Fig. 11's off-centre-yaw band and the attractor atlas's "yaw"
both mean: a stable stationary state off straight rolling.

Straight rolling is rolling.state (the equilibrium connected to the
zero-freeplay one at that load; None where that branch has ended in a fold
of y_fp).  The other stationary states are found by Newton (rolling.solve)
from seeds spread across the freeplay on both sides: the straight-rolling
state with the link twist psi_s = psi + beta sin p set to SEEDS x y_fp /
r_tlk (the yawed states of Fig. 12 lie inside the freeplay, up to 0.78 of it
at the paper's gear, so seeds on both sides up to past its edges reach every
one that Newton can).  A state is off centre when its psi differs from
straight rolling's by attractor.CENTRE or more, the classifier's own test.
Stationary states do not depend on V > 0 (docs/model.md 4.20); their
stability does, from the eigenvalues of the exact Jacobian at each V.

    found = states("figures", 0.2, freeplay.NOMINAL)    # {"straight", "yawed"}
    grid = stable_grid("figures", F_GRID, V_GRID, freeplay.NOMINAL, **geometry)
"""
import math
from typing import Dict, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import attractor
from mlgshimmy.shared import domain
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import rolling

SEEDS = (0.2, 0.4, 0.6, 0.8, 0.95, 1.1, 1.3)   # |psi_s| of the seeds / (y_fp / r_tlk)
SAME = 1e-9         # rad: Newton's states (to 1e-13) whose psi differ less are one


def _vector(u: Dict[str, float]) -> numpy.ndarray:
    return numpy.array([u[n] for n in mlgmodel.UNAMES])


def model(parameter_set: str, Fstar: float, freeplay: Dict[str, float], V: float = rolling.V_SOLVE,
          **overrides: float) -> mlgmodel.Model:
    return mlgmodel.Model(parameter_set, Fstar=Fstar, V=V, **freeplay, **overrides)


def straight(parameter_set: str, Fstar: float, freeplay: Dict[str, float],
             **overrides: float) -> Optional[Dict[str, float]]:
    """Straight rolling at this load (rolling.state), or None where its branch
    from zero freeplay has ended before y_fp."""
    epsilon = {k: freeplay[k] for k in ("eps_abs", "eps_rel")}
    try:
        return rolling.state(parameter_set, Fstar, freeplay["yfp"], epsilon, **overrides)
    except rolling.NoRollingState:
        return None


def reference(parameter_set: str, Fstar: float, freeplay: Dict[str, float],
              u0: Optional[Dict[str, float]], **overrides: float) -> Tuple[float, Optional[float]]:
    """(psi_fp, psi_straight) [rad] at this load for shared.attractor.classify:
    the freeplay angle y_fp / r_tlk at straight rolling u0 (r_tlk depends on
    the strut compression, so on F*: 2.56e-3 at F* = 0.02, 2.05e-3 at 3.5)
    and straight rolling's psi (None where there is none, u0 None; psi_fp
    then at the library's equilibrium)."""
    m = mlgmodel.Model(parameter_set, Fstar=Fstar, **freeplay, **overrides)
    eta = (m.equilibrium() if u0 is None else u0)["eta"]
    return freeplay["yfp"] * 1e-3 / m.r_tlk(eta), None if u0 is None else u0["psi"]


def states(parameter_set: str, Fstar: float, freeplay: Dict[str, float],
           **overrides: float) -> Dict[str, object]:
    """{"straight": straight rolling (a state vector in mlgmodel.UNAMES
    order) or None, "yawed": [the other stationary states found, by psi]}."""
    m = model(parameter_set, Fstar, freeplay, **overrides)
    sr = straight(parameter_set, Fstar, freeplay, **overrides)
    try:
        base = sr if sr is not None else m.equilibrium()    # the seeds' other states
    except RuntimeError as exc:
        raise RuntimeError(f"yawed: no straight rolling from zero freeplay at F* = {Fstar:g} "
                           f"and no equilibrium to seed from ({exc})") from None
    d = domain.diagnose(m, base)
    twist = base["psi"] + base["beta"] * math.sin(d["p"])    # psi_s of the base state
    psi_fp = freeplay["yfp"] * 1e-3 / d["r_tlk"]
    found = rolling.fan_states(m, _vector(base), [base["psi"] + (seed * psi_fp - twist)
                                                   for k in SEEDS for seed in (k, -k)], SAME)
    centre = None if sr is None else sr["psi"]
    return {"straight": None if sr is None else _vector(sr),
            "yawed": [u for u in found if centre is None or abs(u[0] - centre) >= attractor.CENTRE]}


def stable_speeds(m: mlgmodel.Model, u: numpy.ndarray, speeds: Sequence[float]) -> numpy.ndarray:
    """[len(speeds)] True where no eigenvalue of the Jacobian at the
    stationary state u has a positive real part (m is set to each V)."""
    out = numpy.zeros(len(speeds), dtype=bool)
    for k, V in enumerate(speeds):
        m.set(V=float(V))
        out[k] = numpy.max(numpy.linalg.eigvals(m.jacobian(u)).real) < 0.0
    return out


def stable_grid(parameter_set: str, loads: Sequence[float], speeds: Sequence[float],
                freeplay: Dict[str, float], **overrides: float) -> numpy.ndarray:
    """[len(loads), len(speeds)] True where a stable off-centre stationary
    state exists (states, stable_speeds)."""
    out = numpy.zeros((len(loads), len(speeds)), dtype=bool)
    for i, Fstar in enumerate(loads):
        m = model(parameter_set, float(Fstar), freeplay, **overrides)
        for u in states(parameter_set, float(Fstar), freeplay, **overrides)["yawed"]:
            out[i] |= stable_speeds(m, u, speeds)
    return out
