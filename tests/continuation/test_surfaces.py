"""drivers/mlgshimmy/shared/surfaces.py on synthetic slices: turns found
past AUTO-like wiggles, a retraced branch cut, folds of neighbouring slices
joined, a fold born at the Hopf point padded, a sheet closed at its apex,
stability kept."""
import numpy
import pytest

from mlgshimmy.shared import surfaces

N = surfaces.POINTS


def folded(y, V_hopf=100.0, V_fold=40.0):
    """A subcritical family: from the Hopf point down to a fold at V_fold
    (unstable), then up to 200 (stable); amplitude y (1 -+ sqrt(...))."""
    lower = numpy.linspace(V_hopf, V_fold, 60)
    upper = numpy.linspace(V_fold, 200.0, 80)[1:]
    amp_fold = y * 1.0
    a_low = amp_fold * (1 - numpy.sqrt((lower - V_fold) / (V_hopf - V_fold)))
    a_up = amp_fold * (1 + numpy.sqrt((upper - V_fold) / (200.0 - V_fold)))
    return {"V": numpy.r_[lower, upper], "amp": numpy.r_[a_low, a_up],
            "stable": numpy.r_[numpy.zeros(60, bool), numpy.ones(79, bool)]}


def supercritical(y, V_hopf=40.0):
    V = numpy.linspace(V_hopf, 200.0, 90)
    return {"V": V, "amp": y * numpy.sqrt((V - V_hopf) / 160.0), "stable": numpy.ones(90, bool)}


def test_turns_ignore_wiggles_at_the_start_and_find_the_fold():
    V = numpy.r_[100.0, 100.05, 99.98, 100.04, numpy.linspace(99, 40, 30),
                 numpy.linspace(41, 90, 20)]
    assert surfaces.turns(V) == [33], surfaces.turns(V)


def test_pieces_cut_a_branch_that_goes_back_along_itself_at_the_first_turn():
    up = numpy.linspace(2.0, 28.0, 50)
    bubble = numpy.sin(numpy.pi * (up - 2.0) / 26.0) * 0.06 + 0.001
    curve = {"V": numpy.r_[up, up[::-1][1:], up[1:]],
             "amp": numpy.r_[bubble, bubble[::-1][1:], bubble[1:]],
             "stable": numpy.ones(148, bool)}
    got = surfaces.pieces(curve)
    assert len(got) == 1 and numpy.allclose(got[0][0], up), f"{len(got)} pieces"


def test_pieces_a_fold_of_cycles_is_two_pieces():
    assert len(surfaces.pieces(folded(1.0))) == 2


@pytest.fixture(scope="module")
def two_folded_slices():
    return surfaces.loft([(1.0, {"h": folded(1.0)}),
                          (2.0, {"h": folded(2.0, 110.0, 42.0)})], scale=(200.0, 2.0))


def test_loft_two_pieces_of_n_points_give_2_n_minus_1_quads(two_folded_slices):
    quads, _ = two_folded_slices
    assert len(quads) == 2 * (N - 1), len(quads)


def test_loft_joins_the_folds_of_neighbouring_slices_by_a_quad_edge(two_folded_slices):
    quads, _ = two_folded_slices
    fold_edge = [q for q in quads if numpy.allclose(q[1], (40.0, 1.0, 1.0))
                 and numpy.allclose(q[2], (42.0, 2.0, 2.0))]
    assert len(fold_edge) == 1, len(fold_edge)


def test_loft_keeps_stability_stable_and_unstable_branch(two_folded_slices):
    _, stable = two_folded_slices
    assert not stable[:N - 1].any() and stable[N - 1:].all()


def test_loft_corners_lie_on_the_slices_curves(two_folded_slices):
    quads, _ = two_folded_slices
    upper = quads[N - 1:, :2].reshape(-1, 3)   # the second strip's corners at y_fp = 1
    curve = folded(1.0)
    assert numpy.allclose(upper[:, 1], 1.0) and numpy.allclose(
        upper[:, 2], numpy.interp(upper[:, 0], curve["V"][59:], curve["amp"][59:]), atol=1e-9)


def test_loft_pads_a_slice_without_the_fold_with_its_hopf_point():
    quads, _ = surfaces.loft([(0.1, {"h": supercritical(0.1)}),
                              (0.2, {"h": folded(0.2, 45.0)})], scale=(200.0, 0.4))
    start = quads[: N - 1][:, [0, 1]]
    assert len(quads) == 2 * (N - 1) and numpy.allclose(start[..., 0], 40.0) \
        and numpy.allclose(start[..., 2], 0.0)


def test_loft_closes_a_sheet_absent_from_the_slice_below_at_its_apex():
    quads, _ = surfaces.loft([(0.3, {}), (0.4, {"low": supercritical(0.4)})],
                             apexes={"low": [(30.0, 0.32)], "h": [(1.0, 0.35)]},
                             scale=(200.0, 0.4))
    apex = quads[:, [0, 1]].reshape(-1, 3)
    assert len(quads) == N - 1 and numpy.allclose(apex, (30.0, 0.32, 0.0))
