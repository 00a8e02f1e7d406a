"""Tests of the attractor atlas's classifier (shared/attractor.py) and of
single cells simulated by studies/atlas/cell.py (y_fp = 1 mm, epsilon = 0.1 mm).

Synthetic signals check each criterion exactly; three simulated starts check
known states: straight rolling at V = 100 m/s, F* = 1 (stable, the Hopf
points are at 28.3 and 144.3 m/s), the low-frequency orbit at V = 20, F* = 1
(Fig. 10: 1.7-4.7 Hz inside the freeplay), and the high-frequency orbit at
V = 450, F* = 0.3 (the issue's run: psi amplitude 0.120-0.121 rad, ~40 Hz),
whose slowly growing modulation must not be called settled after 20 s.
"""
import os
import subprocess
import sys

import numpy as np
import pytest

import helpers
from mlgshimmy.shared import attractor
from mlgshimmy.shared import paths
from mlgshimmy.studies.atlas import cell as atlas_cell
from mlgshimmy.studies.atlas import compare as atlas_compare

T = np.arange(0.0, 10.0 + 1e-9, 1e-3)       # two 5 s windows, atlas sampling
T40 = np.arange(0.0, 40.0 + 1e-9, 1e-3)     # the first stage's time limit
PSI_FP = 2.088e-3                           # freeplay angle at F* = 1 [rad]
SR = 0.0                                    # psi of straight rolling at the paper's gear
W = atlas_cell.WINDOW
DRIVERS = os.path.join(paths.ROOT, "drivers")


def carrier(modulation):
    """A 40 s signal (a first stage): the trend is fitted over 20-40 s."""
    return 0.12 * (1 + modulation) * np.sin(2 * np.pi * 39.8 * T40)


GROWING = carrier(1e-3 * np.exp(0.02 * T40) * np.sin(2 * np.pi * 1.4 * T40))


# --- the classifier on synthetic signals -------------------------------------

def test_classify_synthetic_40_hz_sine_high():
    sine = 0.12 * np.sin(2 * np.pi * 40.0 * T)
    r = attractor.classify(T, sine, W, PSI_FP, SR)
    assert r["kind"] == "high", r
    helpers.assert_close(r["amplitude_rad"], 0.12, rel=1e-4)
    helpers.assert_close(r["frequency_hz"], 40.0, rel=1e-4)
    assert r["peak_spread"] < 1e-6, f"peak spread {r['peak_spread']} (quartic fit)"


def test_classify_synthetic_3_hz_sine_low():
    r = attractor.classify(T, 2e-3 * np.sin(2 * np.pi * 3.0 * T + 0.3), W, PSI_FP, SR)
    assert r["kind"] == "low", r
    helpers.assert_close(r["frequency_hz"], 3.0, rel=1e-3)


@pytest.mark.parametrize("amplitude, f, psi_fp, kind", (
    (2.42e-3, 9.7, 2.066e-3, "low"),
    (3.13e-3, 18.1, 2.066e-3, "high"),
    (3.40e-3, 13.6, 2.555e-3, "high"),
    (2.84e-3, 20.3, 2.555e-3, "high")))
def test_classify_low_or_high_by_engagement_and_frequency(amplitude, f, psi_fp, kind):
    """Low / high by how far the swing passes the freeplay angle (ENGAGED)
    and LOW_HZ: the orbits of V = 20 m/s, F* = 1.8 (psi_fp 2.066e-3) and of
    V = 200 and 600 m/s, F* = 0.02 (psi_fp 2.555e-3)."""
    r = attractor.classify(T, amplitude * np.sin(2 * np.pi * f * T), W, psi_fp, SR)
    assert r["kind"] == kind, \
        (f"{amplitude:g} rad at {f:g} Hz, psi_fp {psi_fp:g} rad (ratio {amplitude / psi_fp:.2f}, "
         f"ENGAGED {attractor.ENGAGED}, LOW_HZ {attractor.LOW_HZ:g}): {r}")


