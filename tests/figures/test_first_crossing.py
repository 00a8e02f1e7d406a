"""kappa*'s inner search in few evaluations (kappa_criterion.first_crossing with
spectrum.root), checked against the plain search it replaces: a bisection to
1e-10 mm of each speed's first change of stability on the y_fp grid
(kappa_criterion.yfp_crossings), the least over the speeds.

Run: /usr/bin/python3 -m pytest -q tests/figures/test_first_crossing.py
"""
import math

import numpy
import pytest

from mlgshimmy.shared import kappa_criterion
from mlgshimmy.shared import yfp_runs
from mlgshimmy.shared import spectrum

SPEEDS = numpy.linspace(yfp_runs.V_MIN, yfp_runs.V_LIMIT, 7)


def plain(Fstar, band, **model):
    """The least first crossing over SPEEDS, speed by speed, by bisection."""
    best = (numpy.inf, None)
    for V in SPEEDS:
        found = kappa_criterion.yfp_crossings(Fstar, V, band, first_only=True, **model)
        if found and found[0] < best[0]:
            best = (found[0], V)
    return best


@pytest.mark.parametrize("Fstar, band, model", [
    (1.0, "any", {}), (0.3, "high", {}), (1.7, "any", {}),
    (1.0, "any", {"rho": math.radians(10), "mu": math.radians(10), "eom_terms": 2.0}),
    (0.3, "any", {"rho": math.radians(15), "mu": math.radians(-5), "eom_terms": 2.0})])
def test_first_crossing_is_the_plain_search(Fstar, band, model):
    y, V = kappa_criterion.first_crossing(Fstar, SPEEDS, band, **model)
    y_plain, V_plain = plain(Fstar, band, **model)
    assert V == V_plain and y == pytest.approx(y_plain, abs=2e-10)
    assert 0.01 < y < 0.2   # mm: a crossing inside the grid, not at an end


def test_unstable_without_freeplay_is_zero_at_the_first_such_speed():
    """At rho = mu = 10 deg, F* = 0.65 straight rolling is unstable without
    freeplay at some speeds (kappa* = 0 there)."""
    model = {"rho": math.radians(10), "mu": math.radians(10), "eom_terms": 2.0}
    y, V = kappa_criterion.first_crossing(0.65, SPEEDS, "any", **model)
    assert (y, V) == plain(0.65, "any", **model) and y == 0.0


def test_root_brackets_a_sign_change_as_bisection_does_in_fewer_evaluations():
    calls = []

    def f(x):
        calls.append(x)
        return math.tanh(40 * (x - 0.3137)) + 0.2 * (x - 0.3137) ** 2
    found = spectrum.root(f, 0.0, 1.0, f(0.0), f(1.0), tol=1e-12)
    assert found == pytest.approx(0.3137, abs=1e-12) and len(calls) - 2 < 20
    bisected = spectrum.bisect(lambda x: f(x) <= 0, 0.0, 1.0, tol=1e-12)
    assert found == pytest.approx(bisected, abs=2e-12)


def test_root_halves_where_a_value_is_not_finite():
    def f(x):
        return -numpy.inf if x < 0.25 else x - 0.6
    assert spectrum.root(f, 0.0, 1.0, f(0.0), f(1.0), tol=1e-12) == pytest.approx(0.6, abs=1e-12)
