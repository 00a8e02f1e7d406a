"""fig11.plane.distance and on_curves: a point is measured against a
branch's chords, so a point between two steps of a coarse curve (a torus
curve's steps reach 5 m/s) lies on it, as at rho = 15, mu = -5 deg, where
the crossing at (385.26 m/s, F* = 0.4375) lay 6.6e-4 from the torus curve's
chord but 3.1e-3 from its nearest point, and started a second run of it."""
from mlgshimmy.figures.fig11.plane import F_MAX, V_MAX, distance, on_curves

TORUS = {"V": [382.13515293, 387.08968357, 392.04370445],
         "Fstar": [0.43018337, 0.43804475, 0.44615493]}   # three steps of that curve


def test_a_point_between_two_steps_is_measured_to_the_chord():
    point = {"V": 385.26468134, "Fstar": 0.4375}
    assert abs(distance(point, TORUS) - 6.6e-4) < 0.2e-4
    assert on_curves(point, [[TORUS]], 0.002)


def test_beyond_a_branch_end_the_distance_is_to_the_end():
    point = {"V": 392.04370445 + 0.003 * V_MAX, "Fstar": 0.44615493}
    assert abs(distance(point, TORUS) - 0.003) < 1e-12
    assert not on_curves(point, [[TORUS]], 0.002)


def test_a_one_point_branch_and_a_point_off_the_curve():
    assert abs(distance({"V": 0.0, "Fstar": 0.0}, {"V": [0.3 * V_MAX], "Fstar": [0.4 * F_MAX]})
               - 0.5) < 1e-12
    assert not on_curves({"V": 385.26, "Fstar": 0.46}, [[TORUS]], 0.002)