def test_classify_steady_modulation_quasi():
    """A steady 3 % modulation at 1.03 Hz: quasi, its trend steady (below
    RATE_MIN), its frequency found."""
    r = attractor.classify(T40, carrier(0.03 * np.sin(2 * np.pi * 1.03 * T40)), W, PSI_FP, SR)
    assert r["kind"] == "quasi" and r["trend"] == "steady" and not r["growing"], r
    assert abs(r["spread_rate"]) < attractor.RATE_MIN, r["spread_rate"]
    helpers.assert_close(r["modulation_hz"] or 0, 1.03, rel=0.05)


def test_classify_growing_modulation_quasi_growing():
    """A modulation growing at 0.02 /s from 0.1 % (still below MODULATED):
    quasi, growing, the fitted rate 0.02 /s."""
    r = attractor.classify(T40, GROWING, W, PSI_FP, SR)
    assert r["kind"] == "quasi" and r["growing"] and r["trend"] == "growing", r
    helpers.assert_close(r["spread_rate"], 0.02, rel=0.05)


def test_classify_decaying_modulation_high():
    """A 1 % modulation decaying at 0.016 /s (the axial mode): high, decaying."""
    decaying = carrier(2e-2 * np.exp(-0.016 * T40) * np.sin(2 * np.pi * 0.8 * T40))
    r = attractor.classify(T40, decaying, W, PSI_FP, SR)
    assert r["kind"] == "high" and r["trend"] == "decaying", r
    helpers.assert_close(r["spread_rate"], -0.016, rel=0.05)


def test_classify_slowly_growing_modulation_unsettled():
    """0.2 % growing at 2e-4 /s (< RATE_MIN): steady, so unsettled."""
    slow = carrier(1e-3 * np.exp(2e-4 * T40) * np.sin(2 * np.pi * 1.4 * T40))
    r = attractor.classify(T40, slow, W, PSI_FP, SR)
    assert r["kind"] == "unsettled" and r["trend"] == "steady", r


def test_spread_trend_first_spread_and_too_short_a_fit():
    fit = attractor.spread_trend(T40, GROWING, 20.0, 40.0)
    helpers.assert_close(fit["first"], 2e-3 * np.exp(0.02 * 21.0), rel=0.05)
    assert attractor.spread_trend(T40, GROWING, 34.0, 40.0) is None, \
        "fewer than 4 spreads gave a fit"


def test_mode_shape_amplitude_ratio_and_phase():
    lateral = 0.2 * 0.12 * np.sin(2 * np.pi * 39.8 * T40 - np.radians(60.0))
    ratio = attractor.mode_shape(T40[-5000:], carrier(0)[-5000:], lateral[-5000:], 39.8)
    helpers.assert_close(abs(ratio), 0.2, rel=1e-3)
    helpers.assert_close(np.degrees(np.angle(ratio)), -60.0, abs=0.1)


def test_classify_decay_unsettled_not_straight():
    decaying = 1e-4 * np.exp(-0.3 * T) * np.sin(2 * np.pi * 38.0 * T)
    r = attractor.classify(T, decaying, W, PSI_FP, SR)
    assert r["kind"] == "unsettled", r


def test_classify_rest_straight_or_yaw():
    r = attractor.classify(T, np.zeros_like(T), W, PSI_FP, SR)
    assert r["kind"] == "straight", f"rest at psi = 0: {r}"
    r = attractor.classify(T, np.full_like(T, 1.7e-3), W, PSI_FP, SR)
    assert r["kind"] == "yaw", f"rest at psi = 1.7e-3: {r}"
    helpers.assert_close(r["mean_rad"], 1.7e-3, rel=1e-9)


@pytest.mark.parametrize("rest, psi_straight, kind", (
    (-1.02e-3, -1.02e-3, "straight"),     # straight rolling twisted by side-stay angles
    (-1.02e-3 + 2e-5, -1.02e-3, "yaw"),   # 2 CENTRE from it
    (-1.02e-3 + 5e-6, -1.02e-3, "straight"),
    (0.0, -1.02e-3, "yaw"),               # psi = 0 is not straight rolling there
    (0.0, None, "yaw")))                  # no straight rolling at this load
