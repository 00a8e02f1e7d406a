"""Fig. 16: the periodic orbits over (V, y_fp) at F* = 1 as a family of
diagrams in V, (a) eps = 0.1 y_fp, (b) eps = 0.1 mm, with the curves of
Hopf points and folds of cycles; in (b) the rectangles R1 = (0, r1) and
R2 = (r2, r3) of y_fp where straight rolling is stable up to V = 120 m/s."""
import sys

import matplotlib.pyplot as plt
import numpy
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

import autoglue
import diagrams as dg
import fig14
import magnitude as mg
import paper_table

FAMILY = {
    "ratio": (0.5, 1.0, 1.5, 2.0),   # a pure scaling (Fig. 13): few slices suffice
    "fixed": (0.04, 0.05, 0.06, 0.07, 0.08, 0.098, 0.11, 0.13, 0.15, 0.2, 0.25, 0.35, 0.6, 1.0),
}
HIGHLIGHT = {"ratio": (0.5, 1.0, 2.0), "fixed": fig14.FREEPLAYS}
DEG = numpy.degrees(1.0)
Y_MAX = 1.0   # y_fp range [mm] of panel (b)


def compute(where="fig16"):
    rundir = dg.rundir(where)
    family = {scaling: [mg.diagram_in_V(rundir, f"{scaling}_y{y:g}", scaling, y, uzr=(),
                                        figure="fig16") for y in freeplays]
              for scaling, freeplays in FAMILY.items()}
    seeds = [d for d in family["fixed"] if d.yfp == 0.15]
    curves = {"hopf": mg.hopf_curves(rundir, "hopf", "fixed", figure="fig16"),
              "fold": mg.fold_curves(rundir, "fold", seeds, figure="fig16")}
    return family, curves, mg.window_points(mg.FSTAR)


def crossing(curves, V):
    """y_fp values where the AUTO curves cross speed V (linear interpolation)."""
    found = []
    for curve in curves:
        ys, Vs = mg.curve_points(curve, "yfp", "V")
        for i in numpy.nonzero(numpy.diff(numpy.sign(Vs - V)))[0]:
            t = (V - Vs[i]) / (Vs[i + 1] - Vs[i])
            found.append(ys[i] + t * (ys[i + 1] - ys[i]))
    return sorted(found)


def numbers(family, curves, window):
    """{quantity: value}: r1, r2, r3 (= a, b, c of magnitude.window_points)
    with AUTO's Hopf curves as a check, and the Hopf and fold speeds of
    every slice."""
    out = {f"r{k + 1} = {name} [mm]": window[name] for k, name in enumerate("abc")}
    out.update({f"V at {name} [m/s]": window["V_" + name] for name in "abc"})
    for k, y in enumerate(crossing(curves["hopf"], mg.V_LIMIT)):
        out[f"check: AUTO Hopf curves at V = 120, y_fp {k + 1} [mm]"] = y
    out["check: smallest y_fp of AUTO's low-frequency Hopf curve [mm]"] = min(
        mg.curve_points(c, "yfp", "V")[0].min() for c in curves["hopf"] if _is_low(c))
    for scaling, diagrams in family.items():
        for d in diagrams:
            for k, (V, _) in enumerate(d.hopf):
                out[f"{scaling} y_fp = {d.yfp:g}: H{k + 1} [m/s]"] = V
            for k, (*_, V, _) in enumerate(d.folds()):
                out[f"{scaling} y_fp = {d.yfp:g}: S{k + 1} [m/s]"] = V
    return out


def _is_low(curve):
    return max(1.0 / numpy.asarray(run[0]["T"]).min() for run in curve) < mg.BANDS["low"][1]


def clipped(ys, Vs):
    """A curve with the points outside the plotted box (y_fp <= Y_MAX,
    V <= V_MAX) set to NaN: mplot3d does not clip."""
    outside = (ys > Y_MAX) | (Vs > mg.V_MAX)
    return numpy.where(outside, numpy.nan, ys), numpy.where(outside, numpy.nan, Vs)


def plot(family, curves, window):
    fig = plt.figure(figsize=(13, 6))
    for n, scaling in enumerate(("ratio", "fixed")):
        ax = fig.add_subplot(1, 2, n + 1, projection="3d")
        for d in family[scaling]:
            wide = d.yfp in HIGHLIGHT[scaling]
            for run in d.branches:
                for branch in run:
                    for xs, zs, stable in dg.segments(branch, "V", "psi_amp"):
                        ax.plot(xs, numpy.full_like(xs, d.yfp), zs * DEG,
                                color=dg.STABLE if stable else dg.UNSTABLE,
                                ls="-" if stable else "--", lw=1.8 if wide else 0.7)
            for *_, V, amp in d.folds():
                ax.scatter([V], [d.yfp], [amp * DEG], color="k", s=6)
        if scaling == "ratio":
            for k in range(3):   # the Hopf speeds do not move with y_fp
                ax.plot([d.hopf[k][0] for d in family[scaling]], [d.yfp for d in family[scaling]],
                        0.0, "b-.", lw=1)
            folds = [(d.folds()[0][2], d.yfp, d.folds()[0][3] * DEG) for d in family[scaling]]
            ax.plot(*zip(*folds), "k-.", lw=1)
            ax.set_title(r"(a) $\epsilon$ = 0.1 $y_{fp}$")
        else:
            for curve in curves["hopf"]:
                ys, Vs = clipped(*mg.curve_points(curve, "yfp", "V"))
                ax.plot(Vs, ys, 0.0 * Vs, "b-.", lw=1)
            for curve in curves["fold"]:
                ys, Vs = clipped(*mg.curve_points(curve, "yfp", "V"))
                _, amp = mg.curve_points(curve, "yfp", "psi_amp")
                ax.plot(Vs, ys, amp * DEG, "k-.", lw=1)
            for lo, hi, name in ((0.0, window["a"], "R1"), (window["b"], window["c"], "R2")):
                ax.add_collection3d(Poly3DCollection(
                    [[(0, lo, 0), (mg.V_LIMIT, lo, 0), (mg.V_LIMIT, hi, 0), (0, hi, 0)]],
                    facecolor="tab:cyan", alpha=0.5))
                ax.text(60, 0.5 * (lo + hi), 0, name, fontsize=8)
            ax.set_ylim(0, Y_MAX)
            ax.set_title(r"(b) $\epsilon$ = 0.1 mm (R1, R2: stable up to 120 m/s)")
        ax.set(xlabel="V [m/s]", ylabel="$y_{fp}$ [mm]", zlabel=r"$\psi$ amplitude [deg]",
               xlim=(0, mg.V_MAX))
        ax.view_init(elev=25, azim=-60)
    fig.suptitle("Fig. 16: periodic orbits over (V, $y_{fp}$), $F^*$ = 1 (green stable, red "
                 "unstable; dot-dashed: Hopf (blue) and fold (black) curves)")
    fig.tight_layout()
    dg.save(fig, "fig16")


def main():
    try:
        family, curves, window = compute()
        ours = numbers(family, curves, window)
    except (autoglue.RunError, ValueError, RuntimeError) as exc:
        sys.exit(f"fig16: {exc}")
    paper_table.report("fig16", ours)
    plot(family, curves, window)


if __name__ == "__main__":
    main()
