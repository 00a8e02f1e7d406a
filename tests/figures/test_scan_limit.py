"""Fig. 18's b (the largest y_fp with the high-frequency mode unstable for
some V <= 120 m/s) is infinite where the mode is still unstable at the
scan's end YFP_MAX: the scan's limit is never printed as a value.  At
rho = 15, mu = -5 deg the mode stays unstable past 2 mm at F* = 1.9 and
restabilises at about 1.144 mm at F* = 1."""
import numpy

from mlgshimmy.shared import gear, geometry
from mlgshimmy.shared import kappa_criterion as kc
from mlgshimmy.shared import yfp_runs

MODEL = gear.Gear(geometry.Geometry(15.0, -5.0, 2)).parameters()


def test_b_beyond_the_scan_is_infinite():
    b, V = kc.extreme_yfp_crossing(1.9, "high", highest=True, **MODEL)
    assert b == numpy.inf and yfp_runs.V_MIN <= V <= yfp_runs.V_LIMIT
    # ... because at that speed the mode is unstable at the scan's end
    assert kc.growth(1.9, yfp_runs.YFP_MAX, V, **MODEL)["high"] > 0


def test_b_inside_the_scan_is_its_crossing():
    b, V = kc.extreme_yfp_crossing(1.0, "high", highest=True, **MODEL)
    assert abs(b - 1.1439) < 1e-3 and V == yfp_runs.V_LIMIT, (b, V)
    below, above = (kc.growth(1.0, y, V, **MODEL)["high"] for y in (0.99 * b, 1.01 * b))
    assert below > 0 > above
