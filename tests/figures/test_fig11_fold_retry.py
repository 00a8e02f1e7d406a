"""Fig. 11's fold curves (curves.fold_curve): an MX end inside the stage
switch or on the Hopf locus is an end (ends.explained), any other sends the
curve up the shared retry ladder (continuation.Ends), which keeps the last
rung and reports it if every rung stops there too; no AUTO run."""
import pytest

from mlgshimmy.figures.fig11 import curves, ends
from mlgshimmy.shared import continuation

SWITCH = (0.627, 0.700)


@pytest.fixture
def explained(monkeypatch):
    monkeypatch.setattr(curves, "stage_switch", lambda: SWITCH)
    # the Hopf locus of straight rolling: V = 134 m/s here
    monkeypatch.setattr(ends, "on_hopf_locus", lambda stop: abs(stop["V"] - 134.0) < 0.5)
    return curves.fold_end_explained


@pytest.mark.parametrize("stop", [{"V": 137.4, "Fstar": 0.6949},   # inside the switch
                                  {"V": 134.1, "Fstar": 0.0263}])  # on the Hopf locus
def test_an_explained_stop_is_an_end(explained, stop):
    assert explained(stop, "V")


def test_any_other_stop_is_not(explained):
    assert not explained({"V": 473.54, "Fstar": 0.9804}, "V")


def test_fold_curves_use_the_shared_ladder_and_keep_what_they_have(monkeypatch):
    made = []
    monkeypatch.setattr(curves.ct, "fold_curve", lambda *a, **kw: made.append(kw))
    curves.fold_curve("dir", "fold1-", {}, -1, time_limit=curves.FOLD_TIME_LIMIT)
    ends_, = [kw["allow_mx"] for kw in made]
    assert isinstance(ends_, continuation.Ends) and ends_.keep
    assert ends_.explains is curves.fold_end_explained
    assert made[0]["DS"] == -0.05 and made[0]["time_limit"] == curves.FOLD_TIME_LIMIT
