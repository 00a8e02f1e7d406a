"""Segmented orbits of eq. (14) (shared.segmented) on Fig. 10's gear (F* =
1, y_fp = 1 mm) end to end: the event-located simulation at 100 m/s gives
the segments, AUTO continues them to 104 m/s, and the orbit there agrees
with an independent simulation (studies.segmented.check, its tolerance
1e-4 relative; measured 4e-7 and 1e-7 on the study's five speeds), is
stable, with its trivial Floquet multiplier 1 (the product of the
segments' monodromies); the gap orbits from H3.  About 15 s.

Run: /usr/bin/python3 -m pytest -q tests/continuation/test_segmented.py
"""
import pytest

from mlgshimmy.shared import rundirs, segmented
from mlgshimmy.studies import segmented as study

CASE = study.CASE
START, AT = 100.0, 104.0


@pytest.fixture(scope="module")
def orbits(tmp_path_factory):
    root = tmp_path_factory.mktemp("segmented")
    with pytest.MonkeyPatch.context() as mp:
        mp.delenv(rundirs.CLAIMED_ENV, raising=False)
        mp.setenv("MLG_RUN_ROOT", str(root))
        orbit = segmented.simulated(CASE, START)
        runs = segmented.follow(str(root / "runs"), "up", CASE, orbit, START,
                                stop={"V": AT + 1.0}, at=[AT], DS=0.5, DSMAX=1.0)
        assert len(runs) == 1       # no fold on the way
        yield orbit, runs[0]


def test_the_simulation_gives_four_segments_symmetric_in_contact(orbits):
    """gap, contact+, gap, contact- (in some rotation); at rho = mu = 0 the
    gear is symmetric, so both contacts last as long, and both gaps."""
    orbit, _ = orbits
    modes = orbit["modes"]
    k = modes.index(segmented.CONTACT_POS)
    assert modes[k:] + modes[:k] == [segmented.CONTACT_POS, segmented.GAP,
                                     segmented.CONTACT_NEG, segmented.GAP]
    T = orbit["durations"][k:] + orbit["durations"][:k]
    assert T[0] == pytest.approx(T[2], rel=1e-6)
    assert T[1] == pytest.approx(T[3], rel=1e-6)
    assert sum(T) == pytest.approx(1.0 / orbit["frequency_hz"], rel=1e-6)


def test_auto_s_orbit_agrees_with_the_simulation(orbits):
    _, bd = orbits
    solution, = [s for s in bd("UZ") if abs(s["V"] - AT) < study.AT_SPEED]
    row, = study.check(CASE, [{"family": "high-frequency", "V": solution["V"],
                               "psi_amp": segmented.amplitude(solution),
                               "freq": 1.0 / segmented.period(solution)}])
    assert abs(row["amp_rel"]) < study.TOLERANCE
    assert abs(row["freq_rel"]) < study.TOLERANCE


def test_the_orbit_is_stable_with_its_trivial_multiplier_at_one(orbits):
    _, bd = orbits
    solution, = [s for s in bd("UZ") if abs(s["V"] - AT) < study.AT_SPEED]
    model = segmented.mlgmodel.Model("figures", **segmented.law14(CASE), V=AT)
    verdict = segmented.stability(model, solution)
    assert abs(verdict["trivial"] - 1.0) < 1e-5
    assert verdict["stable"] and verdict["largest"] < 1.0


def test_a_grazing_is_a_contact_of_zero_duration():
    """segmented.grazing: the contact segments (not the gaps) whose duration
    is below GRAZED at a fold."""
    modes = [segmented.GAP, segmented.CONTACT_POS, segmented.GAP, segmented.CONTACT_NEG]
    short = 0.5 * segmented.GRAZED
    assert segmented.grazing({"T1": 0.02, "T2": short, "T3": 0.02, "T4": short}, modes) == [2, 4]
    assert segmented.grazing({"T1": short, "T2": 0.0127, "T3": short, "T4": 0.0127}, modes) == []
    assert segmented.grazing({"T1": 0.02, "T2": 2 * segmented.GRAZED, "T3": 0.02,
                              "T4": short}, modes) == [4]


def test_gap_orbits_from_h3_are_unstable_and_return_under_the_simulation(tmp_path):
    """segmented.gap_orbits: the orbits of eq. (14)'s gap mode from H3
    (straight rolling's Hopf point in the gap) to 0.5 mm/s below it (short
    of their grazing, 0.9 mm/s below: amplitude about 0.75 of the freeplay
    angle); the one labelled midway is unstable, its largest multiplier 1 +
    8e-6 (the gap mode's monodromy; H3 is subcritical), and one period
    simulated from its first point with every switch located
    (segmented.one_period) crosses none, returns within 1e-4 of the
    amplitude and has AUTO's amplitude within 1e-4 (studies.segmented's
    TOLERANCE)."""
    with pytest.MonkeyPatch.context() as mp:
        mp.delenv(rundirs.CLAIMED_ENV, raising=False)
        mp.setenv("MLG_RUN_ROOT", str(tmp_path))
        law = segmented.law14(CASE)
        H3 = study.naming.scanned("figures", "V", study.ct.SPEED_SCAN, **law)["H3"]
        model = segmented.mlgmodel.Model("figures", **law)
        psi_fp = 1e-3 * CASE["yfp"] / model.r_tlk(model.equilibrium()["eta"])
        bd = segmented.gap_orbits(str(tmp_path / "runs"), "gap", CASE, H3, H3 - 5e-4,
                                  UZR={"V": [H3 - 2.5e-4]}, **study.PAST_STEPS)
        end = bd[-1][-1]
        assert abs(end["V"] - (H3 - 5e-4)) < 1e-7 and end["psi_amp"] < 0.8 * psi_fp
        point = min(bd("UZ"), key=lambda p: abs(p["V"] - (H3 - 2.5e-4)))
        verdict = segmented.stability(model.set(V=point["V"]), point)
        got = segmented.one_period(CASE, point)
    assert 1e-6 < verdict["largest"] - 1.0 < 1e-4, verdict["multipliers"]
    assert got["switches"] == 0
    assert got["closes"] < study.TOLERANCE
    assert abs(got["psi_amplitude_rad"] / segmented.amplitude(point) - 1.0) < study.TOLERANCE
