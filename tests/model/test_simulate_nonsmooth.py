"""The simulator with the non-smooth law (14) (--param freeplay_law=1):
CVODE's root finding on h+- restarts the integration at every crossing in
the new mode; the settled orbit is the limit of the smoothed model's as
eps -> 0.  Fig. 10's gear (F* = 1, y_fp = 1 mm) at V = 100 m/s, on the
high-frequency orbit (23.6 Hz), 10 s from psi = 0.01 rad.

Run: /usr/bin/python3 -m pytest -q tests/model/test_simulate_nonsmooth.py
"""
import pytest

import helpers
from mlgshimmy.shared import mlgmodel, simulator

RUN = ("--V", 100, "--Fstar", 1, "--yfp", 1, "--t-end", 10, "--psi0", 0.01,
       "--rtol", 1e-10, "--atol", 1e-12)


@pytest.fixture(scope="module")
def runs():
    """{eps/y_fp: summary} of the smoothed law (15), and 0: law (14)."""
    law14 = mlgmodel.LAWS.index("nonsmooth")
    out = {0.0: simulator.simulate(None, *RUN, params={"freeplay_law": law14})}
    for ratio in (1e-2, 1e-3):
        out[ratio] = simulator.simulate(None, *RUN, "--eps-rel", ratio)
    return out


def test_every_switch_is_located(runs):
    """Two crossings of each surface per period over the settled window and
    the transient before it (the orbit crosses both surfaces each period)."""
    law14 = runs[0.0]
    periods = law14["frequency_hz"] * 9.0
    for surface in ("upper", "lower"):
        assert law14[f"crossings_freeplay_{surface}"] >= 2 * periods
    assert "crossings_freeplay_upper" not in runs[1e-3]        # a smooth law: no events


def test_the_smoothed_orbit_tends_to_law_14s(runs):
    """Amplitude and frequency: eps = 1e-3 y_fp within 1e-6 of law (14),
    ten times closer than eps = 1e-2 y_fp (measured: 1.2e-7 and 2.0e-5 for
    the amplitude)."""
    law14 = runs[0.0]
    error = {ratio: {key: abs(runs[ratio][key] / law14[key] - 1)
                     for key in ("psi_amplitude_rad", "frequency_hz")}
             for ratio in (1e-2, 1e-3)}
    assert error[1e-3]["psi_amplitude_rad"] < 1e-6
    assert error[1e-3]["frequency_hz"] < 1e-6
    assert error[1e-3]["psi_amplitude_rad"] < 0.1 * error[1e-2]["psi_amplitude_rad"]


def test_the_fold_by_simulation_is_auto_s_fold():
    """simulator.fold_speed at Fig. 10's eps = 0.1 y_fp against the fold S1
    that AUTO located for the reference set (tests/reference/fig10): low by
    the slow passage past the fold, at most 3e-3 m/s (measured 1.1e-3)."""
    import json
    import pathlib
    named = pathlib.Path(helpers.ROOT, "tests", "reference", "fig10", "named.json")
    auto_s = json.loads(named.read_text())["numbers"]["S1 [m/s]"]
    s = simulator.fold_speed(40.0, 43.0, 1e-3, {"Fstar": 1.0, "yfp": 1.0, "eps_abs": 0.0,
                                                 "eps_rel": 0.1})
    print(f"# S: AUTO {auto_s:.6f} m/s, by simulation {s:.6f} m/s")
    assert auto_s - 3e-3 < s < auto_s + 1e-3


def test_the_events_file_lists_every_switch_on_its_surface(tmp_path):
    """--events: one row per crossing, as many as the summary counts, each
    state on its surface (|r_tlk(eta) psi| = y_fp within 1e-9 of y_fp) and
    the mode after it the table's (mlg_switching_mode_after)."""
    import numpy
    law14 = {"freeplay_law": mlgmodel.LAWS.index("nonsmooth")}
    path = tmp_path / "events.csv"
    summary = simulator.simulate(None, "--V", 100, "--Fstar", 1, "--yfp", 1, "--t-end", 1,
                                 "--psi0", 0.01, "--events", str(path), params=law14)
    rows = numpy.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding=None)
    for surface, sign in (("upper", 1.0), ("lower", -1.0)):
        mine = rows[rows["switch"] == f"freeplay_{surface}"]
        assert len(mine) == summary[f"crossings_freeplay_{surface}"] > 0
        model = mlgmodel.Model("figures", V=100.0, Fstar=1.0, yfp=1.0, **law14)
        y = numpy.array([model.r_tlk(r["eta"]) * r["psi"] for r in mine])
        assert numpy.allclose(y, sign * 1e-3, rtol=0, atol=1e-12)
        # upper: up into contact+ (1), down into the gap; lower: down into contact- (2)
        after = {("upper", 1): 1, ("upper", -1): 0, ("lower", -1): 2, ("lower", 1): 0}
        assert all(r["mode"] == after[surface, r["direction"]] for r in mine)
