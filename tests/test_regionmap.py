"""Tests of drivers/regions.py on a synthetic map whose edges are known
exactly: a circle of radius 0.3 about (0.5, 0.5) and the line y = 0.8 on a
400 x 300 raster of the unit square; labels 1 inside the circle, 2 between
circle and line, 3 above the line, sampled on 6 rows only (as the slices of
Fig. 11 sample it), with 3 % of the samples wrong."""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "drivers"))
from check import check, check_close  # noqa: E402
from mlgshimmy.shared import regions  # noqa: E402

X = np.linspace(0.0, 1.0, 400)
Y = np.geomspace(0.01, 1.0, 300)      # uneven rows: index_of must follow them
XX, YY = np.meshgrid(X, Y)
TRUE = np.where(np.hypot(XX - 0.5, YY - 0.5) < 0.3, 1, np.where(YY < 0.8, 2, 3))
ANGLE = np.linspace(0.0, 2 * np.pi, 200)
# the line runs beyond the raster both ways: clipped, not dropped
CURVES = [(0.5 + 0.3 * np.cos(ANGLE), 0.5 + 0.3 * np.sin(ANGLE)), ([-0.5, 1.5], [0.8, 0.8])]


def main():
    check_close("index_of on an uneven grid", regions.index_of(Y, [Y[7]])[0], 7.0, abs=1e-9)
    check_close("index_of: extended beyond the grid's end",
                regions.index_of(X, [1.0 + 2 * (X[1] - X[0])])[0], len(X) + 1.0, abs=1e-9)
    edges = regions.curve_pixels(X, Y, CURVES)
    check("curve pixels lie within 1.5 pixels of a curve",
          np.all(np.abs(np.hypot(XX - 0.5, YY - 0.5)[edges & (YY < 0.79)] - 0.3) < 0.02))
    samples = np.full(TRUE.shape, -1)
    rows = np.linspace(20, 290, 6).astype(int)
    samples[rows] = TRUE[rows]
    wrong = np.random.default_rng(1).random(samples.shape) < 0.03
    samples[rows] = np.where(wrong[rows], 4, samples[rows])
    painted, report = regions.paint(edges, samples)
    off = np.hypot(XX - 0.5, YY - 0.5)
    away = (np.abs(off - 0.3) > 0.02) & (np.abs(YY - 0.8) > 0.02)
    check("painted map equals the exact one away from the curves",
          np.array_equal(painted[away], TRUE[away]), int((painted[away] != TRUE[away]).sum()))
    check("every pixel labelled (edges by the nearest piece)", painted.min() >= 1)
    check_close("the wrong samples are counted", report["disagree"], int(wrong[rows].sum()),
                rel=0.05)
    check("samples counted off the curves", report["samples"] <= 6 * len(X))
    field = np.zeros((5, 5), dtype=int)
    field[:, 3:] = 1
    check("boundary_pixels: both columns either side of a step",
          regions.boundary_pixels(field).sum(axis=0).tolist() == [0, 0, 5, 5, 0])


main()
