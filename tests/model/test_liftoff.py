"""shared/liftoff.py: the bisection on a known step (no simulation), and
two simulations of the `figures` set with y_fp = 1 mm, epsilon = 0.1 mm:
at V = 600 m/s, F* = 0.3 the shimmy grown from straight rolling lifts a
wheel off after about 19 s (docs/reproduction.md, Fig. 11); at V = 100 m/s,
F* = 1 straight rolling is stable (the Hopf point lies at 130 m/s) and no
wheel lifts off."""
import math

import numpy
import pytest

from mlgshimmy.shared import liftoff


def step(at):
    return lambda x: x >= at


def test_bisection_locates_the_step_to_half_the_tolerance():
    found = liftoff.bisected(step(573.3), 450.0, 600.0, 2.0, "V")
    assert math.isclose(found, 573.3, abs_tol=1.0), found


def test_bisection_with_the_bracket_reversed():
    """Lift-off below 0.537: the bracket runs from 0.6 down to 0.5."""
    found = liftoff.bisected(lambda f: f <= 0.537, 0.6, 0.5, 0.005, "F*")
    assert math.isclose(found, 0.537, abs_tol=0.0025), found


def test_bisection_without_lift_off_at_the_top_of_the_bracket_is_none():
    assert liftoff.bisected(step(700.0), 450.0, 600.0, 2.0, "V") is None


def test_bisection_of_a_checked_bracket_runs_only_the_cuts():
    """The caller checked the bracket: its ends are not run again; each cut
    keeps at most LIFT_SIDE_SPLIT of the bracket, so from 150 to 2 m/s it
    takes at most ceil(log(75) / log(1 / 0.75)) = 16 runs."""
    tried = []
    found = liftoff.bisected(lambda x: tried.append(x) or x >= 573.3, 450.0, 600.0, 2.0, "V",
                             checked=True)
    assert 450.0 not in tried and 600.0 not in tried and abs(found - 573.3) <= 1.0, tried
    bound = math.ceil(math.log(150.0 / 2.0) / math.log(1.0 / liftoff.LIFT_SIDE_SPLIT))
    assert len(tried) <= bound, (len(tried), bound, tried)


def test_bisection_of_an_unchecked_bracket_runs_its_top_not_its_bottom():
    """The top end and the cuts are run, not the bottom end (the edge
    lies far from it)."""
    tried = []
    liftoff.bisected(lambda x: tried.append(x) or x >= 573.3, 450.0, 600.0, 2.0, "V")
    assert tried[0] == 600.0 and 450.0 not in tried, tried


def test_bisection_makes_fewer_runs_without_lift_off_than_halving(monkeypatch):
    """A run without lift-off costs the whole T_END, one with lift-off stops
    early: for edges spread over a 100 m/s bracket the cuts towards the
    lift-off end make at most 2.3 runs without lift-off on average, halving
    at least 3.0; every edge is still found to half TOL_V."""
    def runs_without(split):
        monkeypatch.setattr(liftoff, "LIFT_SIDE_SPLIT", split)
        counts = []
        for edge in numpy.linspace(400.5, 499.5, 100):
            tried = []
            found = liftoff.bisected(lambda V: tried.append(V) or V >= edge, 400.0, 500.0,
                                     liftoff.TOL_V, "V", checked=True)
            assert abs(found - edge) <= 0.5 * liftoff.TOL_V, (split, edge, found)
            counts.append(sum(V < edge for V in tried))
        return numpy.mean(counts)
    cuts, halving = runs_without(liftoff.LIFT_SIDE_SPLIT), runs_without(0.5)
    assert cuts <= 2.3 and halving >= 3.0, (cuts, halving)


def test_bisection_with_lift_off_at_the_bottom_of_the_bracket_names_it():
    with pytest.raises(ValueError) as error:
        liftoff.bisected(step(400.0), 450.0, 600.0, 2.0, "V")
    assert "V = 450" in str(error.value), str(error.value)


def test_lifts_off_refuses_a_negative_speed_naming_V():
    with pytest.raises(ValueError) as error:
        liftoff.lifts_off("x.csv", -5.0, 0.3)
    assert "V = -5" in str(error.value), str(error.value)


def test_lifts_off_simulated_at_600_and_100_m_s(tmp_path):
    """V = 600 m/s, F* = 0.3: a wheel lifts off within 60 s; V = 100 m/s,
    F* = 1: no lift-off in 5 s (straight rolling stable); no simulator
    output left behind."""
    csv = str(tmp_path / "run.csv")
    assert liftoff.lifts_off(csv, 600.0, 0.3, t_end=60.0), \
        "V = 600 m/s, F* = 0.3: no wheel lifted off within 60 s"
    assert not liftoff.lifts_off(csv, 100.0, 1.0, t_end=5.0), \
        "V = 100 m/s, F* = 1: a wheel lifted off within 5 s"
    assert list(tmp_path.iterdir()) == [], list(tmp_path.iterdir())


def test_edge_speed_moves_its_bracket_down_where_a_wheel_lifts_off_at_its_bottom(monkeypatch):
    """At a side-stay geometry the edge can lie below the bracket's low end:
    it moves down by LOWER_BY until a speed without lift-off, then bisects
    there (the edge at 420 m/s from a bracket 500-600, to half TOL_V)."""
    tried = []
    monkeypatch.setattr(liftoff, "lifts_off",
                        lambda csv, V, Fstar, **_: tried.append(V) or V >= 420.0)
    found = liftoff.edge_speed("x.csv", 0.2, 500.0, 600.0)
    assert abs(found - 420.0) <= 0.5 * liftoff.TOL_V, (found, tried)
    assert 400.0 in tried and min(tried) == 400.0, tried


def test_edge_speed_gives_up_below_its_lowest_bracket(monkeypatch):
    monkeypatch.setattr(liftoff, "lifts_off", lambda csv, V, Fstar, **_: True)
    with pytest.raises(liftoff.HoldsAtLow) as error:
        liftoff.edge_speed("x.csv", 0.2, 500.0, 600.0)
    assert "V = 500" in str(error.value), str(error.value)
