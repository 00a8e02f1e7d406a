"""Fig. 17: the Hopf and fold-of-cycles curves of Fig. 16(b) (eps = 0.1 mm,
F* = 1) in the plane (V, y_fp/eps), with R1 and R2 and the points a, b, c
that bound them (defined in magnitude.window_points)."""
import sys

import matplotlib.pyplot as plt

import autoglue
import diagrams as dg
import magnitude as mg
import paper_table

SEEDS = (0.15,)   # y_fp [mm] of the diagram whose fold starts the fold curve


def compute(where="fig17"):
    rundir = dg.rundir(where)
    seeds = [mg.diagram_in_V(rundir, f"y{y:g}", "fixed", y, uzr=(), figure="fig17")
             for y in SEEDS]
    hopf = mg.hopf_curves(rundir, "hopf", "fixed", figure="fig17")
    folds = mg.fold_curves(rundir, "fold", seeds, figure="fig17")
    return hopf, folds, mg.window_points(mg.FSTAR)


def plot(hopf, folds, window):
    fig, ax = plt.subplots(figsize=(7, 5))
    eps = mg.EPSILON
    label = "Hopf"
    for curve in hopf:
        ys, Vs = mg.curve_points(curve, "yfp", "V")
        ax.plot(Vs, ys / eps, "b-.", lw=1.2, label=label)
        label = None
    label = "fold of cycles"
    for curve in folds:
        ys, Vs = mg.curve_points(curve, "yfp", "V")
        ax.plot(Vs, ys / eps, "k-.", lw=1.2, label=label)
        label = None
    for lo, hi, name in ((0.0, window["a"], "R1"), (window["b"], window["c"], "R2")):
        ax.fill_between([0, mg.V_LIMIT], lo / eps, hi / eps, color="tab:cyan", alpha=0.35)
        ax.text(60, 0.5 * (lo + hi) / eps, name, ha="center", va="center")
    for name in "abc":
        V, y = window[f"V_{name}"], window[name] / eps
        ax.plot(V, y, "ko", ms=4)
        ax.annotate(name, (V, y), textcoords="offset points", xytext=(4, 4))
    ax.axvline(mg.V_LIMIT, color="0.4", ls=":", lw=1)
    ax.set(xlim=(0, mg.V_MAX), ylim=(0, 6), xlabel="V [m/s]", ylabel=r"$y_{fp}/\epsilon$",
           title=r"Fig. 17: bifurcation curves in (V, $y_{fp}/\epsilon$), $F^*$ = 1, "
                 r"$\epsilon$ = 0.1 mm")
    ax.legend(fontsize=8, loc="upper right")
    dg.save(fig, "fig17")


def main():
    try:
        hopf, folds, window = compute()
    except (autoglue.RunError, ValueError, RuntimeError) as exc:
        sys.exit(f"fig17: {exc}")
    eps = mg.EPSILON
    ours = {}
    for name in "abc":
        ours[f"{name}: V [m/s]"] = window["V_" + name]
        ours[f"{name}: y_fp/eps"] = window[name] / eps
    paper_table.report("fig17", ours)
    plot(hopf, folds, window)


if __name__ == "__main__":
    main()
