"""Whether a periodic orbit is close to a connection of saddles: a
homoclinic or heteroclinic cycle, where the orbit's branch ends with its
period growing without bound at a nearly constant parameter.  AUTO stops
there with no convergence (MX), as the mesh no longer resolves the orbit's
long stays near the saddles; that stop is an end of the branch, not a
failure.

Near such a cycle the orbit spends most of its period next to saddle
equilibria (the time near one grows like log(1/distance) / its unstable
eigenvalue, while the excursions between them keep their time).  With the
`tanh` law at Fig. 10's case the orbits born at H2 end so at 29.753 m/s:
they sit at the yawed saddles psi = +-1.754e-3 rad (y_tlk = +-0.840 mm,
where tanh's force dips below zero inside the gap) for 79 % of their
period of 2.42 s.

    visited, share = saddle_stays(model, solution)   # equilibria, part of the period near them
"""
from __future__ import annotations

from typing import Any, List, Tuple

import numpy

from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import rolling

NEAR = 0.01       # of the orbit's diameter: the orbit is at an equilibrium this close to it
MOST = 0.5        # part of the period near saddles that makes a connection
MAX_SADDLES = 4   # equilibria looked for, one from each slowest stay


def saddle_stays(model: mlgmodel.Model, sol: Any) -> Tuple[List[numpy.ndarray], float]:
    """(saddles, share): the saddle equilibria of `model` (an unstable
    eigenvalue, or a zero one) next to which the orbit `sol` (an AUTO
    solution: t in [0, 1] and the states) stays, found by Newton from its
    slowest point not yet near one, and the part of its period spent
    within NEAR of its diameter of them."""
    t = numpy.asarray(sol["t"], dtype=float)
    X = numpy.column_stack([numpy.asarray(sol[n], dtype=float) for n in mlgmodel.UNAMES])
    if len(t) < 3:
        return [], 0.0
    diameter = numpy.linalg.norm(X.max(axis=0) - X.min(axis=0))
    speed = numpy.linalg.norm(numpy.gradient(X, t, axis=0), axis=1)
    weight = numpy.gradient(t)            # the time each mesh point stands for
    near, saddles = numpy.zeros(len(t), dtype=bool), []
    for _ in range(MAX_SADDLES):
        free = numpy.flatnonzero(~near)
        if not free.size:
            break
        slowest = X[free[numpy.argmin(speed[free])]]
        u = rolling.solve(model, slowest)
        if u is None or numpy.linalg.norm(slowest - u) > NEAR * diameter or not _saddle(model, u):
            break
        saddles.append(u)
        near |= numpy.linalg.norm(X - u, axis=1) <= NEAR * diameter
    return saddles, float(numpy.sum(weight[near]) / numpy.sum(weight))


def _saddle(model: mlgmodel.Model, u: numpy.ndarray) -> bool:
    """Not asymptotically stable: an orbit can reach it and leave it."""
    lam = numpy.linalg.eigvals(model.jacobian(u))
    return bool(numpy.max(lam.real) > -1e-9 * numpy.max(numpy.abs(lam)))


def connects(model: mlgmodel.Model, sol: Any) -> bool:
    """Whether the orbit `sol` is close to a connection of saddles: most
    of its period (MOST) near them."""
    return saddle_stays(model, sol)[1] >= MOST
