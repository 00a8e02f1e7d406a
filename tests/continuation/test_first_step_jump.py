"""continuation.follow_orbits on a nearly degenerate Hopf point: a first
step from it that alone jumps more than 2 DSMAX in V is tried again with a
tenth of DS, on runs of FIRST_STEP_TRIAL steps, before the branch is run
(at rho = mu = 10 deg, F* = 2.375 the Hopf point at 115.24 m/s: the first
step of 0.005 landed 2.47 m/s along the branch); a jump later in a run is
still refused as a switch to another branch.  Synthetic runs stand in for
AUTO's (cut to NMX points, as AUTO's are)."""
import numpy
import pytest

from mlgshimmy.shared import runerror
from mlgshimmy.shared import continuation as ct

H, FREQ = 115.24, 28.8


class Run:
    """The parts of an AUTO orbit run follow_orbits reads."""

    def __init__(self, V, nmx=None):
        V = V[:nmx]
        self.branch = {"V": numpy.asarray(V, dtype=float),
                       "psi_amp": numpy.linspace(0.0, 1e-3, len(V)),
                       "freq": numpy.full(len(V), FREQ)}

    def __getitem__(self, k):
        return self.branch

    def __call__(self, label=None):
        return []


def follow(monkeypatch, runs):
    """follow_orbits from H downwards with DSMAX = 1 (stops at V = 0.5), the
    AUTO runs taken from `runs`: {DS: V values of the run}; the DS tried."""
    tried = []

    def periodic_from(rundir, name, origin, parameter, stop, allow_mx, **kw):
        tried.append((kw["DS"], kw.get("NMX")))
        return Run(runs[round(kw["DS"], 12)], kw.get("NMX"))
    monkeypatch.setattr(ct, "periodic_from", periodic_from)
    found, _ = ct.follow_orbits("rundir", lambda n: f"po{n}", "HB", "V", {H: FREQ},
                                lambda h: 0.01, (0.5, 600.0), DS=-0.005, DSMAX=1.0)
    return found, tried


def test_a_first_step_alone_that_jumps_is_run_again_with_a_smaller_step(monkeypatch):
    smooth = numpy.concatenate(([H, H - 0.3], numpy.arange(H - 1.0, 0.49, -1.0)))
    found, tried = follow(monkeypatch, {-0.005: [H, H - 2.47] + list(smooth[2:]),
                                        -0.0005: smooth})
    trial = ct.FIRST_STEP_TRIAL
    assert tried == [(-0.005, trial), (-0.0005, trial), (-0.0005, None)], tried
    assert len(found) == 1 and found[0][0]["V"][1] == pytest.approx(H - 0.3, abs=1e-12)


def test_a_jump_later_in_the_run_is_refused(monkeypatch):
    V = [H, H - 0.5, H - 1.0, H - 4.0] + list(numpy.arange(H - 5.0, 0.49, -1.0))
    with pytest.raises(runerror.RunError) as error:
        follow(monkeypatch, {-0.005: V})
    assert "jumped by more than 2.0 in V" in str(error.value), str(error.value)



def test_a_jump_off_a_vertical_start_runs_its_corner_first(monkeypatch):
    """The hertz law's H3 (144.545 m/s): its orbits grow in the gap at
    constant V (4e-4 m/s over three steps) up to the contact, where the
    fourth step cut the corner, 11.3 m/s down.  The corner is run with a
    hundredth of the steps (CORNER_STEPS of them), and the branch goes on
    from its end with the run's own steps."""
    start = [H, H - 6e-5, H - 4e-4]
    corner = numpy.linspace(H - 4e-4, H - 3.0, ct.CORNER_STEPS - 3)
    runs = [start + list(numpy.arange(H - 11.3, 0.49, -1.0)),
            start + list(corner),
            list(numpy.arange(H - 3.0, 0.49, -1.0))]
    calls = []

    class Labelled(Run):
        def __call__(self, label=None):
            return [] if label else ["the last orbit"]

    def periodic_from(rundir, name, origin, parameter, stop, allow_mx, **kw):
        calls.append((name, origin, kw["DS"], kw["DSMAX"], kw.get("NMX")))
        trials = sum(c[-1] == ct.FIRST_STEP_TRIAL for c in calls)
        return Labelled(runs[len(calls) - 1 - trials], kw.get("NMX"))
    monkeypatch.setattr(ct, "periodic_from", periodic_from)
    found, _ = ct.follow_orbits("rundir", lambda n: f"po{n}", "HB", "V", {H: FREQ},
                                lambda h: 0.01, (0.5, 600.0), DS=-0.005, DSMAX=1.0)
    assert calls == [("po0", "HB", -0.005, 1.0, ct.FIRST_STEP_TRIAL),
                     ("po0", "HB", -0.005, 1.0, None),
                     ("po0", "HB", pytest.approx(-5e-5), pytest.approx(0.01), ct.CORNER_STEPS),
                     ("po1", "the last orbit", -0.005, 1.0, None)], calls
    assert len(found) == 2 and found[1][0]["V"][0] == pytest.approx(H - 3.0)
