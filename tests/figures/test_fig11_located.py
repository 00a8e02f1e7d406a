"""Fig. 11's located codimension-two points (figures/fig11/located.py) on
synthetic input, no AUTO run: a fold curve's end is a GH point only near
a located one, the sign of l2 from the side the fold curve leaves on
against the computed l2, and one entry per point where two curves both
locate it."""
import pytest

from mlgshimmy.figures.fig11 import ends, located

GH = {"type": "GH", "V": 40.4767, "Fstar": 1.37361, "curve": "hopf1", "omega": 60.0,
      "l1": 0.0, "l2": -2.5e4, "dl1_db": 745.0, "a2": -1.3e-5}


def fold(Vs, Fs):
    """A stored fold curve ending (MX) at its last point."""
    return [{"columns": {"V": list(Vs), "Fstar": list(Fs)}, "stable": [True] * len(Vs),
             "labels": [[len(Vs) - 1, 9, "MX"]]}]


def test_a_fold_curves_end_is_a_gh_point_only_within_the_fold_tolerance():
    """ends.FOLD_TOL = 0.002 in V/600 and F*/3.5: 0.6 m/s off the GH point
    is on it, 1.5 m/s off is not."""
    at_gh = located.at_gh([GH], ends.FOLD_TOL)
    near = {"V": GH["V"] + 0.6, "Fstar": GH["Fstar"], "curve": "fold7"}
    far = {"V": GH["V"] + 1.5, "Fstar": GH["Fstar"], "curve": "fold8"}
    found = ends.explained([near, far], None, None, at_gh=at_gh)
    assert found["generalised_hopf"] == [near] and found["open"] == [far]


@pytest.mark.parametrize("above, sign", [(True, -1), (False, +1)])
def test_l2_sign_from_the_side_the_fold_curve_leaves_on(above, sign):
    """l1 rises with F* through the GH point (subcritical above it): a fold
    curve of orbits that leaves on the side above has l1 > 0 there, so
    l1 l2 < 0 gives l2 < 0; leaving below, l2 > 0, which the point's
    computed l2 < 0 contradicts."""
    step = 0.01 if above else -0.01
    Fs = [GH["Fstar"] + step * k for k in (5, 4, 3, 2, 1, 0)]
    Vs = [GH["V"] + 0.5 * k for k in (5, 4, 3, 2, 1, 0)]
    point = dict(GH)
    stop = {"V": Vs[-1], "Fstar": Fs[-1], "curve": "fold1"}
    located.l2_signs([point], [fold(Vs, Fs)], [stop])
    assert point["l2_sign"] == sign and point["l2_from"] == "fold1"
    text = located.coefficient(point)
    assert "l2 = -2.5e+04" in text
    assert f"says l2 {'< 0' if sign < 0 else '> 0'}: {'agrees' if above else 'DISAGREES'}" in text


def test_a_point_two_curves_locate_is_listed_once():
    """Two located GH points 1e-6 apart (in V/600, F*/3.5) are one
    (located.SAME); a ZH point at the same place is another point."""
    twin = {**GH, "V": GH["V"] + 6e-4, "curve": "hopf2"}
    zh = {**GH, "type": "ZH"}
    assert located.distance(GH, twin) < located.SAME
    assert located.once([GH, twin, zh]) == [GH, zh]


def line(a, b, n):
    """n points from a to b, (V, F*) pairs."""
    return [(a[0] + (b[0] - a[0]) * k / (n - 1), a[1] + (b[1] - a[1]) * k / (n - 1))
            for k in range(n)]


def stored(points, label="EP"):
    Vs, Fs = zip(*points)
    return {"columns": {"V": list(Vs), "Fstar": list(Fs)}, "stable": [True] * len(Vs),
            "labels": [[len(Vs) - 1, 9, label]]}


def test_a_fold_curve_that_retraces_itself_past_a_gh_point_is_cut_there():
    """fold1+ runs from its start (100, 1.0) down to the GH point at
    (110, 0.8), back through its start and on to (50, 2.0), where fold1-
    ends too: cut at the GH point, which becomes its MX end; fold1- and a
    curve that passes the GH point into new ground stay whole."""
    start, gh, edge = (100.0, 1.0), (GH["V"], GH["Fstar"]), (50.0, 2.0)
    gh_point = dict(GH)
    plus = stored(line(start, gh, 11) + line(gh, start, 11)[1:] + line(start, edge, 21)[1:])
    minus = stored(line(start, edge, 21))
    onward = stored(line((90.0, 1.2), gh, 6) + line(gh, (300.0, 0.3), 30)[1:])
    out = located.retraced_past_gh([[plus, minus], [onward]], [gh_point], ends.FOLD_TOL)
    cut = out[0][0]
    assert len(cut["columns"]["V"]) == 11
    assert (cut["columns"]["V"][-1], cut["columns"]["Fstar"][-1]) == pytest.approx(gh)
    assert cut["labels"][-1] == [10, 9, "MX"]
    assert out[0][1] is minus and out[1][0] is onward