def test_classify_rest_against_the_straight_rolling_state(rest, psi_straight, kind):
    """Straight or yaw by the distance of the mean psi from straight
    rolling's psi (attractor.CENTRE = 1e-5 rad), not from psi = 0."""
    r = attractor.classify(T, np.full_like(T, rest), W, PSI_FP, psi_straight)
    assert r["kind"] == kind, f"rest at psi = {rest:g}, straight rolling {psi_straight}: {r}"


def test_classify_period_2_high_with_two_levels():
    two = 0.1 * np.sin(2 * np.pi * 40.0 * T40) * (1 + 0.05 * np.sign(np.sin(2 * np.pi * 20.0
                                                                              * T40 + 0.1)))
    r = attractor.classify(T40, two, W, PSI_FP, SR)
    assert r["kind"] == "high" and r["levels"] == 2, r


def test_classify_refuses_fewer_samples_than_two_windows():
    with pytest.raises(ValueError) as error:
        attractor.classify(T[:3000], T[:3000], W, PSI_FP, SR)
    assert "window" in str(error.value), str(error.value)


# --- cell rules ----------------------------------------------------------------

def test_unstable_orbit_at_the_noise_floor_ends_on_the_torus():
    """A start on an orbit with its modulation at the noise floor ends on the
    torus when another start's modulation grows around the same orbit."""
    starts = {"rolling": {"kind": "high", "peak_spread": 6e-6, "amplitude_rad": 0.1425,
                          "frequency_hz": 39.98},
              "shimmy": {"kind": "quasi", "growing": True, "peak_spread": 1.2e-3,
                         "amplitude_rad": 0.1426, "frequency_hz": 39.98},
              "other": {"kind": "high", "peak_spread": 6e-6, "amplitude_rad": 0.05,
                        "frequency_hz": 30.0},
              "modulated": {"kind": "high", "peak_spread": 2e-4, "amplitude_rad": 0.1425,
                            "frequency_hz": 39.98}}
    atlas_cell.unstable_orbits(starts)
    assert starts["rolling"]["kind"] == "quasi" and starts["rolling"]["unstable_by"] == "shimmy", \
        f"the start at the noise floor on the same orbit (0.07 % apart): {starts['rolling']}"
    assert starts["other"]["kind"] == "high", \
        f"a different orbit (0.05 rad, 30 Hz): {starts['other']}"
    assert starts["modulated"]["kind"] == "high", \
        f"a start whose own spread (2e-4) was read: {starts['modulated']}"


@pytest.mark.parametrize("result, expected", (
    ({"kind": "quasi", "growing": True, "peak_spread": 1e-4}, False),
    ({"kind": "quasi", "growing": True, "peak_spread": 0.02}, True),
    ({"kind": "quasi", "growing": False, "peak_spread": 0.02}, True),
    ({"kind": "high", "growing": False, "peak_spread": 1e-6}, True),
    ({"kind": "unsettled", "peak_spread": 1e-3}, False)))
def test_confirmed_growing_modulation_below_modulated_must_last(result, expected):
    assert atlas_cell.confirmed(result) == expected, f"confirmed({result})"


# --- the comparison with Fig. 11 ---------------------------------------------

def stub_cell(v, fstar, *kinds):
    return {"V": v, "Fstar": fstar,
            "starts": {f"s{k}": {"kind": kind, "amplitude_rad": 0.1, "frequency_hz": 40.0}
                       for k, kind in enumerate(kinds)}}


@pytest.mark.parametrize("kinds, code", (
    (("straight", "high", "high"), 5),
    (("quasi", "domain"), 16),       # a transient, not a region
    (("domain", "domain"), 32),      # lift-off
    (("straight", "unsettled"), None)))
def test_compare_cell_code(kinds, code):
    assert atlas_compare.cell_code(stub_cell(1, 1, *kinds)) == code, kinds


LINE = {"name": "hopf", "kind": "hopf", "V": [300.0, 300.0], "Fstar": [0.0, 3.5]}


