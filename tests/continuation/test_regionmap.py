"""Tests of drivers/mlgshimmy/shared/regions.py on a synthetic map whose
edges are known exactly: a circle of radius 0.3 about (0.5, 0.5) and the
line y = 0.8 on a 400 x 300 raster of the unit square; labels 1 inside the
circle, 2 between circle and line, 3 above the line, sampled on 6 rows only
(as the slices of Fig. 11 sample it), with 3 % of the samples wrong."""
import math

import numpy as np
import pytest

from mlgshimmy.shared import regions

X = np.linspace(0.0, 1.0, 400)
Y = np.geomspace(0.01, 1.0, 300)      # uneven rows: index_of must follow them
XX, YY = np.meshgrid(X, Y)
TRUE = np.where(np.hypot(XX - 0.5, YY - 0.5) < 0.3, 1, np.where(YY < 0.8, 2, 3))
ANGLE = np.linspace(0.0, 2 * np.pi, 200)
# the line runs beyond the raster both ways: clipped, not dropped
CURVES = [(0.5 + 0.3 * np.cos(ANGLE), 0.5 + 0.3 * np.sin(ANGLE)), ([-0.5, 1.5], [0.8, 0.8])]


@pytest.fixture(scope="module")
def edges():
    return regions.curve_pixels(X, Y, CURVES)


@pytest.fixture(scope="module")
def painted(edges):
    """(painted map, report, rows sampled, wrong-sample mask)."""
    samples = np.full(TRUE.shape, -1)
    rows = np.linspace(20, 290, 6).astype(int)
    samples[rows] = TRUE[rows]
    wrong = np.random.default_rng(1).random(samples.shape) < 0.03
    samples[rows] = np.where(wrong[rows], 4, samples[rows])
    labels, report = regions.paint(edges, samples)
    return labels, report, rows, wrong


def test_index_of_on_an_uneven_grid():
    got = regions.index_of(Y, [Y[7]])[0]
    assert math.isclose(got, 7.0, rel_tol=0.0, abs_tol=1e-9), got


def test_index_of_extended_beyond_the_grid_end():
    got = regions.index_of(X, [1.0 + 2 * (X[1] - X[0])])[0]
    assert math.isclose(got, len(X) + 1.0, rel_tol=0.0, abs_tol=1e-9), got


def test_curve_pixels_lie_within_1_5_pixels_of_a_curve(edges):
    off = np.abs(np.hypot(XX - 0.5, YY - 0.5)[edges & (YY < 0.79)] - 0.3)
    assert np.all(off < 0.02), off.max()


def test_paint_equals_the_exact_map_away_from_the_curves(painted):
    labels = painted[0]
    off = np.hypot(XX - 0.5, YY - 0.5)
    away = (np.abs(off - 0.3) > 0.02) & (np.abs(YY - 0.8) > 0.02)
    assert np.array_equal(labels[away], TRUE[away]), \
        f"{int((labels[away] != TRUE[away]).sum())} pixels differ"


def test_paint_labels_every_pixel_edges_by_the_nearest_piece(painted):
    assert painted[0].min() >= 1


def test_paint_counts_the_wrong_samples(painted):
    _, report, rows, wrong = painted
    expected = int(wrong[rows].sum())
    assert math.isclose(report["disagree"], expected, rel_tol=0.05), \
        f"got {report['disagree']}, expected {expected} (rel 0.05)"


def test_paint_counts_samples_off_the_curves(painted):
    assert painted[1]["samples"] <= 6 * len(X), painted[1]["samples"]


def test_boundary_pixels_both_columns_either_side_of_a_step():
    field = np.zeros((5, 5), dtype=int)
    field[:, 3:] = 1
    assert regions.boundary_pixels(field).sum(axis=0).tolist() == [0, 0, 5, 5, 0]


def test_deepest_is_the_centre_of_a_disc_and_of_a_box():
    x, y = np.linspace(0.0, 2.0, 401), np.linspace(0.0, 1.0, 201)
    xx, yy = np.meshgrid(x, y)
    # a disc in units of the ranges: its centre is farthest from its edge
    disc = np.hypot((xx - 1.4) / 2.0, yy - 0.5) < 0.2
    assert regions.deepest(x, y, disc) == pytest.approx((1.4, 0.5), abs=0.011)
    # the grid's edge bounds a region too: the middle of the whole plane
    assert regions.deepest(x, y, np.ones_like(disc)) == pytest.approx((1.0, 0.5), abs=0.011)
    assert regions.deepest(x, y, np.zeros_like(disc)) is None


def test_representatives_prefer_a_kind_alone_and_fall_back_to_it_among_others():
    bits = regions.ATTRACTORS
    x, y = np.linspace(0.0, 600.0, 601), np.linspace(0.0, 3.0, 31)
    found = np.full((len(y), len(x)), bits["straight"])
    found[:, x > 300] = bits["high"] | bits["straight"]      # bistable: no high alone
    found[:, x > 500] = bits["quasi"]
    found[:, x <= 50] = bits["low"]
    chosen = regions.representatives(x, y, found)
    assert sorted(chosen) == ["high", "low", "quasi", "straight"]      # no yaw in the map
    assert chosen["high"] == {"x": 400.0, "y": 1.5, "alone": False, "start": "shimmy"}
    assert chosen["straight"] == {"x": 175.0, "y": 1.5, "alone": True, "start": "rolling"}
    assert chosen["quasi"] == {"x": 550.0, "y": 1.5, "alone": True, "start": "shimmy"}
    assert chosen["low"] == {"x": 25.0, "y": 1.5, "alone": True, "start": "shimmy"}
