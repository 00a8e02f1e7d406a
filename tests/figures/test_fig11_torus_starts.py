"""Fig. 11's torus part with side-stay angles (tori.found_curves): two
crossings inside one step of a slice's orbit branch (a window that opens
and closes between two steps) are placed by AUTO at one TR label; the curve
from it is continued once, not twice (at rho = 5, mu = -15 deg two tongue
edges from V = 131.25 m/s ran the same 150 steps, 46 s each)."""
from mlgshimmy.figures.fig11 import tori


def crossing(V, direction):
    return {"value": V, "angle": 1.0, "direction": direction, "slope_per_unit": 1e-4,
            "between": (126.0, 133.0)}


def test_two_crossings_placed_at_one_tr_label_start_one_curve(monkeypatch, capsys):
    edge = [{"V": [131.25, 131.25, 131.3], "Fstar": [0.70, 0.6875, 0.67]}]   # one branch
    continued = []
    monkeypatch.setattr(tori, "SLICES", (0.6875,))
    monkeypatch.setattr(tori, "stage_switch", lambda: None)
    monkeypatch.setattr(tori, "diagrams_on", lambda Fstar, large: [
        ("orbits", [crossing(127.2, 1), crossing(129.9, -1)])])
    monkeypatch.setattr(tori.torus, "tr_point", lambda rundir, name, bd, v, slope, between:
                        {"V": 131.25, "Fstar": 0.6875, "name": name})
    monkeypatch.setattr(tori.torus, "torus_curve",
                        lambda rundir, name, tr, steps: continued.append(name) or (edge,))
    monkeypatch.setattr(tori.jobs, "stored", lambda run, columns, _at_mx: list(run))
    found = tori.found_curves(set())
    assert continued == ["tongue1"], continued
    assert len(found["tongue"]) == 1 and found["points"] == [], found
    assert "start tr2 at V = 131.2, F* = 0.6875 lies on a curve found already" \
        in capsys.readouterr().out
