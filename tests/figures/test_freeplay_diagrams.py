"""The freeplay diagrams (Figs. 10, 11 and 12; y_fp = 1 mm, epsilon = 0.1 mm,
`figures` set) against the paper's printed numbers, and AUTO's located
special points against the independent eigenvalue scan."""
import math

import numpy
import pytest

from mlgshimmy.shared import rundirs
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import spectrum

FREEPLAY = dict(yfp=1.0, eps_rel=0.1)
FOLD_LOAD = 1.8


def hopf_speeds(Fstar, grid=numpy.linspace(0.5, 600, 3000)):
    return [v for v, kind, _ in spectrum.stability_changes("figures", "V", grid, Fstar=Fstar,
                                                           **FREEPLAY) if kind == "HB"]


@pytest.fixture(scope="module")
def rundir(tmp_path_factory):
    """The runs' directory; the run directories this process claims are not
    passed on to later tests' child processes."""
    path = tmp_path_factory.mktemp("freeplay")
    with pytest.MonkeyPatch.context() as mp:
        mp.delenv(rundirs.CLAIMED_ENV, raising=False)
        yield str(path)


@pytest.fixture(scope="module")
def speeds():
    """The Hopf points in V at F* = 1 (eigenvalue scan)."""
    return hopf_speeds(1.0)


def test_hopf_speeds_at_unit_load_match_the_paper(speeds):
    """Section IV.B: H at 1.5, 28.1 and 142.5 m/s.  The paper prints one
    decimal: H1 within rounding (+-0.05) plus 0.5 %; H2 and H3 within 2 %."""
    assert len(speeds) == 3, f"three Hopf points in V at F* = 1: found {speeds}"
    assert abs(speeds[0] - 1.5) <= 0.05 + 0.0075, f"H1 {speeds[0]:.5f} vs paper 1.5 m/s"
    assert math.isclose(speeds[1], 28.1, rel_tol=0.02), f"H2 {speeds[1]!r} vs paper 28.1 m/s"
    assert math.isclose(speeds[2], 142.5, rel_tol=0.02), f"H3 {speeds[2]!r} vs paper 142.5 m/s"


@pytest.fixture(scope="module")
def fold_s(rundir, speeds):
    """AUTO's HB at the scanned H3 and the orbits born there, continued to
    their fold S: (HB point, orbit run)."""
    assert len(speeds) == 3, f"no H3 to start from: Hopf points {speeds}"
    point = ct.hopf_point(rundir, "hb3", "figures", "V", speeds[2], Fstar=1.0, **FREEPLAY)
    orbits = ct.periodic_from(rundir, "po3", point, stop={"V": [30.0, 200.0]}, DS=0.05,
                              DSMAX=1.0, NMX=600, expect=["LP"])
    return point, orbits


def test_auto_hopf_point_is_the_scanned_one(fold_s, speeds):
    """AUTO locates the scanned Hopf point H3 to 1e-7 relative."""
    point, _ = fold_s
    assert math.isclose(point["V"], speeds[2], rel_tol=1e-7), \
        f"AUTO's HB {point['V']!r}, scanned {speeds[2]!r}"


def test_fold_s_matches_the_paper(fold_s):
    """The orbits born at H3 fold at S (paper: 41.5 m/s) within 1 %."""
    _, orbits = fold_s
    assert math.isclose(orbits("LP1")["V"], 41.5, rel_tol=0.01), orbits("LP1")["V"]


@pytest.fixture(scope="module")
def fold_curve(rundir, fold_s):
    """The fold S continued in (V, F*) from F* = 1 to 1.8, and the fold of
    an independent diagram in V at F* = 1.8: (fold S, the curve's point at
    1.8, the diagram's fold)."""
    _, orbits = fold_s
    fold = orbits("LP1")
    curve = ct.fold_curve(rundir, "fold_S", fold, ("V", "Fstar"), DS=0.05, DSMAX=1.0,
                          NMX=200, stop={"Fstar": FOLD_LOAD})
    on_curve = curve("UZ")[-1]
    speed = hopf_speeds(FOLD_LOAD, numpy.linspace(100, 200, 500))
    point = ct.hopf_point(rundir, "hb_1.8", "figures", "V", speed[-1], Fstar=FOLD_LOAD,
                          **FREEPLAY)
    diagram = ct.periodic_from(rundir, "po_1.8", point, stop={"V": [30.0, 200.0]}, DS=0.05,
                               DSMAX=1.0, NMX=600, expect=["LP"])
    return fold, on_curve, diagram("LP1")


