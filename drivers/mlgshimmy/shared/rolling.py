"""Straight rolling at side-stay angles, followed in the freeplay from zero
freeplay (ctypes and numpy, no AUTO).

At rho = mu = 0 straight rolling is psi = delta = 0 and mlg_equilibrium
(Newton from there) finds it at every load and freeplay.  With side-stay
angles the load twists the gear (docs/model.md 8.7) and the links sit
off-centre in the freeplay; at light load there are then several
equilibria (the pitchforks of Fig. 12 become imperfect, the yawed states
one-sided), and Newton from psi = 0 may land on any of them or on none
(rho = mu = 10 deg, eps = 0.1 mm: no convergence at F* = 0.1-0.3 for y_fp
from about 0.6 mm).  Here straight rolling at (F*, y_fp) is the equilibrium
connected to the zero-freeplay one at that load: continued in y_fp from
y_fp = 0 (where the links are linear and the equilibrium unique) by
`follow`, whose steps the branch itself bounds.  Where the branch ends at a
fold in y_fp (the links jump to the other side of the freeplay) there is
no straight rolling beyond: NoRollingState.

    u = state("figures", 0.3, 1.0, {"eps_abs": 0.1, "eps_rel": 0.0}, rho=0.17, mu=0.17)
"""
import bisect
import ctypes
from typing import Callable, Dict, List, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import mlgmodel

# Newton-Kantorovich: corrections shrinking by 1/4 or more (h <= 1/2) make the
# state reached the only equilibrium within twice the first of the prediction.
CONTRACTION = 0.25
V_SOLVE = 50.0       # m/s: straight rolling does not depend on V > 0 (docs/model.md 4.20)


class NoRollingState(RuntimeError):
    """The branch followed ends at a fold short of the value asked for (for
    straight rolling from zero freeplay: of this y_fp); .at: the parameter's
    value there (None where not known)."""

    def __init__(self, message: str, at: Optional[float] = None):
        super().__init__(message)
        self.at = at


def _residual(model: mlgmodel.Model, x: numpy.ndarray, par: Optional[str] = None):
    """(f, df/du) at x, with df/d par appended if par names a parameter;
    None outside the model's domain."""
    lib = mlgmodel.library()
    nx = len(x)
    xs = (ctypes.c_double * nx)(*x)
    f = (ctypes.c_double * nx)()
    J = (ctypes.c_double * (nx * nx))()
    P = (ctypes.c_double * (nx * len(mlgmodel.PARNAMES)))() if par else None
    if lib.mlg_rhs_jacobian(ctypes.byref(model._p), xs, f, J, P) != 0:
        return None
    got = numpy.array(f), numpy.array(J).reshape(nx, nx).T
    if par:
        k = mlgmodel.PARNAMES.index(par)
        got += (numpy.array(P[k * nx:(k + 1) * nx]),)
    return got


def solve(model: mlgmodel.Model, start: numpy.ndarray, iterations: int = 30,
          tol: float = 1e-13) -> Optional[numpy.ndarray]:
    """Newton on f(u) = 0 from `start` with backtracking on |f| (as
    mlg_equilibrium); the state, or None if it does not converge."""
    x = numpy.array(start, dtype=float)
    got = _residual(model, x)
    if got is None:
        return None
    for _ in range(iterations):
        f, J = got
        try:
            step = -numpy.linalg.solve(J, f)
        except numpy.linalg.LinAlgError:
            return None
        norm, scale = numpy.linalg.norm(f), 1.0
        while scale > 1e-4:
            trial = x + scale * step
            got = _residual(model, trial)
            if got is not None and numpy.linalg.norm(got[0]) < norm:
                break
            scale *= 0.5
        else:
            return x if norm < 1e-6 else None
        moved, x = numpy.max(numpy.abs(trial - x)), trial
        if moved < tol:
            return x
    return None


def fan_states(model: mlgmodel.Model, base: numpy.ndarray, psis: Sequence[float], same: float,
               iterations: int = 30) -> List[numpy.ndarray]:
    """The distinct stationary states Newton (solve) converges to from the
    state `base` with psi set to each of `psis` in turn (psi within `same`
    of a state found before: the same state), sorted by psi; how
    shared.yawed and shared.stationary look for the yawed states."""
    found: List[numpy.ndarray] = []
    for psi in psis:
        guess = numpy.array(base, dtype=float)
        guess[0] = psi
        u = solve(model, guess, iterations=iterations)
        if u is not None and all(abs(u[0] - v[0]) > same for v in found):
            found.append(u)
    return sorted(found, key=lambda u: u[0])


