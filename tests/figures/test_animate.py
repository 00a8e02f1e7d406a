"""The gear's motion (shared.motion, shared.draw.gear_motion, studies.animate):
what a start settles on, the frames it keeps, the stated scales, and one-line
refusals of bad input.

Run: /usr/bin/python3 -m pytest -q tests/figures/test_animate.py   (about 30 s)
"""
import json
import os
import subprocess

import matplotlib
matplotlib.use("Agg")
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from helpers import ROOT  # noqa: E402
from mlgshimmy.shared import freeplay, mlgmodel, motion  # noqa: E402
from mlgshimmy.shared.draw import gear_motion  # noqa: E402
from mlgshimmy.studies import animate  # noqa: E402


@pytest.fixture(scope="module")
def shimmy(tmp_path_factory):
    return motion.settle(300.0, 1.0, freeplay.NOMINAL, "shimmy", animate.T_END,
                         str(tmp_path_factory.mktemp("shimmy")))


def test_a_large_start_at_300_settles_on_high_frequency_shimmy(shimmy):
    # as make animate V=300 FSTAR=1 (40 s): 38.46 Hz, psi amplitude 0.02335 rad
    assert shimmy["kind"] == "high"
    assert shimmy["frequency_hz"] == pytest.approx(38.46, abs=0.05)
    assert shimmy["amplitude_rad"] == pytest.approx(0.02335, rel=0.01)
    frames = shimmy["frames"]
    assert len(frames["t"]) == motion.PERIODS * motion.FRAMES_PER_PERIOD
    span = frames["t"][-1] - frames["t"][0]
    assert span == pytest.approx(motion.PERIODS / shimmy["frequency_hz"] * (1 - 1 / 60), rel=1e-9)
    # the torque-link apex deflection is r_tlk psi: it swings well past the +-1 mm gap
    model = mlgmodel.Model("figures", V=300.0, Fstar=1.0, **freeplay.NOMINAL)
    k = int(np.argmax(np.abs(frames["psi"])))
    assert frames["y_tlk"][k] == pytest.approx(model.r_tlk(frames["eta"][k]) * frames["psi"][k],
                                               rel=1e-12)
    assert max(np.abs(frames["y_tlk"])) > 5 * shimmy["yfp_m"]


def test_the_yawed_start_stays_yawed_at_50_and_light_load(tmp_path):
    # the yawed state at F* = 0.2 is stable at 50 m/s (tests/model/test_yawed.py)
    found = motion.settle(50.0, 0.2, freeplay.NOMINAL, "yawed", 12.0, str(tmp_path))
    assert found["kind"] == "yaw" and found["frequency_hz"] == 0.0
    assert len(found["frames"]["t"]) == motion.STILL_FRAMES
    assert abs(found["frames"]["psi"][0]) > 1e-3           # off centre: psi_yaw ~ 1.7e-3 rad


@pytest.mark.parametrize("swing, mean, expected", [
    (0.02335, 0.0, 10.0),           # 1.3 deg -> 13 deg
    (0.002, 0.0, 100.0),            # 0.11 deg -> 11 deg
    (0.3, 0.0, 1.0),                # already large: never shrunk
    (1e-12, 0.0, 1.0),              # a stationary state's rounding: nothing moves
    (1e-12, 1.7e-3, 200.0),         # a yawed state: its offset made visible
])
def test_scales_are_round_and_state_what_is_drawn(swing, mean, expected):
    t = np.linspace(0.0, 1.0, 61)
    psi = mean + swing * np.sin(2 * np.pi * t)
    frames = {"psi": psi, "delta": 0 * t, "beta": 0 * t, "lambda_L": 0 * t, "lambda_R": 0 * t}
    assert motion.scales(frames)["angle"] == expected
    assert motion.scales(frames)["deflection"] == 1.0


