"""torus.closes: a torus curve run that comes back through its first two
points is a closed curve (an isola in (V, F*), as the tongue at F* ~ 0.69
at rho = 20, mu = 5 deg), and the other direction is not run; an open arc,
or a spiral that passes its start one step-width off, is not closed.  A
direction whose run fails is left out and reported, the other kept; both
failing is an error (AUTO's runs faked)."""
import numpy as np
import pytest

from mlgshimmy.shared import runerror, torus

VS = torus.V_MAX
FS = torus.CURVE_FSTAR[1] - torus.CURVE_FSTAR[0]


def loop(turns, shrink=0.0, points=150):
    """A circle of radius 0.1 (in V/V_MAX, F*/span) about (0.5, 0.3), from
    its rightmost point, with the radius shrinking by `shrink` per turn."""
    t = np.linspace(0.0, 2 * np.pi * turns, points)
    r = 0.1 * (1 - shrink * t / (2 * np.pi))
    return (0.5 + r * np.cos(t)) * VS, (0.3 + r * np.sin(t)) * FS


def test_a_curve_traced_past_its_start_closes():
    assert torus.closes(*loop(1.5))


def test_an_open_arc_does_not_close():
    assert not torus.closes(*loop(0.9))


def test_a_spiral_passing_a_step_inside_its_start_does_not_close():
    # one turn moves the radius by 0.004, about the step's length (0.1 x 2 pi / 100)
    assert not torus.closes(*loop(1.5, shrink=0.04))


class _Run:
    """A stand-in for a run's diagram: run[0] is its branch of (V, F*)."""

    def __init__(self, V, Fstar):
        self.branch = {"V": V, "Fstar": Fstar}

    def __getitem__(self, k):
        return self.branch

    def __call__(self):
        return [None]


@pytest.fixture
def fake_runs(monkeypatch):
    """torus_curve with its AUTO runs faked: the start, an open arc up and a
    down run that fails the way a non-finite solution does."""
    made = []

    def run(rundir, name, *args, **kw):
        made.append(name)
        if name.endswith("_down"):
            raise runerror.RunError(f"run {name}: non-finite solution (component 1)")
        return _Run(*loop(0.4))
    monkeypatch.setattr(torus.ct, "run", run)
    monkeypatch.setattr(torus, "seeded", lambda *a, **k: None)
    return made


class _TR:
    PAR = {"PAR(12)": 1.0}


def test_a_direction_that_fails_is_left_out_and_the_other_kept(fake_runs, capsys):
    runs = torus.torus_curve("unused", "torus3", _TR())
    assert fake_runs == ["torus3_start", "torus3_up", "torus3_down"] and len(runs) == 1
    assert "REPORTED: torus curve torus3: one direction left out: run torus3_down" \
        in capsys.readouterr().out


def test_both_directions_failing_is_an_error(fake_runs, monkeypatch):
    def run(rundir, name, *args, **kw):
        if name.endswith(("_up", "_down")):
            raise runerror.RunError(f"run {name}: no convergence (MX)")
        return _Run(*loop(0.4))
    monkeypatch.setattr(torus.ct, "run", run)
    with pytest.raises(runerror.RunError, match="torus3_up"):
        torus.torus_curve("unused", "torus3", _TR())
