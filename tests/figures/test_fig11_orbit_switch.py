"""An orbit curve's MX end where its orbit grazes the oleo's stage switch
(figures/fig11/ends.py, shared/stage_switch.py), on synthetic orbits, no
AUTO run: how near an orbit's extremes of compression come to the switch,
kept with each MX end through the stored part, and the end sorted by it."""
import json

import numpy
import pytest

from mlgshimmy.figures.fig11 import ends
from mlgshimmy.shared import jobs, mlgmodel, stage_switch

MODEL = mlgmodel.Model("figures")
ETA_S, K = MODEL["eta_stage"], MODEL["k_stage"]


class Orbit:
    """An AUTO solution as extremes_from_switch reads it: coordarray, one
    row per state (U(1) ... U(NX)), here eta = eta_s + widths / k_stage."""

    def __init__(self, widths):
        rows = numpy.zeros((mlgmodel.NX, len(widths)))
        rows[mlgmodel.UNAMES.index("eta")] = ETA_S + numpy.asarray(widths) / K
        self.coordarray = rows


@pytest.mark.parametrize("widths, expected", [
    ([-136.0, -40.0, 0.597, -80.0], 0.597),   # the largest compression just inside
    ([-186.4, -90.0, -120.0], 90.0),          # left the switch: 90 widths below it
    ([-300.0, 0.0, 250.0], 250.0),            # passes through it: extremes far from it
    ([12.0, 3.0, 40.0], 3.0),                 # above it, the smallest compression near
])
def test_extremes_from_switch_in_widths(widths, expected):
    assert stage_switch.extremes_from_switch(Orbit(widths)) == pytest.approx(expected, rel=1e-6)


class Run(jobs.Branch):
    """A run's branch that gives its solutions by label, as AUTO's does."""

    def __init__(self, record, orbits):
        super().__init__(record)
        self.orbits = orbits

    def __call__(self, label):
        return self.orbits[label]


def test_mx_orbits_distance_is_stored_with_the_end_and_sorts_it():
    """jobs.stored keeps at_mx per MX point (through the part's JSON); the
    end then carries it ("switch") and within ends.SWITCH_WIDTHS it is an
    end where the orbit grazes the switch, beyond it an open stop."""
    def run(widths, V):   # two ends apart: not a tongue's tip (ends.JOIN_TOL)
        record = {"columns": {"V": [400.0, 430.0, V], "Fstar": [0.81, 0.88, 0.9423]},
                  "stable": [False] * 3, "labels": [[0, 1, "EP"], [2, 10, "MX"]]}
        return [Run(record, {10: Orbit(widths), 1: Orbit([-1e3, 1e3])})]
    near, far = ([json.loads(json.dumps(jobs.stored(run(w, V), ("V", "Fstar"),
                                                    ends.orbit_at_switch),
                                        default=lambda a: a.tolist()))
                  for w, V in (([-136.0, 0.597], 462.86), ([-186.4, -12.0], 500.0))])
    assert jobs.loaded(near)[0].at_mx == {2: pytest.approx(0.597, rel=1e-6)}
    _, stops = ends.mx_ends({"tongue": [near, far]})
    assert [s["switch"] for s in stops] == [pytest.approx(0.597, rel=1e-6),
                                            pytest.approx(12.0, rel=1e-6)]
    found = ends.explained(stops, None, None)
    assert [s["curve"] for s in found["orbit_switch"]] == ["tongue1"]
    assert [s["curve"] for s in found["open"]] == ["tongue2"]


def test_an_end_without_its_orbit_stays_open():
    """A stored curve without at_mx (a Hopf curve, an older part) is sorted
    by its place alone."""
    stop = {"V": 462.86, "Fstar": 0.9423, "curve": "tongue1"}
    assert ends.explained([stop], None, None)["open"] == [stop]


def test_a_more_particular_cause_comes_first():
    """A torus curve's end on a fold curve (ends.FOLD_TOL) stays "on_fold"
    even where its orbit also grazes the switch."""
    fold = [jobs.Branch({"columns": {"V": [60.0, 63.4, 70.0], "Fstar": [0.03, 0.0307, 0.032]},
                         "stable": [False] * 3, "labels": []})]
    stop = {"V": 63.4, "Fstar": 0.0307, "curve": "torus2", "switch": 0.5}
    found = ends.explained([stop], None, None, [fold])
    assert found["on_fold"] == [stop] and not found["orbit_switch"]
