"""The allowable-freeplay criterion (studies/criterion.py, eq. 17), fast
checks: straight rolling depends on the freeplay only through y_fp/eps;
the scan's first instability at the minimum load of variant 0 equals the
band-by-band scan of Fig. 18 and the documented kappa*; the stage-switch
family keeps the spring monotone, is the default at eta_s = 0.34 m and
meets the printed stage order (variant 1) at light load as eta_s -> 0."""
import math

import numpy
import pytest

from mlgshimmy.shared import freeplay
from mlgshimmy.shared import kappa_criterion
from mlgshimmy.shared import rolling_state
from mlgshimmy.shared import stage_switch
from mlgshimmy.shared import yfp_runs
from mlgshimmy.shared import mlgmodel
from mlgshimmy.studies import criterion

# the value reviewed when the criterion was written (make report: fig18 and the
# criterion table; build/tables/criterion.txt): kappa* = 0.3651 at F* = 0.295 (variant 0)
KAPPA_REPORTED, FSTAR_REPORTED = 0.3651, 0.295


def eigenvalues(**values):
    model = mlgmodel.Model("figures", **values)
    return numpy.sort_complex(numpy.linalg.eigvals(numpy.array(
        model.jacobian(model.equilibrium()))))


@pytest.mark.parametrize("variant", (0, 1))
@pytest.mark.parametrize("yfp, eps", ((0.04, 0.1), (0.3, 0.1), (1.0, 0.1)))
def test_jacobian_spectrum_depends_on_the_freeplay_only_through_r(variant, yfp, eps):
    """(y_fp, eps) and (2 y_fp, 2 eps) give the same spectrum, both strut
    variants, inside and outside the freeplay-dominated range of r."""
    one = eigenvalues(Fstar=0.3, V=120.0, yfp=yfp, eps_abs=eps, eps_rel=0.0,
                      strut_variant=variant)
    two = eigenvalues(Fstar=0.3, V=120.0, yfp=2 * yfp, eps_abs=2 * eps, eps_rel=0.0,
                      strut_variant=variant)
    diff = numpy.max(numpy.abs(one - two)) / numpy.max(numpy.abs(one))
    assert diff <= 1e-12, \
        f"r-invariance, variant {variant}, r = {yfp / eps:g}: largest relative change {diff:.3g}"


@pytest.fixture(scope="module")
def first_at_reported():
    """The criterion's single scan (any eigenvalue) at the documented minimum."""
    return criterion.first_unstable(FSTAR_REPORTED)


def test_kappa_first_instability_equals_fig18_scan(first_at_reported):
    """The first instability at F* = 0.295 equals Fig. 18's scan (its a, c,
    pitchfork) [mm]."""
    bands = kappa_criterion.window_points(FSTAR_REPORTED)
    assert math.isclose(first_at_reported["first"], bands["first"], rel_tol=1e-8), \
        f"criterion {first_at_reported['first']!r}, Fig. 18's scan {bands['first']!r}"


def test_kappa_star_of_variant_0_is_the_documented_one(first_at_reported):
    kappa = first_at_reported["first"] / freeplay.EPSILON
    assert math.isclose(kappa, KAPPA_REPORTED, rel_tol=2e-4), \
        f"kappa* {kappa!r}, docs {KAPPA_REPORTED!r}"


def test_kappa_first_instability_scales_with_eps(first_at_reported):
    """The criterion at eps = 0.02 mm (the model's eps_abs overridden): at
    the paper's gear straight rolling depends on y_fp/eps alone, so the
    first instability moves to a fifth and kappa* stays (docs/model.md 9.3)."""
    scaled = kappa_criterion.least_unstable(FSTAR_REPORTED, eps_abs=0.02)
    assert math.isclose(scaled["first"], 0.2 * first_at_reported["first"], rel_tol=1e-7), \
        f"{scaled['first']!r} mm at eps = 0.02 mm, {first_at_reported['first']!r} at 0.1"
    kappa, _ = kappa_criterion.kappa_star(lambda F: scaled, [FSTAR_REPORTED, FSTAR_REPORTED + 0.1],
                             {"eps_abs": 0.02}, finer=())
    assert math.isclose(kappa, first_at_reported["first"] / freeplay.EPSILON, rel_tol=1e-7)