def test_each_frame_moves_the_pin_to_its_torque_link_deflection(shimmy):
    fig, show = gear_motion.figure(shimmy, motion.scales(shimmy["frames"]), "test")
    pin = [line for line in fig.axes[2].lines if line.get_marker() == "o"][0]
    for k in (0, 17, 45):
        show(k)
        assert pin.get_xdata()[0] == pytest.approx(1e3 * shimmy["frames"]["y_tlk"][k])
        engaged = abs(shimmy["frames"]["y_tlk"][k]) > shimmy["yfp_m"]
        assert matplotlib.colors.to_hex(pin.get_color()) == ("#e69f00" if engaged else "#0b3d91")
    matplotlib.pyplot.close(fig)


@pytest.mark.parametrize("args, message", [
    (["V=300", "FSTAR=1", "START=yaw"],
     "animate: START='yaw' is not one of rolling, shimmy, yawed; did you mean yawed?"),
    (["V=-3", "FSTAR=1"], "animate: V=-3 must be a finite number >= 0"),
    (["V=300", "FSTAR=x"], "animate: argument --Fstar: invalid float value: 'x'"),
])
def test_make_animate_refuses_bad_input_in_one_line(args, message):
    proc = subprocess.run(["make", "-s", "--no-print-directory", "animate", *args], cwd=ROOT,
                          capture_output=True, text=True)
    assert proc.returncode != 0
    assert [line for line in proc.stderr.splitlines() if not line.startswith("make")] == [message]


def test_motion_scale_is_stated_on_the_frame(shimmy):
    fig, _ = gear_motion.figure(shimmy, {"angle": 10.0, "deflection": 20.0}, "test")
    texts = [t.get_text() for t in fig.texts]
    assert any("angles ×10, tyre deflections ×20" in t for t in texts), texts
    matplotlib.pyplot.close(fig)


def at_rho20_mu5(code):
    """The last line printed by the Python `code` run at rho = 20, mu = 5 deg
    (the gear is read from the environment when the model is built)."""
    env = {"PATH": "/usr/bin:/bin", "PYTHONPATH": os.path.join(ROOT, "drivers"),
           "MLG_RHO_DEG": "20", "MLG_MU_DEG": "5", "MLG_EOM": "2"}
    proc = subprocess.run(["/usr/bin/python3", "-c", code], env=env, cwd=ROOT,
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr[-2000:]
    return proc.stdout.splitlines()[-1]


def test_a_wheel_lifting_off_early_is_drawn_as_such():
    """At rho = 20, mu = 5 deg, V = 450 m/s, F* = 0.3 (make gear's third
    animation) the shimmy start lifts a wheel off at t = 3.0 s, before the
    classifier's 2 x 5 s: the motion up to there is kind "domain" with the
    high-frequency shimmy's numbers from its last LIFTOFF_SPAN, not an error."""
    code = ("import json, sys, tempfile\n"
            "from mlgshimmy.shared import freeplay, motion\n"
            "m = motion.settle(450.0, 0.3, freeplay.NOMINAL, 'shimmy', 40.0, tempfile.mkdtemp())\n"
            "print(json.dumps(dict({k: m[k] for k in ('kind', 'frequency_hz', 'amplitude_rad')},"
            " t_end=m['start']['t_end'], frames=len(m['frames']['t']))))\n")
    found = json.loads(at_rho20_mu5(code))
    assert found["kind"] == "domain"
    assert 2.0 < found["t_end"] < 2 * motion.WINDOW
    assert 20.0 < found["frequency_hz"] < 60.0           # the high-frequency mode
    assert found["amplitude_rad"] > 0.01
    assert found["frames"] > 50


def test_the_yawed_load_is_the_nearest_that_has_a_yawed_state():
    """make gear's yawed animation (NEAR=1): at the paper's gear F* = 0.2
    has yawed states and is kept; from 1.5 the nearest load with one lies
    just below the upper pitchfork (F* = 0.41 in Fig. 11).  At rho = 20,
    mu = 5 deg they end below 0.2: the nearest is 0.19."""
    assert motion.yawed_load(0.2, freeplay.NOMINAL) == 0.2
    assert 0.36 <= motion.yawed_load(1.5, freeplay.NOMINAL) <= 0.45
    code = ("from mlgshimmy.shared import freeplay, motion\n"
            "print(motion.yawed_load(0.2, freeplay.NOMINAL))\n")
    assert float(at_rho20_mu5(code)) == 0.19
