"""Oleo seal friction (docs/model.md 9, studies.friction) at Fig. 10's
conditions: straight rolling's Hopf points see the friction only as the
damper M_fric r_seal / v_fric it linearises to; the fold of the
low-frequency orbit in M_fric, continued by AUTO, is where the simulator's
shimmy stops (orbit kept 2 % below it, rest 2 % above).

Run: /usr/bin/python3 -m pytest -q tests/figures/test_friction.py
"""
import pytest

from mlgshimmy.shared import rundirs, simulator
from mlgshimmy.studies import friction

FIG10 = {**friction.CONDITIONS, "yfp": 1.0}


def test_hopf_points_see_only_the_linearised_damper():
    """(M_fric, v_fric) = (1 N m, 1 mm/s) and (10 N m, 1 cm/s) give the same
    H1, H2 to 1e-9; zero friction gives those of the paper's model exactly,
    whatever v_fric."""
    a = friction.low_frequency_pairs({**FIG10, "M_fric": 1.0, "v_fric": 1e-3})
    b = friction.low_frequency_pairs({**FIG10, "M_fric": 10.0, "v_fric": 1e-2})
    assert len(a) == len(b) == 2
    for (va, fa), (vb, fb) in zip(a, b):
        assert vb == pytest.approx(va, rel=1e-9) and fb == pytest.approx(fa, rel=1e-9)
    none = friction.low_frequency_pairs(FIG10)
    assert friction.low_frequency_pairs({**FIG10, "v_fric": 0.37}) == none
    # the damper delays H1 and advances H2 (1.458 -> 1.71, 28.31 -> 26.46 m/s)
    assert a[0][0] > none[0][0] + 0.1 and a[1][0] < none[1][0] - 1.0


@pytest.fixture(scope="module")
def fold(tmp_path_factory):
    """The orbit at V0 = 10 m/s (v_fric = 1 mm/s) and its fold in M_fric."""
    rundir = str(tmp_path_factory.mktemp("friction"))
    with pytest.MonkeyPatch.context() as mp:
        mp.delenv(rundirs.CLAIMED_ENV, raising=False)
        values = {**FIG10, "v_fric": 1e-3}
        _, _, _, orbit = friction.orbit_at_v0(rundir, "test", values)
        return orbit, friction.fold_in_friction(rundir, "test", orbit)[0]


@pytest.mark.parametrize("factor, persists", ((0.98, True), (1.02, False)))
def test_the_fold_in_friction_is_where_the_simulated_shimmy_stops(fold, factor, persists):
    orbit, lp = fold
    assert lp["M_fric"] > 1.0 and lp["psi_amp"] > 1e-4     # a fold of real orbits
    out = simulator.simulate(None, "--V", friction.V0, "--Fstar", 1.0, "--yfp", 1.0,
                             "--eps-rel", 0.1, "--psi0", orbit["psi_amp"], "--t-end", 40,
                             params={"M_fric": factor * lp["M_fric"], "v_fric": 1e-3})
    amplitude = out["psi_amplitude_rad"]
    if persists:   # the stable orbit beside the fold: its amplitude within 20 %
        assert amplitude == pytest.approx(lp["psi_amp"], rel=0.2), amplitude
    else:          # no orbit: the twist sticks, the gear rolls straight
        assert amplitude < 1e-6 * orbit["psi_amp"], amplitude
