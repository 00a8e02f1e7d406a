"""Tests of shared/boundary_equilibria.py: the boundary-equilibrium points
(BEPs) of eq. (14) where the yawed states of Fig. 12 (V = 50 m/s, y_fp =
1 mm) meet the contact surfaces h+- = 0, checked against what does not use
their solver: finite differences of its equations, the other mode's Newton,
each mode's equilibria solved at loads beside the BEP, the gap mode's
independence of y_fp, and the smoothed law's yawed states.  A few seconds.

Run: /usr/bin/python3 -m pytest -q tests/model/test_boundary_equilibria.py
"""
import numpy as np
import pytest

from helpers import assert_close
from mlgshimmy.shared import boundary_equilibria as be
from mlgshimmy.shared import convergence, mlgmodel

LAW14 = mlgmodel.LAWS.index("nonsmooth")
VALUES = {"V": 50.0, "yfp": 1.0, "eps_abs": 0.0, "eps_rel": 0.0, "freeplay_law": LAW14}
LOADS = np.linspace(0.02, 3.5, 175)      # F*: Fig. 12's range
GAP, CONTACT_POS = 0, 1


@pytest.fixture(scope="module")
def points():
    return be.from_pitchforks(VALUES, "Fstar", LOADS)


def upper(points):
    return [p for p in points if p["surface"] == "freeplay_upper"]


def model_at(Fstar, **changed):
    return mlgmodel.Model("figures", **{**VALUES, "Fstar": Fstar, **changed})


def test_two_pitchforks_give_four_beps_mirrored_in_psi(points):
    """Two pitchforks of straight rolling in the gap (F* 0.025 and 0.44),
    each yawed pair reaching h+ = 0 and h- = 0 at one load, psi mirrored."""
    assert len(points) == 4, [(p["pitchfork"], p["surface"]) for p in points]
    for plus, minus in zip(points[::2], points[1::2]):
        assert (plus["surface"], minus["surface"]) == ("freeplay_upper", "freeplay_lower")
        assert_close(plus["Fstar"], minus["Fstar"], rel=1e-13)
        assert_close(plus["psi"], -minus["psi"], rel=1e-12)


@pytest.mark.parametrize("mode", (GAP, CONTACT_POS))
def test_the_equations_jacobian_against_central_differences(points, mode):
    """DG of (f_mode(u; F*), h+(u)) against central differences at the BEP
    (each mode continued across h = 0: smooth there), column by column
    (steps 1e-5 of each value, at least 1e-8): measured 5.6e-8 in both
    modes (the rounding of the eta_dot column, whose step is the floor); a
    1e-3 change of any column exceeds the tolerance."""
    p = upper(points)[1]
    x = np.r_[p["u"], p["Fstar"]]
    G, DG = be.system(model_at(p["Fstar"]), mode, p["surface"], p["u"], "Fstar")
    differences = np.empty_like(DG)
    for j in range(len(x)):
        h = 1e-5 * max(abs(x[j]), 1e-3)
        side = []
        for sign in (1.0, -1.0):
            y = x.copy()
            y[j] += sign * h
            side.append(be.system(model_at(y[-1]), mode, p["surface"], y[:-1], "Fstar")[0])
        differences[:, j] = (side[0] - side[1]) / (2 * h)

    def error(jacobian):
        return max(np.max(np.abs(differences[:, j] - jacobian[:, j]))
                   / max(np.max(np.abs(differences[:, j])), 1e-300) for j in range(len(x)))
    assert error(DG) < 1e-6, f"largest relative column error {error(DG):.3g}"
    for j in range(len(x)):
        wrong = DG.copy()
        wrong[:, j] *= 1.0 + 1e-3
        assert error(wrong) > 1e-6, j


def test_the_bep_is_one_point_of_both_modes(points):
    """Eq. (14)'s force vanishes on h = 0: Newton in contact+ from the gap's
    start reaches the same point, where both modes' fields vanish."""
    for p in upper(points):
        model = model_at(p["pitchfork"])
        start = p["u"].copy()
        start[be.PSI] *= 1.0 + 1e-3
        other = be.solve(model, CONTACT_POS, p["surface"], start, "Fstar")
        assert_close(other["Fstar"], p["Fstar"], rel=1e-12)
        assert np.max(np.abs(other["u"] - p["u"])) < 1e-12
        for mode in (GAP, CONTACT_POS):
            f, _ = model_at(p["Fstar"]).jacobian_in_mode(p["u"], mode)
            assert np.max(np.abs(f)) < 1e-8, (mode, f)
        h, _ = model_at(p["Fstar"]).switching(p["u"])["freeplay_upper"]
        assert abs(h) < 1e-15, h