@pytest.mark.parametrize("F", (FSTAR_REPORTED - 0.005, FSTAR_REPORTED + 0.005))
def test_kappa_minimum_is_local(first_at_reported, F):
    """F* = 0.290 and 0.300 need a larger y_fp/eps than F* = 0.295."""
    other = kappa_criterion.extreme_yfp_crossing(F, "any")[0]
    assert other > first_at_reported["first"], \
        f"F* = {F:.3f}: {other:.6g} <= {first_at_reported['first']:.6g} mm"


def test_stage_switch_default_is_0_34_m():
    assert mlgmodel.Model()["eta_stage"] == 0.34, mlgmodel.Model()["eta_stage"]


@pytest.mark.parametrize("eta_s", criterion.STAGE_SWITCHES)
def test_stage_switch_family_keeps_eta_star_increasing(eta_s):
    """eta* rises with F* (a monotone spring) for every eta_s in STAGE_SWITCHES."""
    loads = numpy.linspace(0.1, 2.0, 39)
    eta = [mlgmodel.Model(Fstar=F, eta_stage=eta_s).equilibrium()["eta"] for F in loads]
    assert numpy.all(numpy.diff(eta) > 0), f"eta_s = {eta_s:g}: eta* = {numpy.round(eta, 5)}"


@pytest.mark.parametrize("F", (0.2, 0.4, 0.6))
def test_stage_switch_at_zero_is_variant_1_at_light_load(F):
    """eta* at eta_s = 0 against variant 1 [m]: both hang on the top-out
    term; the soft stage's switched-off tail (weight ~ 1/(pi k_stage eta))
    moves eta* by ~1e-5 m."""
    family = mlgmodel.Model(Fstar=F, eta_stage=0.0).equilibrium()["eta"]
    printed = mlgmodel.Model(Fstar=F, strut_variant=1).equilibrium()["eta"]
    assert math.isclose(family, printed, abs_tol=1e-4), \
        f"F* = {F}: eta_s = 0 gives {family!r}, variant 1 {printed!r}"


def test_stage_switch_at_zero_first_instability_is_variant_1s():
    """The first instability at F* = 0.3, eta_s = 0 against variant 1 [mm]."""
    family = kappa_criterion.extreme_yfp_crossing(0.3, "any", eta_stage=0.0)[0]
    printed = kappa_criterion.extreme_yfp_crossing(0.3, "any", strut_variant=1.0)[0]
    assert math.isclose(family, printed, rel_tol=1e-3), \
        f"eta_s = 0: {family!r}, variant 1: {printed!r}"


@pytest.mark.parametrize("name, value, what", (
    ("F_tyre_min", -1.0, "negative F_tyre_min"),
    ("eta_stage", -0.05, "stage switch eta_stage below the stroke"),
    ("eta_stage", 0.7, "stage switch eta_stage beyond z_tlk0")))
def test_bad_criterion_parameter_rejected_by_name(name, value, what):
    with pytest.raises(ValueError) as error:
        mlgmodel.Model(**{name: value}).check()
    assert f"parameter {name} = {value:g}" in str(error.value), f"{what}: {error.value}"


def test_a_band_unstable_at_the_scan_floor_is_followed_to_zero_freeplay():
    """Printed strut, c_psi = 410 (Table 1), F* = 0.2, V = 90 m/s: the
    high-frequency mode is unstable already without freeplay, so its first
    crossing is y_fp = 0 (kappa* = 0), not the scan's first grid point
    YFP_MIN (what the scan reported before: kappa* = 0.050)."""
    model = dict(strut_variant=1.0, c_psi=410.0)
    assert kappa_criterion.growth(0.2, 0.0, 90.0, **model)["high"] > 0
    assert kappa_criterion.yfp_crossings(0.2, 90.0, "high", first_only=True, **model) == [0.0]


