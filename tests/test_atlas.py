"""Tests of the attractor atlas's classifier (drivers/attractor.py) and of
single cells simulated by drivers/atlas_cell.py (y_fp = 1 mm, epsilon = 0.1 mm).

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
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "drivers"))
from check import check, check_close  # noqa: E402
from mlgshimmy.studies.atlas import cell as atlas_cell  # noqa: E402
from mlgshimmy.studies.atlas import compare as atlas_compare  # noqa: E402
from mlgshimmy.shared import attractor  # noqa: E402

T = np.arange(0.0, 10.0 + 1e-9, 1e-3)       # two 5 s windows, atlas sampling
T40 = np.arange(0.0, 40.0 + 1e-9, 1e-3)     # the first stage's time limit
PSI_FP = 2.088e-3                           # freeplay angle at F* = 1 [rad]
W = atlas_cell.WINDOW


def synthetic():
    sine = 0.12 * np.sin(2 * np.pi * 40.0 * T)
    r = attractor.classify(T, sine, W, PSI_FP)
    check("synthetic 40 Hz sine: high", r["kind"] == "high", r)
    check_close("synthetic 40 Hz sine: amplitude", r["amplitude_rad"], 0.12, rel=1e-4)
    check_close("synthetic 40 Hz sine: frequency", r["frequency_hz"], 40.0, rel=1e-4)
    check("synthetic 40 Hz sine: peak spread below 1e-6 (quartic fit)",
          r["peak_spread"] < 1e-6, r["peak_spread"])

    r = attractor.classify(T, 2e-3 * np.sin(2 * np.pi * 3.0 * T + 0.3), W, PSI_FP)
    check("synthetic 3 Hz sine: low", r["kind"] == "low", r)
    check_close("synthetic 3 Hz sine: frequency", r["frequency_hz"], 3.0, rel=1e-3)

    # low / high by how far the swing passes the freeplay angle (ENGAGED)
    # and LOW_HZ: the orbits of V = 20 m/s, F* = 1.8 (psi_fp 2.066e-3) and
    # of V = 200 and 600 m/s, F* = 0.02 (psi_fp 2.555e-3)
    for amplitude, f, psi_fp, kind in ((2.42e-3, 9.7, 2.066e-3, "low"),
                                       (3.13e-3, 18.1, 2.066e-3, "high"),
                                       (3.40e-3, 13.6, 2.555e-3, "high"),
                                       (2.84e-3, 20.3, 2.555e-3, "high")):
        r = attractor.classify(T, amplitude * np.sin(2 * np.pi * f * T), W, psi_fp)
        check(f"synthetic {amplitude:g} rad at {f:g} Hz, psi_fp {psi_fp:g} rad "
              f"(ratio {amplitude / psi_fp:.2f}, ENGAGED {attractor.ENGAGED}, LOW_HZ "
              f"{attractor.LOW_HZ:g}): {kind}",
              r["kind"] == kind, r)

    # 40 s signals (a first stage): the trend is fitted over 20-40 s
    def carrier(modulation):
        return 0.12 * (1 + modulation) * np.sin(2 * np.pi * 39.8 * T40)

    r = attractor.classify(T40, carrier(0.03 * np.sin(2 * np.pi * 1.03 * T40)), W, PSI_FP)
    check("synthetic steady 3 % modulation at 1.03 Hz: quasi, trend steady",
          r["kind"] == "quasi" and r["trend"] == "steady" and not r["growing"], r)
    check("synthetic steady modulation: |trend| below RATE_MIN",
          abs(r["spread_rate"]) < attractor.RATE_MIN, r["spread_rate"])
    check_close("synthetic modulation: its frequency", r["modulation_hz"] or 0, 1.03, rel=0.05)

    growing = carrier(1e-3 * np.exp(0.02 * T40) * np.sin(2 * np.pi * 1.4 * T40))
    r = attractor.classify(T40, growing, W, PSI_FP)
    check("synthetic modulation growing at 0.02 /s from 0.1 % (still below MODULATED): "
          "quasi, growing", r["kind"] == "quasi" and r["growing"] and r["trend"] == "growing", r)
    check_close("synthetic growing modulation: fitted rate 0.02 /s", r["spread_rate"], 0.02,
                rel=0.05)

    decaying = carrier(2e-2 * np.exp(-0.016 * T40) * np.sin(2 * np.pi * 0.8 * T40))
    r = attractor.classify(T40, decaying, W, PSI_FP)
    check("synthetic 1 % modulation decaying at 0.016 /s (the axial mode): high, decaying",
          r["kind"] == "high" and r["trend"] == "decaying", r)
    check_close("synthetic decaying modulation: fitted rate -0.016 /s", r["spread_rate"],
                -0.016, rel=0.05)

    slow = carrier(1e-3 * np.exp(2e-4 * T40) * np.sin(2 * np.pi * 1.4 * T40))
    r = attractor.classify(T40, slow, W, PSI_FP)
    check("synthetic 0.2 % modulation growing at 2e-4 /s (< RATE_MIN): steady, so unsettled",
          r["kind"] == "unsettled" and r["trend"] == "steady", r)

    fit = attractor.spread_trend(T40, growing, 20.0, 40.0)
    check_close("spread_trend: first spread 2e-3 exp(0.02 * 21) (two-sided, 1 s into the fit)",
                fit["first"], 2e-3 * np.exp(0.02 * 21.0), rel=0.05)
    check("spread_trend: fewer than 4 spreads give no fit",
          attractor.spread_trend(T40, growing, 34.0, 40.0) is None)

    lateral = 0.2 * 0.12 * np.sin(2 * np.pi * 39.8 * T40 - np.radians(60.0))
    ratio = attractor.mode_shape(T40[-5000:], carrier(0)[-5000:], lateral[-5000:], 39.8)
    check_close("mode_shape: amplitude ratio 0.2", abs(ratio), 0.2, rel=1e-3)
    check_close("mode_shape: phase -60 deg", np.degrees(np.angle(ratio)), -60.0, abs=0.1)

    decaying = 1e-4 * np.exp(-0.3 * T) * np.sin(2 * np.pi * 38.0 * T)
    r = attractor.classify(T, decaying, W, PSI_FP)
    check("synthetic decay at 0.3 /s: unsettled, not straight", r["kind"] == "unsettled", r)

    r = attractor.classify(T, np.zeros_like(T), W, PSI_FP)
    check("synthetic rest at psi = 0: straight", r["kind"] == "straight", r)
    r = attractor.classify(T, np.full_like(T, 1.7e-3), W, PSI_FP)
    check("synthetic rest at psi = 1.7e-3: yaw", r["kind"] == "yaw", r)
    check_close("synthetic yaw: mean", r["mean_rad"], 1.7e-3, rel=1e-9)

    two = 0.1 * np.sin(2 * np.pi * 40.0 * T40) * (1 + 0.05 * np.sign(np.sin(2 * np.pi * 20.0
                                                                              * T40 + 0.1)))
    r = attractor.classify(T40, two, W, PSI_FP)
    check("synthetic period-2 (two peak levels): high with levels 2",
          r["kind"] == "high" and r["levels"] == 2, r)

    try:
        attractor.classify(T[:3000], T[:3000], W, PSI_FP)
        check("3 s of samples for two 5 s windows: refused", False, "no error")
    except ValueError as exc:
        check("3 s of samples for two 5 s windows: refused", "window" in str(exc), exc)


def unstable_orbit():
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
    check("unstable orbit: the start at the noise floor on the same orbit (0.07 % apart) "
          "is quasi, shown by shimmy",
          starts["rolling"]["kind"] == "quasi" and starts["rolling"]["unstable_by"] == "shimmy",
          starts["rolling"])
    check("unstable orbit: a different orbit (0.05 rad, 30 Hz) stays high",
          starts["other"]["kind"] == "high", starts["other"])
    check("unstable orbit: a start whose own spread (2e-4) was read stays as read",
          starts["modulated"]["kind"] == "high", starts["modulated"])


def confirmation():
    """A growing modulation below MODULATED must last to the last stage."""
    for result, expected in (({"kind": "quasi", "growing": True, "peak_spread": 1e-4}, False),
                             ({"kind": "quasi", "growing": True, "peak_spread": 0.02}, True),
                             ({"kind": "quasi", "growing": False, "peak_spread": 0.02}, True),
                             ({"kind": "high", "growing": False, "peak_spread": 1e-6}, True),
                             ({"kind": "unsettled", "peak_spread": 1e-3}, False)):
        check(f"confirmed({result}) is {expected}", atlas_cell.confirmed(result) == expected)


def simulated():
    with tempfile.TemporaryDirectory() as tmp:
        r = atlas_cell.run_stage(100.0, 1.0, atlas_cell.STARTS["rolling"], 20.0, tmp)
        check("V = 100, F* = 1 from straight rolling + 1e-4 rad: straight",
              r["kind"] == "straight", r)

        r = atlas_cell.run_stage(20.0, 1.0, atlas_cell.STARTS["shimmy"], 20.0, tmp)
        check("V = 20, F* = 1 from 0.05 rad: low", r["kind"] == "low", r)
        check_close("V = 20, F* = 1: frequency (Fig. 10's 1.7-4.7 Hz branch)",
                    r["frequency_hz"], 4.70, rel=0.01)
        check("V = 20, F* = 1: amplitude inside the freeplay angle (2.1e-3 rad)",
              1.5e-3 < r["amplitude_rad"] < 2.2e-3, r["amplitude_rad"])

        r = atlas_cell.run_stage(450.0, 0.3, 0.05, 20.0, tmp)
        check_close("V = 450, F* = 0.3: psi amplitude 0.120 rad", r["amplitude_rad"], 0.120,
                    abs=0.002)
        check_close("V = 450, F* = 0.3: frequency 39.8 Hz", r["frequency_hz"], 39.8, abs=0.2)
        check("V = 450, F* = 0.3 after 20 s: growing modulation, so quasi (growing)",
              r["kind"] == "quasi" and r["growing"], r)
        check("V = 450, F* = 0.3: modulation growing at 0.005-0.1 /s (AUTO's rates near "
              "the torus points: 1e-3 .. 1e-1)", 0.005 < r["spread_rate"] < 0.1, r["spread_rate"])
        r = atlas_cell.run_stage(600.0, 0.3, 0.05, 25.0, tmp)
        check("V = 600, F* = 0.3 from 0.05 rad: a wheel lifts off before 25 s",
              r["kind"] == "domain" and "lifts off" in r["reason"], r)
        before = r["before"] or {}
        check("V = 600, F* = 0.3: before lift-off a ~40 Hz shimmy whose modulation grows "
              "beyond 0.5 %", before.get("trend") == "growing"
              and before.get("peak_spread", 0) > attractor.MODULATED
              and 35 < before.get("frequency_hz", 0) < 45, before)
        check("no simulator output left behind", os.listdir(tmp) == [], os.listdir(tmp))


def bad_input():
    """A grid the atlas cannot run stops before any cell, naming the variable."""
    atlas = os.path.join(os.path.dirname(HERE), "drivers", "atlas.py")
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, MLG_RUN_ROOT=tmp)
        for args, words in ((["targets", "--V=10,10.0000001"], ["ATLAS_V", "same grid point"]),
                            (["jobs", "--Fstar=0:1:0"], ["ATLAS_FSTAR", "step > 0"]),
                            (["check", "--V=-5", "--Fstar=1"], ["V = -5", "must be >= 0"]),
                            (["cell", "V1_G2"], ["not a cell name"])):
            proc = subprocess.run([sys.executable, atlas, *args], capture_output=True,
                                  text=True, env=env)
            check(f"atlas.py {' '.join(args)}: refused naming {words[0]}",
                  proc.returncode != 0 and all(w in proc.stderr for w in words)
                  and not os.path.exists(os.path.join(tmp, "atlas", "V1_G2")),
                  f"exit status {proc.returncode}, stderr {proc.stderr.strip()!r}")
        proc = subprocess.run([sys.executable, atlas, "targets", "--V=150:300:50",
                               "--Fstar=0.1"], capture_output=True, text=True, env=env)
        names = [os.path.basename(os.path.dirname(p)) for p in proc.stdout.split()]
        check("atlas.py targets --V=150:300:50: four cells",
              names == ["V150_F0.1", "V200_F0.1", "V250_F0.1", "V300_F0.1"], names)


def comparison():
    """atlas_compare on a stub of Fig. 11's region map: codes OR-ed over the
    starts, the distance to a curve, the fraction over the cells off it."""
    def cell(v, fstar, *kinds):
        return {"V": v, "Fstar": fstar,
                "starts": {f"s{k}": {"kind": kind, "amplitude_rad": 0.1, "frequency_hz": 40.0}
                           for k, kind in enumerate(kinds)}}
    check("cell code: straight + high + high = 5",
          atlas_compare.cell_code(cell(1, 1, "straight", "high", "high")) == 5)
    check("cell code: quasi + a start leaving the domain = 16 (a transient, not a region)",
          atlas_compare.cell_code(cell(1, 1, "quasi", "domain")) == 16)
    check("cell code: every start leaving the domain = 32 (lift-off)",
          atlas_compare.cell_code(cell(1, 1, "domain", "domain")) == 32)
    check("cell code: an unsettled start gives no code",
          atlas_compare.cell_code(cell(1, 1, "straight", "unsettled")) is None)
    # the vertical line V = 300 m/s: distance (V - 300) / 600 at any F*
    line = {"name": "hopf", "kind": "hopf", "V": [300.0, 300.0], "Fstar": [0.0, 3.5]}
    d, name = atlas_compare.curve_distance([line], 330.0, 1.75)
    check_close("distance to the segment V = 300: 30 / 600", d, 0.05, rel=1e-12)
    check("nearest curve named", name == "hopf", name)
    stub = {"region_map": {"V": [0.0, 200.0, 400.0, 600.0], "Fstar": [0.0, 3.5],
                           "code": [[1, 1, 4, 4], [1, 1, 4, 4]], "names": {"1": "straight"}},
            "edge_curves": [line]}
    cells = [cell(100, 1, "straight"), cell(500, 1, "straight", "high"), cell(303, 1, "high"),
             cell(450, 2, "high"), cell(150, 2, "unsettled"), cell(550, 2, "high", "yaw")]
    r = atlas_compare.compare(cells, stub)
    check("stub: V = 303 (distance 0.005 < NEAR) on the curve",
          [(e["V"], e["Fstar"]) for e in r["on_curve"]] == [(303, 1)], r["on_curve"])
    check("stub: V = 100, 450 and 550 (yaw bit not compared) agree",
          [e["V"] for e in r["agree"]] == [100, 450, 550], r["agree"])
    check("stub: V = 550 listed with a differing yaw bit",
          [e["V"] for e in r["yaw_differs"]] == [550], r["yaw_differs"])
    check("stub: V = 500 (straight + high in the high region) and 150 (not settled) disagree",
          [(e["V"], e["atlas_name"]) for e in r["disagree"]]
          == [(500, "straight + high"), (150, "not settled")], r["disagree"])
    check_close("stub: fraction 3 of 5", r["fraction"], 0.6, rel=1e-12)
    check("stub: report lists both disagreeing cells",
          sum("disagree V" in line for line in atlas_compare.report(r)) == 2)


def main():
    synthetic()
    unstable_orbit()
    confirmation()
    comparison()
    bad_input()
    simulated()


if __name__ == "__main__":
    main()
