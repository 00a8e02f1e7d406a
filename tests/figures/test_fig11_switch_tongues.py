"""Fig. 11's torus starts at a side-stay geometry (fig11.tori.found_curves):
a tongue edge started on a load inside the oleo's stage switch is followed
SWITCH_CURVE_STEPS steps each way; a torus curve there, and a tongue edge
outside it, keep torus.CURVE_STEPS (AUTO's runs faked)."""
import numpy as np

from mlgshimmy.figures.fig11 import tori
from mlgshimmy.shared import torus

SWITCH = (0.627, 0.700)


def crossing(V, kind):
    return {"value": V, "angle": 1.0, "direction": 1, "slope_per_unit": 0.01, "kind": kind}


def run_starts(monkeypatch, tmp_path, found):
    """The (name, F*, steps) of every curve found_curves starts, with the
    crossings `found` ({F*: [(V, kind)]}) on the slices' diagrams."""
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    monkeypatch.setattr(tori, "SLICES", np.array(sorted(found)))
    monkeypatch.setattr(tori, "stage_switch", lambda: SWITCH)
    monkeypatch.setattr(tori, "diagrams_on", lambda F, _loads: [
        (F, [crossing(V, kind) for V, kind in found[F]])])
    monkeypatch.setattr(tori, "crossing_kinds", lambda cs: [c["kind"] for c in cs])
    started = []

    def tr_point(_rundir, _name, Fstar, V, _slope, _between):   # the diagram: its load
        return {"V": V, "Fstar": Fstar}

    def torus_curve(_rundir, name, tr, steps):
        started.append((name, tr["Fstar"], steps))
        return ([{"V": [tr["V"], tr["V"] + 1e-3], "Fstar": [tr["Fstar"]] * 2}],)   # one run
    monkeypatch.setattr(tori.torus, "tr_point", tr_point)
    monkeypatch.setattr(tori.torus, "torus_curve", torus_curve)
    monkeypatch.setattr(tori.jobs, "stored", lambda run, _columns, _at_mx: run)
    tori.found_curves(set())
    return started


def test_a_tongue_edge_inside_the_switch_is_followed_fewer_steps(monkeypatch, tmp_path):
    started = run_starts(monkeypatch, tmp_path, {
        0.5625: [(300.0, "tongue")], 0.6875: [(130.0, "tongue"), (420.0, "torus")],
        0.8125: [(470.0, "tongue")]})
    assert started == [("tongue1", 0.5625, torus.CURVE_STEPS),
                       ("tongue2", 0.6875, tori.SWITCH_CURVE_STEPS),
                       ("torus3", 0.6875, torus.CURVE_STEPS),
                       ("tongue4", 0.8125, torus.CURVE_STEPS)]
    assert tori.SWITCH_CURVE_STEPS < torus.CURVE_STEPS


def test_no_switch_window_keeps_every_budget(monkeypatch, tmp_path):
    monkeypatch.setattr(tori.ends, "inside", lambda switch, F: False)
    started = run_starts(monkeypatch, tmp_path, {0.6875: [(130.0, "tongue")]})
    assert started == [("tongue1", 0.6875, torus.CURVE_STEPS)]