def test_a_crossing_below_the_scan_floor_is_bisected():
    """rho = mu = 10 deg, eta_s = 0, F* = 0.16, V = 7.5 m/s: the
    high-frequency mode turns unstable between zero freeplay and YFP_MIN;
    the crossing found there has the growth change sign across it
    (1e-6 relative)."""
    model = dict(rho=math.radians(10), mu=math.radians(10), eom_terms=2.0, eta_stage=0.0)
    y, = kappa_criterion.yfp_crossings(0.16, 7.5, "high", first_only=True, **model)
    assert 0.0 < y < yfp_runs.YFP_MIN
    assert kappa_criterion.growth(0.16, y * (1 - 1e-6), 7.5, **model)["high"] < 0
    assert kappa_criterion.growth(0.16, y * (1 + 1e-6), 7.5, **model)["high"] > 0


def test_the_stage_switch_loads_put_the_strut_on_its_switch():
    """stage_switch_loads spans the loads where eta* crosses the oleo's stage
    switch: eta* within 3 / k_stage of eta_s at its ends, below and above
    eta_s at its ends in turn (default strut, F* about 0.63-0.69)."""
    loads = stage_switch.stage_switch_loads(criterion.LOADS)
    model = mlgmodel.Model("figures")
    eta_s, width = model["eta_stage"], stage_switch.SWITCH_WIDTHS / model["k_stage"]
    etas = [rolling_state.rolling_state(F, 0.0)["eta"] for F in loads]
    assert len(loads) == stage_switch.SWITCH_LOADS and 0.6 < loads[0] < loads[-1] < 0.72, loads
    assert math.isclose(etas[0], eta_s - width, abs_tol=1e-7), etas
    assert math.isclose(etas[-1], eta_s + width, abs_tol=1e-7), etas


def test_the_stage_switch_window_at_side_stay_angles_is_where_eta_crosses_its_widths():
    """stage_switch_window at rho = mu = 10 deg, 10 widths (Fig. 11's):
    eta* of straight rolling at its ends is eta_s -+ 10 / k_stage, and the
    window holds the 3-width one of stage_switch_loads."""
    geometry = dict(rho=math.radians(10), mu=math.radians(10), eom_terms=2.0)
    lo, hi = stage_switch.stage_switch_window(0.02, 3.5, 10.0, **geometry)
    model = mlgmodel.Model("figures", **geometry)
    eta_s, width = model["eta_stage"], 10.0 / model["k_stage"]
    assert math.isclose(stage_switch.zero_freeplay_eta(lo, **geometry), eta_s - width, abs_tol=1e-7)
    assert math.isclose(stage_switch.zero_freeplay_eta(hi, **geometry), eta_s + width, abs_tol=1e-7)
    narrow = stage_switch.stage_switch_loads(criterion.LOADS, **geometry)
    assert lo < narrow[0] < narrow[-1] < hi < 0.72, (lo, hi, narrow)
    assert stage_switch.stage_switch_window(0.8, 3.5, 10.0, **geometry) is None


def test_on_the_stage_switch_at_side_stay_angles_kappa_is_zero_and_the_switch_decides():
    """rho = mu = 10 deg, default strut, on the stage switch: straight rolling
    is unstable without freeplay (kappa* = 0 there, docs/design-map.md);
    with a switch ten times less steep (k_stage = 1e4 /m) it is not."""
    geometry = dict(rho=math.radians(10), mu=math.radians(10), eom_terms=2.0)
    loads = stage_switch.stage_switch_loads(criterion.LOADS, **geometry)
    middle = loads[stage_switch.SWITCH_LOADS // 2]
    assert kappa_criterion.least_unstable(middle, **geometry)["first"] == 0.0
    softer = stage_switch.stage_switch_loads(criterion.LOADS, k_stage=1e4, **geometry)
    # y_fp [mm]: kappa = 0.48 there
    assert kappa_criterion.least_unstable(softer[len(softer) // 2], k_stage=1e4,
                                          **geometry)["first"] > 0.01
