"""Fig. 11's fold curves (curves.fold_curve) on stand-in runs (no AUTO run):
one that AUTO stops (MX) where nothing explains it is run again on the
fine mesh with a longer guard; one that stops inside the stage switch, on
the Hopf locus or nowhere is not; a fine run that fails leaves the coarse
one."""
import pytest

from mlgshimmy.figures.fig11 import curves, ends
from mlgshimmy.shared import autoglue

SWITCH = (0.627, 0.700)


class Run:
    """A stand-in for a finished AUTO run: run("MX") lists its MX points."""

    def __init__(self, name, mx):
        self.name, self.mx = name, mx

    def __call__(self, label):
        assert label == "MX"
        return self.mx


@pytest.fixture
def calls(monkeypatch):
    """The fold-curve runs asked for, as (name, keywords); each returns a Run
    with the MX points that ENDS gives for its name (a RunError for
    "fail")."""
    made = []
    outcomes = {}

    def fold_curve(rundir, name, point, parameters, **kw):
        made.append((name, kw))
        outcome = outcomes.get(name, [])
        if outcome == "fail":
            raise autoglue.RunError(f"run {name}: no convergence")
        return Run(name, outcome)

    monkeypatch.setattr(curves.ct, "fold_curve", fold_curve)
    monkeypatch.setattr(curves, "stage_switch", lambda: SWITCH)
    # the Hopf locus of straight rolling: V = 134 m/s here
    monkeypatch.setattr(ends, "on_hopf_locus", lambda stop: abs(stop["V"] - 134.0) < 0.5)
    return made, outcomes


def test_an_unexplained_stop_is_run_again_on_the_fine_mesh(calls):
    made, outcomes = calls
    outcomes["fold1-"] = [{"V": 473.54, "Fstar": 0.9804}]
    run = curves.fold_curve("dir", "fold1-", {}, -1, time_limit=curves.FOLD_TIME_LIMIT)
    assert run.name == "fold1-_fine"
    (coarse, first), (fine, second) = made
    assert (coarse, fine) == ("fold1-", "fold1-_fine")
    assert first["DS"] == -0.05 and "NTST" not in first
    assert first["time_limit"] == 120
    assert second["NTST"] == curves.FINE_NTST == 400
    assert second["time_limit"] == 120 * curves.FINE_COST == 600
    assert {k: v for k, v in second.items() if k not in ("NTST", "time_limit")} == \
        {k: v for k, v in first.items() if k != "time_limit"}


@pytest.mark.parametrize("stop", [{"V": 137.4, "Fstar": 0.6949},   # inside the switch
                                  {"V": 134.1, "Fstar": 0.0263}])  # on the Hopf locus
def test_an_explained_stop_is_kept(calls, stop):
    made, outcomes = calls
    outcomes["fold2+"] = [stop]
    assert curves.fold_curve("dir", "fold2+", {}, 1).name == "fold2+"
    assert [name for name, _ in made] == ["fold2+"]


def test_a_curve_without_a_stop_is_kept(calls):
    made, _ = calls
    assert curves.fold_curve("dir", "fold3+", {}, 1).name == "fold3+"
    assert len(made) == 1


def test_a_fine_run_that_fails_leaves_the_coarse_one(calls, capsys):
    made, outcomes = calls
    outcomes["fold4+"] = [{"V": 300.0, "Fstar": 1.5}]
    outcomes["fold4+_fine"] = "fail"
    assert curves.fold_curve("dir", "fold4+", {}, 1).name == "fold4+"
    assert [name for name, _ in made] == ["fold4+", "fold4+_fine"]
    assert "REPORTED: fold4+_fine failed" in capsys.readouterr().out
