"""Freeplay magnitude (shared/yfp_runs.py, shared/kappa_criterion.py; Figs. 13-19),
fast checks: with eps = 0.1 y_fp the Hopf speeds do not move with y_fp and
the orbits scale linearly with the same frequency (low-frequency branch at
y_fp = 0.5 and 1 mm, V = 15 m/s); with eps = 0.1 mm the y_fp thresholds a, b
at V = 120 m/s (eigenvalue scan) agree with AUTO's Hopf points in y_fp and
with the values reviewed when they were first computed (make report, fig16);
the rescaled profiles of the fixed ratio coincide."""
import math

import numpy
import pytest

import helpers
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import freeplay
from mlgshimmy.shared import spectrum
from mlgshimmy.figures import fig15
from mlgshimmy.shared import kappa_criterion
from mlgshimmy.shared import yfp_runs
from mlgshimmy.shared import mlgmodel

# r_1, r_2 as first reviewed (make report, fig16: F* = 1, eps = 0.1 mm, V = 120 m/s)
A_REPORTED, B_REPORTED = 0.054242, 0.213609


@pytest.fixture(scope="module")
def rundir(tmp_path_factory):
    return str(tmp_path_factory.mktemp("magnitude"))


@pytest.fixture(scope="module")
def k_tlk():
    return mlgmodel.Model("figures")["k_tlk"]


def test_profiles_rescaled_coincide_for_eps_proportional_to_yfp(k_tlk):
    spread = fig15.spread("ratio", (0.2, 0.5, 1.0, 2.0), k_tlk)
    assert spread < 1e-12, f"eps = 0.1 y_fp: spread {spread!r} of the rescaled profiles"


def test_profiles_rescaled_differ_for_fixed_eps(k_tlk):
    spread = fig15.spread("fixed", (0.05, 0.35, 1.0), k_tlk)
    assert spread > 0.1, f"eps = 0.1 mm: spread {spread!r} of the rescaled profiles"


@pytest.fixture(scope="module")
def thresholds():
    """a, b: the first two y_fp at which the high-frequency mode changes
    stability at V = 120 m/s (eps = 0.1 mm, eigenvalue scan)."""
    return kappa_criterion.yfp_crossings(yfp_runs.FSTAR, yfp_runs.V_LIMIT, "high")[:2]


def test_thresholds_a_and_b_at_v_120_as_reported(thresholds):
    a, b = thresholds
    helpers.assert_close(a, A_REPORTED, rel=2e-5)
    helpers.assert_close(b, B_REPORTED, rel=2e-5)


@pytest.mark.parametrize("which", ["a", "b"])
def test_thresholds_agree_with_auto_hopf_point_in_yfp(rundir, thresholds, which):
    y = thresholds["ab".index(which)]
    vals = {"Fstar": yfp_runs.FSTAR, "V": yfp_runs.V_LIMIT, **freeplay.SCALINGS["fixed"]}
    hb = ct.hopf_point(rundir, f"hb_{which}", "figures", "yfp", y, width=0.05 * y, **vals)
    helpers.assert_close(hb["yfp"], y, rel=1e-5)


def test_thresholds_straight_rolling_stable_up_to_120_just_below_a(thresholds):
    a = thresholds[0]
    unstable = [V for V in numpy.linspace(yfp_runs.V_MIN, yfp_runs.V_LIMIT, 25)
                if not max(kappa_criterion.growth(yfp_runs.FSTAR, 0.99 * a, V).values()) < 0]
    assert not unstable, f"eps = 0.1 mm, y_fp = 0.99 a: unstable at V = {unstable}"


def low_branch(rundir, yfp):
    """(Hopf speeds, the orbit at V = 15 m/s on the branch born at the first
    Hopf point) at this y_fp, eps = 0.1 y_fp."""
    vals = yfp_runs.values("ratio", yfp)
    hopf = [v for v, kind, _ in spectrum.stability_changes("figures", "V", yfp_runs.V_SCAN, **vals)
            if kind == "HB"]
    hb = ct.hopf_point(rundir, f"hb_{yfp:g}", "figures", "V", hopf[0], **vals)
    run = ct.periodic_from(rundir, f"po_{yfp:g}", hb, stop={"V": 15.5}, UZR={"V": [15.0]},
                           expect=["UZ"], DS=1e-4, DSMAX=yfp_runs.DSMAX_V, DSMIN=1e-9,
                           THU=yfp_runs.THU)
    return hopf, run("UZ1")


@pytest.fixture(scope="module")
def low_branches(rundir):
    """low_branch at y_fp = 0.5 and 1 mm."""
    return low_branch(rundir, 0.5), low_branch(rundir, 1.0)


def test_linear_scaling_hopf_speeds_do_not_move_with_yfp(low_branches):
    (hopf_half, _), (hopf_one, _) = low_branches
    assert hopf_half and hopf_one
    for k, (h, g) in enumerate(zip(hopf_half, hopf_one)):
        assert math.isclose(h, g, rel_tol=1e-9), \
            f"Hopf speed {k + 1}: {h!r} at y_fp = 0.5, {g!r} at 1 mm (rel 1e-9)"


def test_linear_scaling_psi_amplitude_at_v_15_doubles_from_yfp_half_to_1(low_branches):
    (_, half), (_, one) = low_branches
    helpers.assert_close(one["psi_amp"] / half["psi_amp"], 2.0, rel=1e-4)


def test_linear_scaling_frequency_at_v_15_independent_of_yfp(low_branches):
    (_, half), (_, one) = low_branches
    helpers.assert_close(one["freq"], half["freq"], rel=1e-4)
