"""Tests of shared/doubling.py without AUTO: which PD points start a run,
with what, and what the table says (the runs themselves: make fig12
RHO=-10 MU=20, docs/bifurcation-theory.md)."""
from mlgshimmy.shared import doubling


class Run(list):
    """An AUTO diagram as doubling reads it: branches, and its labelled
    solutions by type (run("PD"), run())."""

    def __init__(self, branches, labelled):
        super().__init__(branches)
        self.labelled = labelled

    def __call__(self, kind=None):
        return [p for p in self.labelled if kind in (None, p["TY name"])]


def solution(kind, Fstar, T=0.1266):
    return {"TY name": kind, "Fstar": Fstar, "T": T}


def test_a_pd_point_reached_by_a_doubled_run_starts_none(monkeypatch):
    """Fig. 12 at (-10, 20) deg: PD1 at 1.01413 and PD2 at 1.05119 on the
    orbits; the run from PD1 rejoins them at 1.05107 (BP), so PD2 starts
    nothing; each run switches (ISW = -1), stops at its first BP, within
    the figure's bounds."""
    orbits = Run([], [solution("PD", 1.01413), solution("PD", 1.05119)])
    started = []

    def periodic_from(rundir, name, point, parameter, stop, **kw):
        started.append((name, point["Fstar"], stop, kw))
        return Run([{"Fstar": [1.01413, 1.03, 1.05121]}],
                   [solution("BP", 1.05107, 0.2532)])
    monkeypatch.setattr(doubling.ct, "periodic_from", periodic_from)
    doubled = doubling.follow("rundir", "pd", [orbits], "Fstar", (0.02, 3.5), DS=0.002)
    assert [(name, F) for name, F, _, _ in started] == [("pd1", 1.01413)]
    _, _, stop, kw = started[0]
    assert stop == {"Fstar": [0.02, 3.5]}
    assert kw["ISW"] == -1 and kw["STOP"] == ["BP1"] and kw["DS"] == 0.002
    lines = doubling.describe("Fstar", doubled)
    assert lines == ["PD1 at Fstar = 1.01413 (period 0.1266 s): orbits of twice the period "
                     "followed over Fstar = 1.01413-1.05121, 3 points, ending in BP at 1.05107"]


def test_no_pd_point_is_said():
    assert doubling.describe("Fstar", []) == ["period doubling: none on these orbits"]
    assert doubling.follow("rundir", "pd", [Run([], [solution("LP", 2.0)])], "Fstar",
                           (0.02, 3.5)) == []
