"""Where Fig. 11's curves stop and the slices that go on from there
(figures/fig11/ends.py turns and on_locus, located.past_gh): a Hopf curve
that turns in F*, a fold curve's end on the Hopf locus, and a fold curve
that ran on along the Hopf locus past its GH point.  Synthetic curves; the
Hopf locus is the paper gear's own (an eigenvalue scan, no AUTO run)."""
import numpy as np
import pytest

from mlgshimmy.figures.fig11 import ends, located, plane
from mlgshimmy.shared import jobs, spectrum

SWITCH = (0.627, 0.700)


def curve(Vs, Fs, mx=True):
    """One stored branch (jobs.stored's record), MX at its last point."""
    return [{"columns": {"V": list(Vs), "Fstar": list(Fs)}, "stable": [False] * len(Vs),
             "labels": [[len(Vs) - 1, 5, "MX"]] if mx else []}]


def loaded(*curves):
    return [jobs.loaded(c) for c in curves]


@pytest.fixture(scope="module")
def hopf_point():
    """(V, F*) of a Hopf point of straight rolling at F* = 1.2."""
    found = spectrum.hopf_scan("figures", "V", np.linspace(5.0, 600.0, 600), Fstar=1.2,
                               **plane.MODEL)
    assert found, "no Hopf point of straight rolling at F* = 1.2"
    return found[0][0], 1.2


@pytest.mark.parametrize("side", [-1, +1])
def test_a_hopf_curve_that_turns_in_fstar_gets_a_slice_back_inside_the_turn(side):
    """F* approaches 2.845 from below (a maximum: the slice is TURN_DF
    below it) or from above (a minimum: above it), while V runs on."""
    Fs = 2.845 + side * np.array([0.3, 0.1, 0.01, 1e-4, 1e-7, 0.0])
    Vs = [28.0, 20.0, 15.0, 13.0, 12.1, 12.0]
    found = ends.turns(loaded(curve(Vs, Fs)), SWITCH)
    assert found == [(pytest.approx(2.845 + side * ends.TURN_DF), 12.0)], found


def test_no_turn_slice_inside_the_stage_switch_at_the_plane_edge_or_without_mx():
    """Inside the switch AUTO's stop is explained (ends.explained); a curve
    at the plane's edge, or one that ends without MX, has nothing past it."""
    Vs = [28.0, 20.0, 15.0, 13.0, 12.0]
    inside = curve(Vs, [0.60, 0.65, 0.68, 0.685, 0.685])
    at_edge = curve(Vs, [3.2, 3.3, 3.4, 3.45, plane.F_MAX + 0.01])
    no_mx = curve(Vs, [2.0, 2.5, 2.8, 2.84, 2.845], mx=False)
    assert ends.turns(loaded(inside, at_edge, no_mx), SWITCH) == []
    assert ends.turns(loaded(inside), None) != [], "outside any switch the turn is sliced"


def test_a_fold_curves_end_on_the_hopf_locus_gets_a_slice_there(hopf_point):
    """The end on the locus (|Re| < GH_RATE) is sliced at its load; one
    5 m/s off it, where the pair's real part is far from zero, is not."""
    V, F = hopf_point
    on = curve([V + 20.0, V + 5.0, V], [F + 0.1, F + 0.05, F])
    off = curve([V + 20.0, V + 5.0], [F + 0.1, F])
    assert ends.on_locus(loaded(on, off), SWITCH) == [(F, V)]


def test_a_fold_curve_run_on_along_the_hopf_locus_is_cut_at_its_gh_point(hopf_point):
    """The fold curve passes 0.2 m/s from a located GH point at its third
    point, then runs to an end on the Hopf locus 30 m/s away: cut at the
    third point, the MX label moved there.  One that ends at the GH point,
    one whose end is off the locus and one inside the stage switch are
    kept whole."""
    V, F = hopf_point
    gh = {"type": "GH", "V": V + 30.2, "Fstar": F + 0.02, "curve": "hopf1"}
    Vs, Fs = [V + 60.0, V + 45.0, V + 30.0, V + 15.0, V], [F + 0.05, F + 0.03, F + 0.02,
                                                          F + 0.01, F]
    runs_on = curve(Vs, Fs)
    cut, = located.past_gh([runs_on], [gh], ends.FOLD_TOL, SWITCH)
    assert cut[0]["columns"]["V"] == Vs[:3] and cut[0]["labels"] == [[2, 5, "MX"]], cut
    at_gh = curve(Vs[:3], Fs[:3])
    off_locus = curve(Vs[:4], Fs[:4])
    kept = located.past_gh([at_gh, off_locus], [gh], ends.FOLD_TOL, SWITCH)
    assert kept == [at_gh, off_locus]
    assert located.past_gh([runs_on], [gh], ends.FOLD_TOL, (F - 0.01, F + 0.01)) == [runs_on]
