"""Fig. 18's AUTO check of a window point where AUTO cannot continue its
curve of Hopf points (yfp_runs.window_point_values): at rho = 15 deg,
mu = -5 deg (complete equations), F* = 1, the window point b's straight
rolling holds the torque links within two smoothing widths of the freeplay
corner, closer than the state step AUTO's Hopf-curve system differences
with, 1e-7 (1 + omega^2); located by a one-parameter run instead, AUTO's
Hopf point equals the eigenvalue scan's within 1e-6 mm."""
import numpy as np
import pytest

from mlgshimmy.shared import domain, freeplay, geometry, kappa_criterion, mlgmodel, yfp_runs
from mlgshimmy.shared.freeplay import SCALINGS

GEOMETRY = geometry.Geometry(15.0, -5.0, 2)
FSTAR = 1.0


@pytest.fixture(scope="module")
def point():
    return kappa_criterion.window_points(FSTAR, **GEOMETRY.parameters())


def test_b_sits_on_the_freeplay_corner_closer_than_autos_hopf_step(point):
    model = mlgmodel.Model("figures", Fstar=FSTAR, V=yfp_runs.V_LIMIT, yfp=point["b"],
                           **SCALINGS["fixed"], **GEOMETRY.parameters())
    u = model.equilibrium()
    depth = abs(geometry.y_tlk(model, u)) - point["b"] * 1e-3      # m, < 0 inside the gap
    assert -2 * freeplay.EPSILON * 1e-3 < depth < 0
    rates = np.linalg.eigvals(model.jacobian(u))
    crossing = min((r for r in rates if r.imag > 0), key=lambda r: abs(r.real))
    assert abs(crossing.real) < 1e-6
    step = 1e-7 * (1 + crossing.imag ** 2)                          # rad, AUTO's FNHBF
    r_tlk = domain.diagnose(model, u)["r_tlk"]                      # m per rad of twist
    assert r_tlk * step > freeplay.EPSILON * 1e-3


def test_b_located_by_a_one_parameter_run_equals_the_scan(point, tmp_path):
    (F, found, scan), = yfp_runs.window_point_values(str(tmp_path), "b_at", "b", [point],
                                                     **GEOMETRY.parameters())
    assert F == FSTAR and scan == point["b"]
    assert abs(found - scan) < 1e-6
