"""shared.stationary at Fig. 12's values (V = 50 m/s, y_fp = 1 mm,
eps = 0.1 mm; a few seconds of short AUTO runs in F* and Newton): the
symmetric gear's pitchforks against the eigenvalue scan of straight
rolling, its yawed states mirror images, and at a side-stay geometry the
mirror gear (-rho, -mu) has the mirrored states (psi -> -psi) with the same
stability and the same fold loads (docs/model.md 8.8)."""
import math

import numpy
import pytest

from mlgshimmy.shared import rundirs
from mlgshimmy.shared import spectrum
from mlgshimmy.shared import stationary

VALUES = dict(V=50.0, yfp=1.0, eps_rel=0.1)
LOADS = (0.02, 1.0)
ANGLE = math.radians(10.0)


@pytest.fixture(scope="module")
def rundir(tmp_path_factory):
    """The runs' directory, its claim kept from later tests' children."""
    path = tmp_path_factory.mktemp("stationary")
    with pytest.MonkeyPatch.context() as mp:
        mp.delenv(rundirs.CLAIMED_ENV, raising=False)
        yield str(path)


def found(rundir, tag, sign=0):
    """The stationary states at the geometry sign * (10 deg, 10 deg)."""
    angles = dict(rho=sign * ANGLE, mu=sign * ANGLE, eom_terms=2.0) if sign else {}
    return stationary.states(f"{rundir}/{tag}", "figures", LOADS, **VALUES, **angles)


@pytest.fixture(scope="module")
def symmetric(rundir):
    return found(rundir, "symmetric")


@pytest.fixture(scope="module")
def pair(rundir):
    return found(rundir, "plus", 1), found(rundir, "minus", -1)


def test_symmetric_pitchforks_are_the_real_eigenvalue_crossings(symmetric):
    """AUTO's BPs on straight rolling where the scan of its eigenvalues
    (no AUTO) has a real eigenvalue cross zero: two of them, the yawed
    states between (Fig. 12)."""
    grid = numpy.linspace(*LOADS, 200)
    scan = [F for F, kind, _ in spectrum.stability_changes("figures", "Fstar", grid, **VALUES)
            if kind == "BP"]
    assert len(symmetric.pitchforks) == 2
    assert symmetric.pitchforks == pytest.approx(scan, rel=1e-5)
    assert symmetric.folds() == []


def test_symmetric_yawed_states_are_mirror_images(symmetric):
    """Between the pitchforks: psi = 0 and +-psi_y, the yawed pair with one
    stability; outside them only straight rolling."""
    low, high = symmetric.pitchforks
    for F in numpy.linspace(low, high, 7)[1:-1]:
        states = symmetric.at(F)
        assert len(states) == 3
        (minus, s_minus), (zero, _), (plus, s_plus) = states
        assert abs(zero) < 1e-12
        assert plus > 1e-4 and minus == pytest.approx(-plus, rel=1e-6)
        assert s_minus == s_plus
    for F in (0.5 * (LOADS[0] + low), 0.5 * (high + LOADS[1])):
        assert [abs(psi) < 1e-12 for psi, _ in symmetric.at(F)] == [True]


def test_mirror_gear_has_the_same_fold_loads(pair, symmetric):
    """Imperfect pitchforks: folds (LP) instead of BPs, at the same loads for
    (rho, mu) and (-rho, -mu), mirrored in psi, to AUTO's location of a
    fold from different steps on the two sides (EPSS = 1e-5 of the step:
    1.4e-5 relative seen in F*; psi, along which F* is stationary there, to
    about 1 %, 1e-5 rad of 1e-3); none where the symmetric gear has its
    pitchforks."""
    plus, minus = pair
    assert plus.pitchforks == [] and minus.pitchforks == []
    folds_plus, folds_minus = plus.folds(), minus.folds()
    assert len(folds_plus) == 2
    for (F1, psi1, _), (F2, psi2, _) in zip(folds_plus, folds_minus):
        assert F2 == pytest.approx(F1, rel=1e-4)
        assert psi2 == pytest.approx(-psi1, abs=2e-5)
    assert all(abs(F - p) > 0.01 for F, _, _ in folds_plus for p in symmetric.pitchforks)


def test_mirror_gear_has_the_mirrored_states_with_their_stability(pair):
    """At loads below, between and above the folds: the same number of
    states, psi -> -psi (to the interpolation between AUTO's points, 1e-6
    rad against states of 1e-3 rad), stability the same."""
    plus, minus = pair
    (F1, _, _), (F2, _, _) = plus.folds()
    for F in (0.05, 0.5 * (F1 + F2), 0.3, 0.9):
        here = plus.at(F)
        mirrored = sorted((-psi, stable) for psi, stable in minus.at(F))
        assert len(here) == len(mirrored) == (3 if F1 < F < F2 else 1)
        for (psi, stable), (psi_m, stable_m) in zip(here, mirrored):
            assert psi_m == pytest.approx(psi, abs=1e-6)
            assert stable_m == stable


def test_straight_rolling_past_a_fold_in_the_load_is_on_the_heavy_loads_sheet(rundir):
    """The printed strut at rho = 20, mu = 5 deg: straight rolling from the
    lightest load folds in F* at 0.7012, where eta crosses the stage
    switch (AUTO's steps pass over the S).  Below the fold the state is the
    one from the lightest load, above it the one continued down from the
    heaviest, the same as AUTO's branch there (eta to 1e-4 m, 2e-4 of it)."""
    angles = dict(rho=math.radians(20.0), mu=math.radians(5.0), eom_terms=2.0,
                  strut_variant=1.0)
    states = stationary.states(f"{rundir}/printed", "figures", (0.02, 3.5),
                               {"overlay": "stage_switch"}, **VALUES, **angles)
    branch = states.straight[0]
    below, above = states.rolling_state(0.70), states.rolling_state(0.7013)
    assert below["eta"] < 0.340 < 0.346 < above["eta"], (below["eta"], above["eta"])
    for F in (0.72, 1.0, 3.5):
        k = int(numpy.argmin(numpy.abs(numpy.asarray(branch["Fstar"]) - F)))
        state = states.rolling_state(float(branch["Fstar"][k]))
        assert state["eta"] == pytest.approx(branch["eta_mean"][k], abs=1e-4)
