"""kappa_criterion.unstable_windows: the bands of y_fp in which the
high-frequency mode of straight rolling is unstable for some V <= 120 m/s
(Fig. 18's a, b and what lies between them).  At rho = 15, mu = -5 deg,
F* = 0.1, a's window ends near 0.288 mm and the mode is unstable again
from about 1.21 mm (b lies beyond the scan); at F* = 1 there is one
window, from a to b."""
import numpy

from mlgshimmy.shared import gear, geometry
from mlgshimmy.shared import kappa_criterion as kc
from mlgshimmy.shared import yfp_runs

MODEL = gear.Gear(geometry.Geometry(15.0, -5.0, 2)).parameters()
SPEEDS = numpy.linspace(yfp_runs.V_MIN, yfp_runs.V_LIMIT, 60)   # twice the windows' own grid


def worst(Fstar, yfp):
    return max(kc.growth(Fstar, yfp, V, **MODEL)["high"] for V in SPEEDS)


def test_a_stable_band_between_a_and_b_is_found():
    windows = kc.unstable_windows(0.1, "high", **MODEL)
    assert len(windows) == 2 and windows[1][1] == numpy.inf
    (a, end), (start, _) = windows
    assert abs(a - kc.extreme_yfp_crossing(0.1, "high", **MODEL)[0]) < 1e-8
    assert abs(end - 0.288) < 0.005 and abs(start - 1.21) < 0.02, windows
    # stable at every speed inside the band, unstable just outside it
    for y in numpy.geomspace(1.05 * end, 0.95 * start, 6):
        assert worst(0.1, y) < 0, y
    assert worst(0.1, 0.95 * end) > 0 and worst(0.1, 1.05 * start) > 0


def test_one_window_runs_from_a_to_b():
    point = kc.window_points(1.0, **MODEL)
    (a, b), = kc.unstable_windows(1.0, "high", **MODEL)
    assert abs(a - point["a"]) < 1e-8 and abs(b - point["b"]) < 1e-8
