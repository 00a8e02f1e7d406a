"""The smoothing error of eq. (15) against eq. (14) (studies.smoothing):
the order fit (shared.convergence) on exact power laws, and the predicted
order 3 of straight rolling's Hopf points, from eq. (15)'s stiffness at
y = 0, (k_tlk / pi) (2 atan r - 2 r / (1 + r^2)) = (4 / 3 pi) r^3 k_tlk
(1 - 6 r^2 / 5 + O(r^4)), r = eps / y_fp; Fig. 12's a_12, b_12 by the
eigenvalue scan against AUTO's; the fit of a limit that is not computed
(the torus points).  The orbits' order (2) is measured by the study itself
(make smoothing: about 15 min).

Run: /usr/bin/python3 -m pytest -q tests/figures/test_smoothing.py
"""
import os

import numpy
import pytest

import helpers
from mlgshimmy.shared import autosession, branches, convergence, mlgmodel, naming, spectrum

REFERENCE = os.path.join(helpers.ROOT, "tests", "reference")

RATIOS = (0.1, 0.05, 0.02, 0.01)


@pytest.mark.parametrize("p, C", [(3.0, 2.5), (2.0, -0.7), (1.0, 1e-6)])
def test_the_fit_recovers_a_power_law(p, C):
    errors = [C * r ** p for r in RATIOS]
    fit = convergence.fitted_order(RATIOS, errors, floor=0.0)
    assert fit["p"] == pytest.approx(p, rel=1e-12)
    assert fit["C"] == pytest.approx(abs(C), rel=1e-10)
    assert fit["points"] == 4


def test_the_fit_leaves_out_what_lies_below_the_floor():
    errors = [0.3 * r ** 3 for r in RATIOS[:2]] + [1e-15, 0.0]
    fit = convergence.fitted_order(RATIOS, errors, floor=1e-12)
    assert fit["points"] == 2 and fit["p"] == pytest.approx(3.0, rel=1e-12)
    assert convergence.fitted_order(RATIOS, [0.0, 0.0, 0.0, 1.0], floor=1e-12) is None


def test_eq15_s_stiffness_at_the_centre_is_of_order_three():
    """The law itself: its stiffness at y = 0 against (4 / 3 pi) r^3."""
    k, yfp, h = 3.9e7, 1e-3, 1e-7
    for r in RATIOS:
        stiffness = (mlgmodel.torque_link_force(0, k, h, yfp, r * yfp)
                     - mlgmodel.torque_link_force(0, k, -h, yfp, r * yfp)) / (2 * h)
        assert stiffness == pytest.approx(4 / (3 * numpy.pi) * r ** 3 * k, rel=1.3 * r ** 2)   # the r^2 term: -6/5


def test_the_hopf_points_converge_to_eq14_s_with_order_three():
    grid = numpy.linspace(0.5, 200.0, 400)
    case = {"Fstar": 1.0, "yfp": 1.0, "eps_abs": 0.0}
    limit = naming.scanned("figures", "V", grid, **case, eps_rel=0.0,
                           freeplay_law=mlgmodel.LAWS.index("nonsmooth"))
    smoothed = [naming.scanned("figures", "V", grid, **case, eps_rel=r) for r in RATIOS]
    for name in ("H1", "H2", "H3"):
        fit = convergence.fitted_order(RATIOS, [s[name] - limit[name] for s in smoothed],
                                       floor=1e-10 * limit[name])
        print(f"# {name}: eq. (14) {limit[name]:.9g} m/s, fitted order {fit['p']:.3f}")
        assert fit["points"] == 4 and fit["p"] == pytest.approx(3.0, abs=0.05)


def test_a12_b12_bounds_are_fig12_s_last_pitchfork_and_hopf_load():
    """spectrum.stable_before_hopf in F* at Fig. 12's values against AUTO's
    labels on straight rolling in Fig. 12's reference set: its second
    pitchfork (BP) and its Hopf point (HB), a_12 and b_12 at the paper's
    gear (the report's fig12 table)."""
    eq = autosession.init().parseB.parseBR(os.path.join(REFERENCE, "fig12", "b.eq"))[0]
    labelled = {name: [eq["Fstar"][k] for k, _, _ in branches.labelled_points(eq, name)]
                for name in ("BP", "HB")}
    a12, b12 = spectrum.stable_before_hopf("figures", "Fstar", numpy.linspace(0.02, 3.5, 175),
                                           V=50.0, yfp=1.0, eps_abs=0.0, eps_rel=0.1)
    assert a12 == pytest.approx(labelled["BP"][-1], rel=1e-7)
    assert b12 == pytest.approx(labelled["HB"][0], rel=1e-7)


def test_extrapolation_recovers_a_limit_that_is_not_computed():
    """convergence.extrapolated: X(0), C and p of X(0) + C r^p together, and
    nothing where the values do not spread beyond their resolution."""
    ratios = (0.2, 0.1, 0.05, 0.02, 0.01)
    fit = convergence.extrapolated(ratios, [570.0 - 0.4 * r ** 2 for r in ratios], 1e-6)
    assert fit["limit"] == pytest.approx(570.0, abs=1e-9)
    assert fit["p"] == pytest.approx(2.0, abs=2.5e-3) and fit["C"] == pytest.approx(-0.4, rel=1e-2)
    assert convergence.extrapolated(ratios, [570.0 + 1e-3 * r for r in ratios], 0.05) is None
