"""Hopf points named by their mode (shared.naming): the paper's H1-H3 at
its gear, H3 alone at (rho, mu) = (20, 5) deg, and criticality from the
side of the orbit branch.

Run: /usr/bin/python3 -m pytest -q tests/test_naming.py
"""
import math

import numpy
import pytest

from mlgshimmy.shared import continuation, naming, spectrum

FREEPLAY = {"Fstar": 1.0, "yfp": 1.0, "eps_rel": 0.1}


def modes_along_V(**gear):
    hopf = spectrum.hopf_scan("figures", "V", continuation.SPEED_SCAN, **FREEPLAY, **gear)
    return hopf, [naming.mode("figures", "V", v, **FREEPLAY, **gear) for v, _ in hopf]


def test_the_paper_s_gear_has_its_three_named_points():
    hopf, modes = modes_along_V()
    assert naming.names(modes) == ["H1", "H2", "H3"]
    assert [m["band"] for m in modes] == ["low", "low", "high"]
    assert [m["loses"] for m in modes] == [True, False, True]
    # the paper's 1.5, 28.1, 142.5 m/s (Fig. 10), as docs/reproduction.md compares them
    assert [v for v, _ in hopf] == pytest.approx([1.458, 28.307, 144.270], abs=2e-3)
    # criticality by l1 (shared.lyapunov): the low-frequency orbits stable, H3's not
    assert [naming.by_l1(m["l1"]) for m in modes] == ["supercritical", "supercritical",
                                                      "subcritical"]


def test_a_disagreement_of_l1_and_the_branch_is_said():
    m = {"band": "high", "dof": "lateral", "loses": True, "l1": 0.0338}
    assert naming.describe(m, "subcritical").endswith("subcritical (l1 = +0.0338; the orbit "
                                                      "branch agrees)")
    assert "DISAGREES with the orbit branch, which is supercritical" in \
        naming.describe(m, "supercritical")
    assert "no orbit branch near it to check" in naming.describe(m, None)


def test_a_lone_high_frequency_point_is_h3_not_h1():
    """At (20, 5) deg the low-frequency pair never loses stability: the one
    Hopf point (110.4 m/s, 13 Hz) is H3, and H1, H2 do not exist."""
    hopf, modes = modes_along_V(rho=math.radians(20), mu=math.radians(5), eom_terms=2.0)
    assert naming.names(modes) == ["H3"]
    assert hopf[0][0] == pytest.approx(110.446, abs=2e-3)
    assert modes[0]["freq_hz"] == pytest.approx(13.04, abs=0.01)


@pytest.mark.parametrize("bands, loses, expected", [
    (["low", "low", "high"], [True, False, True], ["H1", "H2", "H3"]),
    (["low", "high"], [False, True], ["H2", "H3"]),          # low pair unstable from the start
    (["high", "low", "low", "high"], [True, True, False, False],
     ["H3", "H1", "H2", "Hhf2"]),
    (["low", "low", "low", "low"], [True, False, True, False], ["H1", "H2", "Hlf3", "Hlf4"]),
])
def test_names_follow_the_mode_not_the_order(bands, loses, expected):
    modes = [{"band": b, "loses": l} for b, l in zip(bands, loses)]
    assert naming.names(modes) == expected


class Run(list):
    pass


def branch(V, amp):
    return {"V": numpy.asarray(V, float), "psi_amp": numpy.asarray(amp, float)}


def test_criticality_is_the_side_of_the_orbits():
    up = Run([branch([10.0, 10.4, 11.0], [0.0, 1e-3, 2e-3])])     # born at 10, grows in V
    down = Run([branch([10.0, 9.6, 9.0], [0.0, 1e-3, 2e-3])])
    assert naming.criticality(10.0, True, [up]) == "supercritical"
    assert naming.criticality(10.0, True, [down]) == "subcritical"
    assert naming.criticality(10.0, False, [down]) == "supercritical"
    ending = Run([branch([2.0, 9.0, 9.99], [0.0, 1e-2, 1e-4])])   # collapses onto 10 from below
    assert naming.criticality(10.0, False, [ending]) == "supercritical"
    assert naming.criticality(50.0, True, [up]) is None