def follow(model_at: Callable[[float], mlgmodel.Model], par: str, s0: float,
           u0: numpy.ndarray, s1: float, branch: str) -> List[Tuple[float, numpy.ndarray]]:
    """[(s, state)] from s0 (not included) to s1 along the branch of
    equilibria of model_at(s) through the state u0 at s0, s the value of
    the parameter `par`.  A step (_step) predicts along the branch's
    tangent and corrects by Newton; where the branch bends or another
    equilibrium is near, the step is halved, and after a success doubled,
    so the branch sets the step.  A step too short to move s that still
    fails means the branch turns back there: NoRollingState (`branch`
    names it in the message)."""
    s, u, h, found = s0, numpy.array(u0, dtype=float), s1 - s0, []
    while s != s1:
        h = min(h, s1 - s) if h > 0 else max(h, s1 - s)
        u_next = _step(model_at(s + h), par, u, h)
        if u_next is not None:
            s, u, h = s + h, u_next, 2.0 * h
            found.append((s, u))
            continue
        h *= 0.5
        if s + h == s:
            raise NoRollingState(f"rolling: {branch} ends at {par} = {s:.9g} (a fold in {par})",
                                 at=s)
    return found


def _step(model: mlgmodel.Model, par: str, u: numpy.ndarray, h: float,
          iterations: int = 30, tol: float = 1e-13):
    """The state of `model` (par moved by h from the state u's), or None
    unless: each Newton correction from the tangent prediction is at most
    CONTRACTION times the step before it (the first: the predicted move),
    and the tangent there points back to u within CONTRACTION of the move.
    Tangents are taken in `model`: at zero freeplay with the links centred
    the link force has a kink in y_fp."""
    predictor = _tangent(model, par, u)
    if predictor is None:
        return None
    predictor *= h
    x, last = u + predictor, numpy.max(numpy.abs(predictor))
    for _ in range(iterations):
        got = _residual(model, x)
        if got is None:
            return None
        f, J = got
        try:
            step = -numpy.linalg.solve(J, f)
        except numpy.linalg.LinAlgError:
            return None
        size = numpy.max(numpy.abs(step))
        if size > max(CONTRACTION * last, tol):
            return None
        x, last = x + step, size
        if size < tol:
            back = _tangent(model, par, x)
            if back is None or numpy.max(numpy.abs(x - u - h * back)) > max(
                    CONTRACTION * numpy.max(numpy.abs(x - u)), tol):
                return None
            return x
    return None


def _tangent(model: mlgmodel.Model, par: str, u: numpy.ndarray):
    """du/d par = -(df/du)^-1 df/d par at u in `model`, or None."""
    got = _residual(model, u, par)
    if got is None:
        return None
    try:
        return -numpy.linalg.solve(got[1], got[2])
    except numpy.linalg.LinAlgError:
        return None


# per load and gear: the freeplays solved, in order, and their states
_paths: Dict[tuple, Tuple[List[float], List[numpy.ndarray]]] = {}


def _model(parameter_set, Fstar, yfp, epsilon, overrides):
    return mlgmodel.Model(parameter_set, Fstar=Fstar, V=V_SOLVE, yfp=yfp, **epsilon,
                          **dict(overrides))


def state(parameter_set: str, Fstar: float, yfp: float, epsilon: Dict[str, float],
          **overrides: float) -> Dict[str, float]:
    """Straight rolling at load F* and freeplay y_fp [mm] (epsilon: its
    eps_abs, eps_rel), continued from y_fp = 0 (follow); overrides: other
    parameters (the geometry).  Every state solved is kept, and a new y_fp
    continues from the nearest one below it.  NoRollingState if the branch
    ends first."""
    key = (parameter_set, float(Fstar), tuple(sorted(epsilon.items())),
           tuple(sorted(overrides.items())))
    if key not in _paths:
        u0 = _model(parameter_set, Fstar, 0.0, epsilon, key[3]).equilibrium()
        _paths[key] = ([0.0], [numpy.array([u0[n] for n in mlgmodel.UNAMES])])
    ys, us = _paths[key]
    k = bisect.bisect_right(ys, yfp) - 1
    y0, u0 = ys[k], us[k]
    if y0 != yfp:
        def model_at(y):
            return _model(parameter_set, Fstar, y, epsilon, key[3])
        found = follow(model_at, "yfp", y0, u0, float(yfp),
                       f"straight rolling from zero freeplay at F* = {Fstar:g}")
        ys[k + 1:k + 1] = [y for y, _ in found]
        us[k + 1:k + 1] = [u for _, u in found]
        u0 = us[k + len(found)]
    return dict(zip(mlgmodel.UNAMES, u0))
