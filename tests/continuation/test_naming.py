"""Hopf points named by their mode (shared.naming): the paper's H1-H3 at
its gear, H3 alone at (rho, mu) = (20, 5) deg, and criticality from the
side of the orbit branch.

Run: /usr/bin/python3 -m pytest -q tests/continuation/test_naming.py
"""
import math

import numpy
import pytest

from mlgshimmy.shared import continuation, naming, spectrum, yfp_stored
from mlgshimmy.shared.jobs import cache

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


def branch(V, amp, stable):
    """A stored orbit branch (jobs.cache.Branch), stable or not throughout."""
    return cache.Branch({"columns": {"V": V, "psi_amp": amp}, "stable": [stable] * len(V),
                         "labels": []})


def test_criticality_is_the_side_and_stability_of_the_orbits():
    up = Run([branch([10.0, 10.4, 11.0], [0.0, 1e-3, 2e-3], True)])     # born at 10, grows in V
    down = Run([branch([10.0, 9.6, 9.0], [0.0, 1e-3, 2e-3], False)])
    assert naming.criticality(10.0, True, [up]) == "supercritical"
    assert naming.criticality(10.0, True, [down]) == "subcritical"
    assert naming.criticality(10.0, False, [up]) == "inconsistent"   # stable, on the stable side
    stable_down = Run([branch([10.0, 9.6, 9.0], [0.0, 1e-3, 2e-3], True)])
    assert naming.criticality(10.0, False, [stable_down]) == "supercritical"
    ending = Run([branch([2.0, 9.0, 9.99], [0.0, 1e-2, 1e-4], True)])   # onto 10 from below
    assert naming.criticality(10.0, False, [ending]) == "supercritical"
    assert naming.criticality(50.0, True, [up]) is None


@pytest.mark.parametrize("V, verdict, decay", [
    (1.4581594746679292, "supercritical", (0.0, 1e-4)),
    (28.306722207961514, "supercritical", (0.0, 1e-4)),
    (144.26969033434705, "subcritical", (0.8, 1.0)),
])
def test_simulations_on_each_side_say_what_l1_says(V, verdict, decay):
    """At H1-H3 of the paper's gear: from a push of 1e-6 rad on the unstable
    side the motion grows (to 9.6e-4, 2.0e-3, 5.3e-3 rad); started with that
    amplitude on the stable side it decays to 2.9e-6 and 6.2e-6 of it at H1
    and H2 (no orbit there) and keeps 0.88 of it at H3 (the orbits from H3
    fold back at S into stable ones)."""
    m = naming.mode("figures", "V", V, **FREEPLAY)
    said = naming.simulated("figures", "V", V, m, **FREEPLAY)
    assert said["verdict"] == verdict == naming.by_l1(m["l1"])
    assert decay[0] < said["decay"] < decay[1]
    assert said["amplitude"] > 100 * naming.PSI0


def test_weak_l1_is_where_the_normal_form_leaves_the_freeplay():
    """The normal form's orbit at real part 0.01 omega: 0.44 freeplay angles
    at H1 (not weak), 2.2 at H2, 4.0 at H3 (weak: simulated)."""
    weak = [naming.mode("figures", "V", V, **FREEPLAY)["weak"]
            for V in (1.4581594746679292, 28.306722207961514, 144.26969033434705)]
    assert weak == [False, True, True]


def test_the_three_checks_are_counted_and_said():
    m = {"band": "high", "dof": "lateral", "loses": True, "l1": 0.0338, "weak": True}
    sub = {"verdict": "subcritical", "distance": 12.9, "amplitude": 5.3e-3, "decay": 0.88}
    sup = {**sub, "verdict": "supercritical"}
    assert naming.verdicts(m, "subcritical", sub)["agree"]
    assert not naming.verdicts(m, "subcritical", sup)["agree"]
    assert not naming.verdicts(m, None, None)["agree"]          # nothing checked it
    assert "simulation agrees (at 12.9 either side" in naming.describe(m, "subcritical", sub)
    assert "DISAGREES with simulation, which is supercritical" in \
        naming.describe(m, "subcritical", sup)
    assert naming.needs_simulation(m, "subcritical")            # weak
    assert naming.needs_simulation({**m, "weak": False}, "supercritical")   # disagrees
    assert not naming.needs_simulation({**m, "weak": False}, "subcritical")
    points = [{"agree": True}, {"agree": False}, {"agree": True}]
    assert naming.agreement(points).startswith("criticality: 2 of 3 Hopf points agree")