def test_persistence_each_mode_admissible_on_the_side_it_is_said_to_be(points):
    """The gap's yawed state and the contact+ state, each solved in its
    mode at loads 0.3 of the BEP's distance from its pitchfork on either
    side: admissible (h+ < 0 in the gap, > 0 in contact) on the side
    classify gives, virtual on the other; opposite sides: persistence, the
    yawed branch crossing into contact (from P1 upwards, from P2 down)."""
    for p in upper(points):
        assert p["kind"] == "persistence", p
        assert p["sides"]["gap"] == -p["sides"]["contact+"]
        assert p["sides"]["gap"] == np.sign(p["pitchfork"] - p["Fstar"]), p
        step = 0.3 * abs(p["pitchfork"] - p["Fstar"])
        for mode, name, admissible in ((GAP, "gap", -1), (CONTACT_POS, "contact+", 1)):
            for side in (1, -1):
                model = model_at(p["Fstar"] + side * step)
                u = be.equilibrium_in_mode(model, mode, p["u"])
                h, _ = model.switching(u)["freeplay_upper"]
                expected = admissible if side == p["sides"][name] else -admissible
                assert np.sign(h) == expected, (p["Fstar"], name, side, h)


def test_the_distance_from_pitchfork_to_bep_scales_as_yfp_squared(points):
    """The gap mode does not depend on y_fp (no link force there), so its
    yawed branch F*(psi) = F*_P - c psi^2 + O(psi^4) is the same at every
    freeplay and reaches the surface at psi ~ y_fp: halving y_fp quarters
    F*_P - F*_BEP (measured 4.0005 and 4.0035)."""
    half = be.from_pitchforks({**VALUES, "yfp": 0.5}, "Fstar", LOADS)
    for p, q in zip(upper(points), upper(half)):
        assert_close(q["pitchfork"], p["pitchfork"], rel=1e-12)
        assert_close((p["pitchfork"] - p["Fstar"]) / (q["pitchfork"] - q["Fstar"]), 4.0,
                     rel=2e-3)


def test_the_smoothed_yawed_state_approaches_the_bep_at_order_one(points):
    """Eq. (15) at the BEP's load: its yawed state lies inside the gap, at
    a distance C eps from the surface (the smoothing's tail k eps^3 / (3 pi
    x^2) balancing the gap's weak moment puts it x ~ eps from the corner);
    fitted order 1.02 over eps / y_fp = 0.0005-0.002."""
    smoothed = {**VALUES, "freeplay_law": mlgmodel.LAWS.index("atan")}
    for p in upper(points):
        found = be.smoothed_approach(smoothed, p, "Fstar", (0.0005, 0.001, 0.002))
        assert len(found) == 3, found
        fit = convergence.fitted_order([a["ratio"] for a in found], [a["gap"] for a in found],
                                       0.0)
        assert_close(fit["p"], 1.0, abs=0.05)


def test_a_smoothed_law_is_refused_naming_the_parameter():
    with pytest.raises(ValueError, match="freeplay_law"):
        be.from_pitchforks({**VALUES, "freeplay_law": 0, "eps_rel": 0.1}, "Fstar", LOADS)


def test_a_parameter_that_h_contains_is_refused_naming_it(points):
    """h+- contains y_fp: the system's Jacobian would miss dh/dy_fp."""
    p = points[0]
    with pytest.raises(ValueError, match="'yfp'"):
        be.system(model_at(p["Fstar"]), GAP, p["surface"], p["u"], "yfp")


def test_the_gap_branch_from_the_bep_is_the_pitchfork_s_parabola(points):
    """branch_in_psi: the gap's yawed states with psi held, F* free, from
    the BEP towards its pitchfork: F*_P - F* ~ c psi^2, so at half the
    BEP's psi a quarter of F*_P - F*_BEP (measured 4e-4 and 9e-4 off,
    relative: the psi^4 term), and y_tlk / y_fp half of the BEP's 1 (1.5e-4,
    5e-6: r_tlk moves with eta)."""
    for p in upper(points):
        model = model_at(p["Fstar"])
        (F, y), = be.branch_in_psi(model, p, "Fstar", [0.5 * p["psi"]])
        assert_close((p["pitchfork"] - F) / (p["pitchfork"] - p["Fstar"]), 0.25, rel=2e-3)
        assert_close(y, 0.5, rel=1e-3)
