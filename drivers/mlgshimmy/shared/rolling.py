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
y_fp = 0 (where the links are linear and the equilibrium unique), each step
a Newton solve from the last state, halved where it does not converge close
by.  Where the branch ends at a fold in y_fp (the links jump to the other
side of the freeplay) there is no straight rolling beyond: NoRollingState.

    u = state("figures", 0.3, 1.0, {"eps_abs": 0.1, "eps_rel": 0.0}, rho=0.17, mu=0.17)
"""
import bisect
import ctypes
from typing import Dict, List, Tuple

import numpy

from mlgshimmy.shared import mlgmodel

STEP_PSI = 5e-4      # rad: a continuation step may move psi this far at most
HALVINGS = 14        # a step of y_fp halved this often before the branch is given up
V_SOLVE = 50.0       # m/s: straight rolling does not depend on V > 0 (docs/model.md 4.20)


class NoRollingState(RuntimeError):
    """The straight-rolling branch from zero freeplay does not reach this y_fp."""


def _residual(model: mlgmodel.Model, x: numpy.ndarray):
    """(f, df/du) at x, or None outside the model's domain."""
    lib = mlgmodel.library()
    nx = len(x)
    xs = (ctypes.c_double * nx)(*x)
    f = (ctypes.c_double * nx)()
    J = (ctypes.c_double * (nx * nx))()
    if lib.mlg_rhs_jacobian(ctypes.byref(model._p), xs, f, J, None) != 0:
        return None
    return numpy.array(f), numpy.array(J).reshape(nx, nx).T


def solve(model: mlgmodel.Model, start: numpy.ndarray, iterations: int = 30,
          tol: float = 1e-13):
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


def fan_states(model: mlgmodel.Model, base: numpy.ndarray, psis, same: float,
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


_paths: Dict[tuple, List[Tuple[float, numpy.ndarray]]] = {}


def _model(parameter_set, Fstar, yfp, epsilon, overrides):
    return mlgmodel.Model(parameter_set, Fstar=Fstar, V=V_SOLVE, yfp=yfp, **epsilon,
                          **dict(overrides))


def state(parameter_set: str, Fstar: float, yfp: float, epsilon: Dict[str, float],
          **overrides: float) -> Dict[str, float]:
    """Straight rolling at load F* and freeplay y_fp [mm] (epsilon: its
    eps_abs, eps_rel), continued from y_fp = 0; overrides: other parameters
    (the geometry).  Every state solved is kept, and a new y_fp continues
    from the nearest one below it.  NoRollingState if the branch ends first."""
    key = (parameter_set, float(Fstar), tuple(sorted(epsilon.items())),
           tuple(sorted(overrides.items())))
    path = _paths.get(key)
    if path is None:
        u0 = _model(parameter_set, Fstar, 0.0, epsilon, key[3]).equilibrium()
        path = _paths[key] = [(0.0, numpy.array([u0[n] for n in mlgmodel.UNAMES]))]
    ys = [y for y, _ in path]
    k = bisect.bisect_right(ys, yfp) - 1
    y0, u0 = path[k]
    if y0 != yfp:
        u0 = _walk(parameter_set, Fstar, epsilon, key[3], y0, u0, yfp, 0)
        path.insert(k + 1, (float(yfp), u0))
    return dict(zip(mlgmodel.UNAMES, u0))


def _walk(parameter_set, Fstar, epsilon, overrides, y0, u0, y1, depth):
    """The state at y1 continued from (y0, u0), the step halved until each
    piece converges within STEP_PSI of its start."""
    u = solve(_model(parameter_set, Fstar, y1, epsilon, overrides), u0)
    if u is not None and abs(u[0] - u0[0]) <= STEP_PSI:
        return u
    if depth >= HALVINGS:
        raise NoRollingState(f"rolling: straight rolling from zero freeplay at F* = {Fstar:g} "
                             f"ends between y_fp = {y0:.6g} and {y1:.6g} mm (a fold in y_fp)")
    middle = 0.5 * (y0 + y1)
    u_mid = _walk(parameter_set, Fstar, epsilon, overrides, y0, u0, middle, depth + 1)
    return _walk(parameter_set, Fstar, epsilon, overrides, middle, u_mid, y1, depth + 1)
