"""drivers/surfaces.py on synthetic slices: turns found past AUTO-like
wiggles, a retraced branch cut, folds of neighbouring slices joined, a fold
born at the Hopf point padded, a sheet closed at its apex, stability kept."""
import os
import sys

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "drivers"))
from check import check  # noqa: E402
from mlgshimmy.shared import surfaces  # noqa: E402

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


def turns_and_retraces():
    V = numpy.r_[100.0, 100.05, 99.98, 100.04, numpy.linspace(99, 40, 30),
                 numpy.linspace(41, 90, 20)]
    check("turns: wiggles of 0.05 at the start ignored, the fold found",
          surfaces.turns(V) == [33], str(surfaces.turns(V)))
    up = numpy.linspace(2.0, 28.0, 50)
    bubble = numpy.sin(numpy.pi * (up - 2.0) / 26.0) * 0.06 + 0.001
    curve = {"V": numpy.r_[up, up[::-1][1:], up[1:]],
             "amp": numpy.r_[bubble, bubble[::-1][1:], bubble[1:]],
             "stable": numpy.ones(148, bool)}
    got = surfaces.pieces(curve)
    check("pieces: a branch that goes back along itself is cut at the first turn",
          len(got) == 1 and numpy.allclose(got[0][0], up), f"{len(got)} pieces")
    check("pieces: a fold of cycles (two different branches) is two pieces",
          len(surfaces.pieces(folded(1.0))) == 2)


def folds_joined():
    quads, stable = surfaces.loft([(1.0, {"h": folded(1.0)}),
                                   (2.0, {"h": folded(2.0, 110.0, 42.0)})], scale=(200.0, 2.0))
    check("loft: two pieces of N points each give 2 (N - 1) quads", len(quads) == 2 * (N - 1),
          str(len(quads)))
    fold_edge = [q for q in quads if numpy.allclose(q[1], (40.0, 1.0, 1.0))
                 and numpy.allclose(q[2], (42.0, 2.0, 2.0))]
    check("loft: the folds of neighbouring slices are joined by a quad edge", len(fold_edge) == 1)
    check("loft: quads on the stable branch stable, on the unstable one unstable",
          not stable[:N - 1].any() and stable[N - 1:].all())
    upper = quads[N - 1:, :2].reshape(-1, 3)   # the second strip's corners at y_fp = 1
    curve = folded(1.0)
    check("loft: corners lie on the slices' curves (1e-9)",
          numpy.allclose(upper[:, 1], 1.0) and numpy.allclose(
              upper[:, 2], numpy.interp(upper[:, 0], curve["V"][59:], curve["amp"][59:]),
              atol=1e-9))


def padding_and_apex():
    quads, _ = surfaces.loft([(0.1, {"h": supercritical(0.1)}), (0.2, {"h": folded(0.2, 45.0)})],
                             scale=(200.0, 0.4))
    start = quads[: N - 1][:, [0, 1]]
    check("loft: a slice without the fold is padded with its Hopf point at the start",
          len(quads) == 2 * (N - 1) and numpy.allclose(start[..., 0], 40.0)
          and numpy.allclose(start[..., 2], 0.0))
    quads, _ = surfaces.loft([(0.3, {}), (0.4, {"low": supercritical(0.4)})],
                             apexes={"low": [(30.0, 0.32)], "h": [(1.0, 0.35)]},
                             scale=(200.0, 0.4))
    apex = quads[:, [0, 1]].reshape(-1, 3)
    check("loft: a sheet absent from the slice below is closed at its apex",
          len(quads) == N - 1 and numpy.allclose(apex, (30.0, 0.32, 0.0)))


def main():
    turns_and_retraces()
    folds_joined()
    padding_and_apex()


if __name__ == "__main__":
    main()
