"""kappa_criterion.refined_minimum stops at its floor: where straight rolling is
unstable without freeplay (kappa* = 0, y_fp = 0 at some load) the search
ends there, with the point the full search keeps, in fewer evaluations."""
import numpy
import pytest

from mlgshimmy.shared import kappa_criterion

LOADS = numpy.arange(0.1, 2.01, 0.1)


def counted(first):
    """evaluate(F*) -> {"Fstar", "first": first(F*)}, and the loads it was asked for."""
    asked = []

    def evaluate(Fstar):
        asked.append(float(Fstar))
        return {"Fstar": float(Fstar), "first": float(first(Fstar))}
    return evaluate, asked


@pytest.mark.parametrize("first", [
    lambda F: max(0.0, abs(F - 0.73) - 0.25),      # zero on [0.48, 0.98]: ties at the floor
    lambda F: 0.0 if F > 1.5 else 1.0,             # zero only on the last loads
    lambda F: 0.2 + (F - 1.234) ** 2,              # never zero: the floor changes nothing
])
def test_the_floor_keeps_the_point_and_saves_evaluations(first):
    full, asked_full = counted(first)
    floored, asked_floored = counted(first)
    whole = kappa_criterion.refined_minimum(full, LOADS, lambda p: p["first"], finer=(5, 4))
    stopped = kappa_criterion.refined_minimum(floored, LOADS, lambda p: p["first"], finer=(5, 4),
                                              floor=0.0)
    assert stopped == whole
    if whole["first"] > 0:
        assert asked_floored == asked_full
    else:   # stopped at the first load on the floor, unrefined
        assert asked_floored == asked_full[:asked_full.index(whole["Fstar"]) + 1]
        assert len(asked_floored) <= len(LOADS) < len(asked_full)


def test_kappa_star_is_zero_at_the_first_load_unstable_without_freeplay():
    evaluate, asked = counted(lambda F: 0.0 if F >= 0.45 else 0.3)
    kappa, best = kappa_criterion.kappa_star(evaluate, LOADS, {}, finer=(5, 4))
    assert kappa == 0.0 and best["Fstar"] == pytest.approx(0.5, abs=1e-12)
    assert len(asked) == 5