def test_compare_curve_distance_to_a_segment():
    """The vertical line V = 300 m/s: distance (V - 300) / 600 at any F*."""
    d, name = atlas_compare.curve_distance([LINE], 330.0, 1.75)
    helpers.assert_close(d, 0.05, rel=1e-12)
    assert name == "hopf", name


def test_compare_with_a_stub_region_map():
    """atlas_compare on a stub of Fig. 11's region map: codes OR-ed over the
    starts, the distance to a curve, the fraction over the cells off it."""
    stub = {"region_map": {"V": [0.0, 200.0, 400.0, 600.0], "Fstar": [0.0, 3.5],
                           "code": [[1, 1, 4, 4], [1, 1, 4, 4]], "names": {"1": "straight"}},
            "edge_curves": [LINE]}
    cells = [stub_cell(100, 1, "straight"), stub_cell(500, 1, "straight", "high"),
             stub_cell(303, 1, "high"), stub_cell(450, 2, "high"),
             stub_cell(150, 2, "unsettled"), stub_cell(550, 2, "high", "yaw")]
    r = atlas_compare.compare(cells, stub)
    assert [(e["V"], e["Fstar"]) for e in r["on_curve"]] == [(303, 1)], \
        f"V = 303 (distance 0.005 < NEAR) not the one on the curve: {r['on_curve']}"
    assert [e["V"] for e in r["agree"]] == [100, 450], \
        f"V = 100 and 450 should agree: {r['agree']}"
    assert [(e["V"], e["atlas_name"], e["differs"]) for e in r["disagree"]] \
        == [(500, "straight + high", "straight"), (150, "not settled", "unsettled"),
            (550, "high + yaw", "yaw")], \
        (f"V = 500 (straight + high in the high region), 150 (not settled) and 550 (a yawed "
         f"end where Fig. 11 has no stable yawed equilibrium): {r['disagree']}")
    helpers.assert_close(r["fraction"], 0.4, rel=1e-12)
    assert sum("disagree V" in line for line in atlas_compare.report(r)) == 3, \
        atlas_compare.report(r)


def test_compare_yaw_edge_counts_as_a_curve():
    """The edge of Fig. 11's yaw region (stable yawed equilibria below
    V = 125 m/s at F* <= 0.35 here) is a curve: a cell 3 m/s from it is not
    compared, one 25 m/s away is, with the yaw bit."""
    V = np.arange(0.0, 600.5, 0.5)
    F = np.arange(0.0, 3.51, 0.01)
    code = np.where(V[None, :] < 125.0, 9, 1) * (F[:, None] <= 0.35) + (F[:, None] > 0.35)
    stub = {"region_map": {"V": V, "Fstar": F, "code": code.tolist(), "names": {}},
            "edge_curves": []}
    helpers.assert_close(atlas_compare.yaw_edge_distance(stub["region_map"], 100.0, 0.2), 25 / 600,
                 rel=1e-9)
    cells = [stub_cell(122, 0.2, "yaw"), stub_cell(100, 0.2, "straight", "yaw"),
             stub_cell(100, 0.1, "straight"), stub_cell(150, 0.2, "straight")]
    r = atlas_compare.compare(cells, stub)
    assert [(e["V"], e["curve"]) for e in r["on_curve"]] == [(122, "yaw edge")], r["on_curve"]
    assert [(e["V"], e["Fstar"]) for e in r["agree"]] == [(100, 0.2), (150, 0.2)], r["agree"]
    assert [(e["V"], e["Fstar"], e["differs"]) for e in r["disagree"]] == [(100, 0.1, "yaw")], \
        r["disagree"]


# --- the command line ----------------------------------------------------------

def atlas(args, root):
    return subprocess.run([sys.executable, "-m", "mlgshimmy.studies.atlas", *args],
                          capture_output=True, text=True, cwd=paths.ROOT,
                          env=dict(os.environ, MLG_RUN_ROOT=str(root), PYTHONPATH=DRIVERS))


