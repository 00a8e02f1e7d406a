"""continuation.collapse_within: where a run of periodic orbits reaches
straight rolling at a Hopf point before its end (AUTO goes on through the
Hopf point, back along the same orbits), on synthetic branches of the
shape AUTO returns near a Hopf point: amplitude ~ sqrt(|F* - h|)."""
import numpy
import pytest

from mlgshimmy.shared import continuation as ct

H, FREQ = 0.875978, 7.87        # a Hopf load and its frequency [Hz]
HOPF = {H: FREQ, 1.8345: 13.7}
GAP = 1e-3


def gap(_):
    return GAP


def branch(loads, amp, freq=FREQ):
    return {"Fstar": numpy.asarray(loads), "psi_amp": numpy.asarray(amp),
            "freq": numpy.full(len(loads), freq)}


def reflected(h=H, largest=2.5e-3, points=41):
    """Down in F* onto the Hopf point h and back up along the same orbits
    (AUTO's path through it); the least computed amplitude 1e-3 of the
    largest, as AUTO's steps leave it."""
    s = numpy.linspace(-1.0, 1.0, points)
    loads = h + 0.3 * s ** 2 + 1e-6
    amp = largest * numpy.sqrt(s ** 2 + 1e-6)
    return loads, amp


def test_the_least_amplitude_at_a_hopf_point_is_the_collapse():
    loads, amp = reflected()
    index, h = ct.collapse_within(branch(loads, amp), "Fstar", HOPF, gap)
    assert h == H
    assert index == 20                           # the middle: the least amplitude
    assert abs(loads[index] - H) < 1e-5


def test_a_pass_at_growing_amplitude_is_no_collapse():
    """Through F* = h at a finite amplitude (the branch only passes the
    Hopf load, as Fig. 12's H3 branch at H4): no least value there."""
    loads = numpy.linspace(H - 0.05, H + 0.05, 41)
    amp = 2.5e-4 + 1e-3 * (loads - loads[0])
    assert ct.collapse_within(branch(loads, amp), "Fstar", HOPF, gap) is None


def test_amplitude_shrinking_with_the_parameter_is_no_collapse():
    """Orbits continued down in y_fp shrink with it (freeplay scaling,
    amplitude ~ y_fp) to 1/200 of their start without any Hopf point: no
    least value inside the run."""
    yfp = numpy.geomspace(1.0, 0.005, 60)
    assert ct.collapse_within({"yfp": yfp, "psi_amp": 3e-4 * yfp, "freq": numpy.full(60, 1.9)},
                              "yfp", {0.087: 1.9}, lambda y: 1e-3 * y) is None


def test_zero_amplitude_after_the_collapse_is_left_to_the_end_rule():
    """An MX run that goes on along straight rolling (amplitude below
    COLLAPSED) after collapsing: the end rule of follow_orbits, not this."""
    loads = numpy.linspace(H + 0.05, H - 0.05, 41)
    amp = numpy.where(loads > H, 1e-3 * numpy.sqrt(numpy.abs(loads - H)), 0.0)
    assert ct.collapse_within(branch(loads, amp), "Fstar", HOPF, gap) is None


def test_a_small_least_amplitude_counts_against_the_largest_of_earlier_runs():
    """A least amplitude half this run's largest but below 1 % of the largest
    of the branch's earlier runs: a collapse only with that largest given."""
    loads, _ = reflected()
    amp = 5e-5 * (1.0 + numpy.linspace(-1.0, 1.0, len(loads)) ** 2)
    assert ct.collapse_within(branch(loads, amp), "Fstar", HOPF, gap, largest=0.0) is None
    assert ct.collapse_within(branch(loads, amp), "Fstar", HOPF, gap, largest=1e-2)[0] == 20


@pytest.mark.parametrize("where, freq", [(1.2, FREQ), (H, 13.0)])
def test_a_least_amplitude_at_no_hopf_point_is_not_taken(where, freq):
    """Away from every Hopf load, or at one with another frequency."""
    loads, amp = reflected(h=where)
    assert ct.collapse_within(branch(loads, amp, freq), "Fstar", HOPF, gap) is None


def test_a_least_amplitude_beyond_the_window_is_not_taken():
    """Fig. 14's orbits at V = 80 m/s (tests/reference/fig14, orbit_V80_down1):
    their least amplitude 1.8e-5 rad at y_fp = 0.07066, the Hopf point at
    0.070486, farther than the window 1e-3 y_fp of follow_orbits."""
    yfp = numpy.array([0.0815036, 0.0743786, 0.0706606, 0.0718185, 0.0820997])
    amp = numpy.array([1.487e-4, 8.615e-05, 1.801e-05, 4.993e-05, 1.53e-4])
    run = {"yfp": yfp, "psi_amp": amp, "freq": numpy.full(5, 21.87)}
    hopf = {0.0704857: 21.87}
    largest = 3.7e-3                 # the branch's, at y_fp = 1 mm (orbit_V80_down0)
    assert ct.collapse_within(run, "yfp", hopf, lambda y: 1e-3 * y, largest) is None
    assert ct.collapse_within(run, "yfp", hopf, lambda y: 3e-3 * y, largest) == (2, 0.0704857)
