"""torus.closes: a torus curve run that comes back through its first two
points is a closed curve (an isola in (V, F*), as the tongue at F* ~ 0.69
at rho = 20, mu = 5 deg), and the other direction is not run; an open arc,
or a spiral that passes its start one step-width off, is not closed."""
import numpy as np

from mlgshimmy.shared import torus

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