def test_fold_curve_meets_the_fold_of_a_diagram_in_V(fold_curve):
    """The fold curve passes through the fold of the diagram in V at
    F* = 1.8 within 1e-4 relative (with the period held fixed, as AUTO does
    unless PAR(11) is third in ICP, it missed by 1 %)."""
    _, on_curve, fold_there = fold_curve
    assert math.isclose(on_curve["V"], fold_there["V"], rel_tol=1e-4), \
        f"fold curve at F* = {FOLD_LOAD:g}: {on_curve['V']!r}, diagram's fold {fold_there['V']!r}"


def test_fold_curve_frequency_varies_along_it(fold_curve):
    """The period is free along the fold curve: the frequency changes."""
    fold, on_curve, _ = fold_curve
    assert abs(on_curve["freq"] - fold["freq"]) > 1e-3 * fold["freq"], \
        f"{fold['freq']:.5f} -> {on_curve['freq']:.5f} Hz"


@pytest.fixture(scope="module")
def loads_at():
    """Fig. 12: the stability changes of straight rolling in F* at V = 50
    and 300 m/s."""
    grid = numpy.linspace(0.02, 3.5, 800)
    return {V: spectrum.stability_changes("figures", "Fstar", grid, V=V, **FREEPLAY)
            for V in (50.0, 300.0)}


def test_loads_at_50_pitchfork_pitchfork_hopf(loads_at):
    """Fig. 12 (V = 50): two pitchforks at low load, then one Hopf point;
    straight rolling is stable between them."""
    kinds = [kind for _, kind, _ in loads_at[50.0]]
    assert kinds == ["BP", "BP", "HB"], str(kinds)


def test_pitchfork_loads_independent_of_V_and_low(loads_at):
    """The pitchforks do not move with V (50 vs 300 m/s, to 1e-9) and both
    lie below F* = 0.5."""
    pitchforks = {V: [f for f, kind, _ in loads_at[V] if kind == "BP"] for V in loads_at}
    assert len(pitchforks[300.0]) == 2 and \
        max(abs(a - b) for a, b in zip(pitchforks[50.0], pitchforks[300.0])) < 1e-9, \
        f"{pitchforks}"
    assert all(f < 0.5 for f in pitchforks[50.0]), f"{pitchforks[50.0]}"


@pytest.mark.parametrize("Fstar, count", ((0.65, 1), (0.70, 3), (0.80, 3), (6.85, 3), (6.9, 1)))
def test_joined_hopf_curve(Fstar, count):
    """Fig. 11 (paper: the Hopf curves are one curve that enters and leaves
    the plot twice): the curves through H1 and H2 join between F* = 0.65 and
    0.7 (V about 7 m/s), those through H2 and H3 between F* = 6.85 and 6.9
    (V about 113 m/s, above the plot); in between all three Hopf points
    exist in V, outside only one."""
    speeds = hopf_speeds(Fstar)
    assert len(speeds) == count, f"F* = {Fstar:g}: {speeds}, not {count} Hopf point(s) in V"
    if Fstar < 1 and count == 3:
        assert 1.0 < speeds[0] < speeds[1] < 20.0, \
            f"F* = {Fstar:g}: low pair {speeds[:2]} not inside V in (1, 20)"
    if Fstar < 1 and speeds:
        assert math.isclose(speeds[-1], 140.0, rel_tol=0.02), \
            f"F* = {Fstar:g}: high Hopf point {speeds[-1]!r} not near 140 m/s"
    if Fstar > 6 and count == 3:
        assert 110.0 < speeds[1] < speeds[2] < 115.0, \
            f"F* = {Fstar:g}: upper pair {speeds[1:]} not inside V in (110, 115)"