ANGLED = {"V": 50.0, "yfp": 1.0, "eps_rel": 0.1, "rho": math.radians(-10),
          "mu": math.radians(20), "eom_terms": 2.0}


@pytest.mark.parametrize("Fstar, a2, l1, verdict, kink_decides", [
    (0.8759784630060929, -0.4009, 22.37, "supercritical", True),
    (1.8344630186915616, -3.91e-7, 21.41, "subcritical", False),
])
def test_the_oleo_kink_decides_where_the_mode_moves_eta_dot(Fstar, a2, l1, verdict,
                                                             kink_decides):
    """Fig. 12 at (-10, 20) deg (V = 50 m/s): at F* = 0.876 the mode moves
    eta' (|q_eta'| = 0.32 of max q) and the oleo's |eta'| eta' gives a2 =
    -0.40: supercritical up to psi 9.2e-6 rad, where l1 = +22.4 takes
    over, as the orbit branch and the simulation say (l1 alone said
    subcritical); at 1.834 a2 = -3.9e-7 yields to l1 above psi ~1e-10 rad."""
    m = naming.mode("figures", "Fstar", Fstar, **ANGLED)
    assert m["a2"] == pytest.approx(a2, rel=1e-3)
    assert m["l1"] == pytest.approx(l1, rel=1e-3)
    assert naming.kink_decides(m) == kink_decides
    assert naming.by_coefficients(m) == verdict


def test_no_kink_at_the_symmetric_gear():
    m = naming.mode("figures", "V", 144.26969033434705, **FREEPLAY)
    assert abs(m["a2"]) < 1e-15 and m["kink_psi"] < naming.KINK_NOISE
    assert "a2" not in naming.describe(m, "subcritical")


def test_a_diagram_names_its_hopf_points_once_and_only_when_read():
    calls = []

    def naming_of_points():
        calls.append(1)
        return [{"name": "H3"}]
    diagram = continuation.Diagram("V", [(144.27, 13.0)], [], [], [], naming_of_points)
    assert calls == []        # Fig. 11's slices never read them: no simulations made
    assert [p["name"] for p in diagram.named] == ["H3"]
    assert diagram.named is diagram.named and calls == [1]


def test_folds_are_named_by_family_and_speed_not_by_order_found():
    """At rho = 20, mu = 5 deg Fig. 13's y_fp = 1 diagram found the fold at
    129.6 m/s first and printed it as S1 against the paper's 41.5; Fig. 10
    named the same folds S1 = 42.47, S2 = 129.6.  Both now name them so."""
    folds = [(129.601, 17.4), (42.472, 13.1), (20.0, 3.2), (10.0, 2.9)]
    assert naming.fold_names(folds) == [("S1", 42.472), ("S2", 129.601),
                                        ("low-frequency fold 1", 10.0),
                                        ("low-frequency fold 2", 20.0)]
    stored = {"yfp": 1.0, "hopf": [], "hopf_names": [], "folds": [(V, 1e-3) for V, _ in folds],
              "fold_hz": [hz for _, hz in folds]}
    assert yfp_stored.diagram_numbers([stored]) == {
        "y_fp = 1: S1 [m/s]": 42.472, "y_fp = 1: S2 [m/s]": 129.601,
        "y_fp = 1: low-frequency fold 1 [m/s]": 10.0, "y_fp = 1: low-frequency fold 2 [m/s]": 20.0}
