"""Fig. 16: the periodic orbits over (V, y_fp) at F* = 1 as a family of
diagrams in V, (a) eps = 0.1 y_fp, (b) eps = 0.1 mm, with the curves of
Hopf points and folds of cycles; in (b) the rectangles R1 = (0, r1) and
R2 = (r2, r3) of y_fp where straight rolling is stable up to V = 120 m/s."""
import matplotlib.pyplot as plt
import numpy
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

import branches
import magnitude as mg
import paper_table
import paths
import plotting
import results

FAMILY = {
    "ratio": (0.5, 1.0, 1.5, 2.0),   # a pure scaling (Fig. 13): few slices suffice
    "fixed": (0.04, 0.05, 0.06, 0.07, 0.08, 0.098, 0.11, 0.13, 0.15, 0.2, 0.25, 0.35, 0.6, 1.0),
}
HIGHLIGHT = {"ratio": (0.5, 1.0, 2.0), "fixed": mg.FIG14_FREEPLAYS}
DEG = numpy.degrees(1.0)
Y_MAX = 1.0   # y_fp range [mm] of panel (b)


FOLD_SEED = 0.15   # y_fp [mm] of the "fixed" diagram whose fold starts the fold curve


def fold_seed():
    """The "fixed" diagram at FOLD_SEED and the fold curves through its folds."""
    rundir = paths.rundir(f"fig16/fixed_y{FOLD_SEED:g}_folds")
    d = mg.diagram_in_V(rundir, f"fixed_y{FOLD_SEED:g}", "fixed", FOLD_SEED, uzr=(),
                        figure="fig16")
    return {"diagram": mg.stored_diagram(d),
            "fold_curves": mg.stored_curves(mg.fold_curves(rundir, "fold", [d], figure="fig16"),
                                            ("yfp", "V", "psi_amp"))}


def hopf_curves():
    curves = mg.hopf_curves(paths.rundir("fig16/hopf_curves"), "hopf", "fixed",
                            figure="fig16")
    return mg.stored_curves(curves, ("yfp", "V", "freq"))


def parts():
    """One diagram in V per slice (the FOLD_SEED one with the fold curves),
    the Hopf curves in (y_fp, V) and the window points a, b, c."""
    jobs = {}
    for scaling, freeplays in FAMILY.items():
        for name, job in mg.diagram_jobs("fig16", scaling, freeplays, f"{scaling}_",
                                         uzr=()).items():
            seed = scaling == "fixed" and name == f"fixed_y{FOLD_SEED:g}"
            jobs[name + "_folds" if seed else name] = fold_seed if seed else job
    return {**jobs, "hopf_curves": hopf_curves, "window": lambda: mg.window_points(mg.FSTAR)}


def compute(parts):
    done = parts.all()
    family = {scaling: mg.diagrams_of(done, f"{scaling}_")[0] for scaling in FAMILY}
    window = parts["window"]
    fold_curves = parts[f"fixed_y{FOLD_SEED:g}_folds"]["fold_curves"]
    return {"numbers": numbers(family, parts["hopf_curves"], window), "window": window,
            "family": family, "hopf_curves": parts["hopf_curves"], "fold_curves": fold_curves}


def crossing(curves, V):
    """y_fp values where the stored AUTO curves cross speed V (linear
    interpolation)."""
    found = []
    for curve in curves:
        ys, Vs = numpy.asarray(curve["yfp"]), numpy.asarray(curve["V"])
        for i in numpy.nonzero(numpy.diff(numpy.sign(Vs - V)))[0]:
            t = (V - Vs[i]) / (Vs[i + 1] - Vs[i])
            found.append(ys[i] + t * (ys[i + 1] - ys[i]))
    return sorted(found)


def numbers(family, hopf_curves, window):
    """{quantity: value}: r1, r2, r3 (= a, b, c of magnitude.window_points)
    with AUTO's Hopf curves as a check, and the Hopf and fold speeds of
    every slice."""
    out = {f"r{k + 1} = {name} [mm]": window[name] for k, name in enumerate("abc")}
    out.update({f"V at {name} [m/s]": window["V_" + name] for name in "abc"})
    for k, y in enumerate(crossing(hopf_curves, mg.V_LIMIT)):
        out[f"check: AUTO Hopf curves at V = 120, y_fp {k + 1} [mm]"] = y
    out["check: smallest y_fp of AUTO's low-frequency Hopf curve [mm]"] = min(
        min(c["yfp"]) for c in hopf_curves if max(c["freq"]) < mg.BANDS["low"][1])
    for scaling, diagrams in family.items():
        out.update(mg.diagram_numbers(diagrams, f"{scaling} "))
    return out


def clipped(ys, Vs):
    """A curve with the points outside the plotted box (y_fp <= Y_MAX,
    V <= V_MAX) set to NaN: mplot3d does not clip."""
    outside = (ys > Y_MAX) | (Vs > mg.V_MAX)
    return numpy.where(outside, numpy.nan, ys), numpy.where(outside, numpy.nan, Vs)


def plot(result):
    paper_table.report("fig16", result["numbers"])
    family, window = result["family"], result["window"]
    fig = plt.figure(figsize=(13, 6))
    for n, scaling in enumerate(("ratio", "fixed")):
        ax = fig.add_subplot(1, 2, n + 1, projection="3d")
        for d in family[scaling]:
            wide = d["yfp"] in HIGHLIGHT[scaling]
            for branch in results.loaded(d["branches"]):
                for xs, zs, stable in branches.segments(branch, "V", "psi_amp"):
                    ax.plot(xs, numpy.full_like(xs, d["yfp"]), zs * DEG,
                            color=plotting.STABLE if stable else plotting.UNSTABLE,
                            ls="-" if stable else "--", lw=1.8 if wide else 0.7)
            for V, amp in d["folds"]:
                ax.scatter([V], [d["yfp"]], [amp * DEG], color="k", s=6)
        if scaling == "ratio":
            for k in range(3):   # the Hopf speeds do not move with y_fp
                ax.plot([d["hopf"][k][0] for d in family[scaling]],
                        [d["yfp"] for d in family[scaling]], 0.0, "b-.", lw=1)
            folds = [(d["folds"][0][0], d["yfp"], d["folds"][0][1] * DEG)
                     for d in family[scaling]]
            ax.plot(*zip(*folds), "k-.", lw=1)
            ax.set_title(r"(a) $\epsilon$ = 0.1 $y_{fp}$")
        else:
            for curve in result["hopf_curves"]:
                ys, Vs = clipped(numpy.asarray(curve["yfp"]), numpy.asarray(curve["V"]))
                ax.plot(Vs, ys, 0.0 * Vs, "b-.", lw=1)
            for curve in result["fold_curves"]:
                ys, Vs = clipped(numpy.asarray(curve["yfp"]), numpy.asarray(curve["V"]))
                ax.plot(Vs, ys, numpy.asarray(curve["psi_amp"]) * DEG, "k-.", lw=1)
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
    plotting.save(fig, "fig16")


if __name__ == "__main__":
    results.run_figure("fig16", compute, plot, parts)