@pytest.mark.parametrize("args, words", (
    (["targets", "--V=10,10.0000001"], ["ATLAS_V", "same grid point"]),
    (["jobs", "--Fstar=0:1:0"], ["ATLAS_FSTAR", "step > 0"]),
    (["check", "--V=-5", "--Fstar=1"], ["V = -5", "must be >= 0"]),
    (["cell", "V1_G2"], ["not a cell name"])))
def test_atlas_command_refuses_a_bad_grid_naming_it(tmp_path, args, words):
    """A grid the atlas cannot run stops before any cell, naming the variable."""
    proc = atlas(args, tmp_path)
    assert proc.returncode != 0 and all(w in proc.stderr for w in words) \
        and not os.path.exists(os.path.join(tmp_path, "atlas", "V1_G2")), \
        (f"atlas {' '.join(args)}: exit status {proc.returncode}, "
         f"stderr {proc.stderr.strip()!r}, expected {words}")


def test_atlas_command_targets_of_a_range(tmp_path):
    proc = atlas(["targets", "--V=150:300:50", "--Fstar=0.1"], tmp_path)
    names = [os.path.basename(os.path.dirname(p)) for p in proc.stdout.split()]
    assert names == ["V150_F0.1", "V200_F0.1", "V250_F0.1", "V300_F0.1"], \
        (names, proc.stderr)


# --- simulated cells -----------------------------------------------------------

@pytest.fixture
def rundir(tmp_path):
    """A cell's run directory (left_empty checks that nothing of the
    simulator's stays in it)."""
    return str(tmp_path)


def left_empty(rundir):
    assert os.listdir(rundir) == [], f"simulator output left behind: {os.listdir(rundir)}"


def test_simulated_straight_rolling_at_100_m_s(rundir):
    r = atlas_cell.run_stage(100.0, 1.0, atlas_cell.STARTS["rolling"], 20.0, rundir)
    assert r["kind"] == "straight", f"V = 100, F* = 1 from straight rolling + 1e-4 rad: {r}"
    left_empty(rundir)


def test_simulated_low_frequency_orbit_at_20_m_s(rundir):
    r = atlas_cell.run_stage(20.0, 1.0, atlas_cell.STARTS["shimmy"], 20.0, rundir)
    assert r["kind"] == "low", f"V = 20, F* = 1 from 0.05 rad: {r}"
    helpers.assert_close(r["frequency_hz"], 4.70, rel=0.01)
    assert 1.5e-3 < r["amplitude_rad"] < 2.2e-3, \
        f"amplitude {r['amplitude_rad']} not inside the freeplay angle (2.1e-3 rad)"
    left_empty(rundir)


def test_simulated_high_frequency_orbit_at_450_m_s_still_growing(rundir):
    r = atlas_cell.run_stage(450.0, 0.3, 0.05, 20.0, rundir)
    helpers.assert_close(r["amplitude_rad"], 0.120, abs=0.002)
    helpers.assert_close(r["frequency_hz"], 39.8, abs=0.2)
    assert r["kind"] == "quasi" and r["growing"], \
        f"V = 450, F* = 0.3 after 20 s: not a growing modulation (quasi, growing): {r}"
    assert 0.005 < r["spread_rate"] < 0.1, \
        (f"modulation rate {r['spread_rate']} not in 0.005-0.1 /s (AUTO's rates near the "
         "torus points: 1e-3 .. 1e-1)")
    left_empty(rundir)


def test_simulated_liftoff_at_600_m_s(rundir):
    r = atlas_cell.run_stage(600.0, 0.3, 0.05, 25.0, rundir)
    assert r["kind"] == "domain" and "lifts off" in r["reason"], \
        f"V = 600, F* = 0.3 from 0.05 rad: no wheel lifted off before 25 s: {r}"
    before = r["before"] or {}
    assert before.get("trend") == "growing" \
        and before.get("peak_spread", 0) > attractor.MODULATED \
        and 35 < before.get("frequency_hz", 0) < 45, \
        f"before lift-off not a ~40 Hz shimmy whose modulation grows beyond 0.5 %: {before}"
    left_empty(rundir)
