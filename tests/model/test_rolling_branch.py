"""Tests of shared/rolling.py: straight rolling is the equilibrium on the
branch continued from zero freeplay, checked against an independent walk
in small steps (Newton, rolling.solve), its eigenvalues, the state before
the continuation had step control where that state was right, and the
folds of the isola at rho = mu = 10 deg (docs/model.md)."""
import math

import numpy as np
import pytest

from mlgshimmy.shared import mlgmodel, rolling

SIDE = {"rho": math.radians(15.0), "mu": math.radians(-5.0), "eom_terms": 2.0}
TEN = {"rho": math.radians(10.0), "mu": math.radians(10.0), "eom_terms": 2.0}
REL = {"eps_abs": 0.0, "eps_rel": 0.1}
ABS = {"eps_abs": 0.1, "eps_rel": 0.0}
LOADS = np.round(np.arange(0.06, 0.305, 0.02), 2)


def model(Fstar, yfp, epsilon, geometry):
    return mlgmodel.Model("figures", Fstar=Fstar, V=50.0, yfp=yfp, **epsilon, **geometry)


def walked(Fstar, yfp, epsilon, geometry):
    """psi at yfp by Newton from the zero-freeplay state in steps of at most
    0.005 mm and half the smoothing width (the link force changes over it)."""
    u = model(Fstar, 0.0, epsilon, geometry).equilibrium()
    u, y = [u[n] for n in mlgmodel.UNAMES], 1e-6
    while True:
        u = rolling.solve(model(Fstar, y, epsilon, geometry), u)
        assert u is not None, f"F* = {Fstar}: the walk lost the branch at y_fp = {y:.6g} mm"
        if y == yfp:
            return u[0]
        y = min(y + min(0.005, 0.5 * model(Fstar, y, epsilon, geometry).epsilon_m() * 1e3), yfp)


@pytest.mark.parametrize("Fstar", LOADS)
def test_straight_rolling_at_a_side_stay_geometry_is_the_stable_state_of_its_branch(Fstar):
    """(15, -5) deg, y_fp = 1 mm, eps = 0.1 y_fp: the branch from zero freeplay
    ends stable (largest Re lambda -0.0163 to -0.0169 /s at V = 50; the
    isola's middle state at the same freeplay has +2.9 to +4.2 /s)."""
    u = rolling.state("figures", Fstar, 1.0, REL, **SIDE)
    growth = max(np.linalg.eigvals(model(Fstar, 1.0, REL, SIDE).jacobian(u)).real)
    assert growth < -0.01, f"F* = {Fstar}: psi {u['psi']:.6g}, largest Re lambda {growth:.4g} /s"
    assert u["psi"] == pytest.approx(walked(Fstar, 1.0, REL, SIDE), abs=1e-12)


@pytest.mark.parametrize("Fstar", (0.24, 0.26))
def test_the_state_does_not_depend_on_the_freeplays_asked_before(Fstar):
    """A path through y_fp = 0.2, 0.5 mm (cached) reaches the state at 1 and
    1.5 mm that a fresh one does: psi linear in y_fp, about -1.7e-3 rad/mm."""
    key = ("figures", float(Fstar), tuple(sorted(REL.items())), tuple(sorted(SIDE.items())))
    rolling._paths.pop(key, None)
    psi = [rolling.state("figures", Fstar, y, REL, **SIDE)["psi"] for y in (0.2, 0.5, 1.0, 1.5)]
    rolling._paths.pop(key)
    assert rolling.state("figures", Fstar, 1.5, REL, **SIDE)["psi"] == pytest.approx(psi[3],
                                                                                     abs=1e-15)
    assert rolling.state("figures", Fstar, 1.0, REL, **SIDE)["psi"] == pytest.approx(psi[2],
                                                                                     abs=1e-15)
    assert psi[3] == pytest.approx(walked(Fstar, 1.5, REL, SIDE), abs=1e-12)
    slopes = np.diff(psi) / np.diff([0.2, 0.5, 1.0, 1.5])
    assert np.all((-1.8e-3 < slopes) & (slopes < -1.6e-3)), slopes


@pytest.mark.parametrize("epsilon", (ABS, REL))
def test_where_the_old_rule_was_right_the_state_is_unchanged(epsilon):
    """The paper's gear: psi = 0, mlg_equilibrium's state at every freeplay.
    (10, 10) deg, y_fp = 1 mm: the states the continuation gave when a step
    was accepted if it moved psi by at most 5e-4 rad (the values below)."""
    for Fstar in (0.02, 0.1, 0.3, 1.0):
        for yfp in (0.5, 1.0):
            u = rolling.state("figures", Fstar, yfp, epsilon)
            v = model(Fstar, yfp, epsilon, {}).equilibrium()
            assert u["psi"] == 0.0 and max(abs(u[n] - v[n]) for n in u) < 1e-15, (Fstar, yfp)
    before = {0.02: 4.3594303211037675e-04, 0.1: 1.9775970124030003e-03,
              0.3: 2.3630146401128027e-03, 0.5: 2.327977684883695e-03}
    for Fstar, psi in before.items():
        assert rolling.state("figures", Fstar, 1.0, epsilon, **TEN)["psi"] == pytest.approx(
            psi, abs=1e-12), Fstar


def test_a_fold_ends_the_branch_where_auto_finds_it():
    """The stable side of the isola at (10, 10) deg, V = 50, y_fp = 1 mm,
    eps = 0.1 mm, followed in F* from 0.12 ends at its folds F1 0.08211 and
    F2 0.15585 (AUTO, docs/model.md) with NoRollingState."""
    def at(Fstar):
        return model(Fstar, 1.0, ABS, TEN)
    base = rolling.state("figures", 0.12, 1.0, ABS, **TEN)
    found = rolling.fan_states(at(0.12), [base[n] for n in mlgmodel.UNAMES],
                               np.linspace(-3e-3, 3e-3, 25), 1e-6)
    yawed = found[0]
    assert math.degrees(yawed[0]) == pytest.approx(-0.069, abs=0.002)
    for end, fold in ((0.3, 0.15585), (0.02, 0.08211)):
        with pytest.raises(rolling.NoRollingState) as ended:
            rolling.follow(at, "Fstar", 0.12, yawed, end, "the yawed state")
        assert float(str(ended.value).split("Fstar = ")[1].split()[0]) == pytest.approx(
            fold, abs=1e-4), str(ended.value)
