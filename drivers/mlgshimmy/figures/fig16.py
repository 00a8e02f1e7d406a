"""Fig. 16: the periodic orbits over (V, y_fp) at F* = 1 as surfaces
lofted through diagrams in V (surfaces.py), (a) eps = 0.1 y_fp, (b) eps =
0.1 mm, shaded by stability, with the curves of Hopf points and folds of
cycles; in (b) the rectangles R1 = (0, r1) and R2 = (r2, r3) of y_fp where
straight rolling is stable up to V = 120 m/s."""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import matplotlib.pyplot as plt
import numpy
from numpy.typing import ArrayLike
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from mlgshimmy.shared import branches
from mlgshimmy.shared import draw
from mlgshimmy.shared import freeplay
from mlgshimmy.shared import gear
from mlgshimmy.shared import jobs
from mlgshimmy.shared import kappa_criterion
from mlgshimmy.shared import yfp_runs
from mlgshimmy.shared import yfp_stored
from mlgshimmy.shared import paper
from mlgshimmy.shared import paths
from mlgshimmy.shared import surfaces

# What make, make help, make submit and the report know of this figure
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "fig16": {
        "help": "Fig. 16: orbit surfaces over (V, y_fp), both scalings",
        "time": "10 min",
        "regress": True,
        "parts": True,
        "report": ("Orbit surfaces over (V, y_fp) for both scalings; regions R1 = (0, r_1) and "
                   "R2 = (r_2, r_3) of y_fp where straight rolling is stable up to 120 m/s, "
                   "values the paper withholds (IV.E)."),
        "held_out": {"r1 = a [mm]": "r_1", "r2 = b [mm]": "r_2", "r3 = c [mm]": "r_3"},
    },
}

FAMILY = {
    "ratio": (0.5, 1.0, 1.5, 2.0),   # a pure scaling (Fig. 13): few slices suffice
    "fixed": (0.04, 0.05, 0.06, 0.07, 0.08, 0.098, 0.11, 0.13, 0.15, 0.2, 0.25, 0.35, 0.6, 0.7,
              0.8, 1.0),
}
HIGHLIGHT = {"ratio": (0.5, 1.0, 2.0), "fixed": freeplay.FIG14_FREEPLAYS}
DEG = numpy.degrees(1.0)
Y_MAX = 1.0   # y_fp range [mm] of panel (b)
SLICE = draw.NEUTRAL   # colour of the highlighted slices
HOPF, FOLD = draw.HOPF_CURVE, draw.FOLD_CURVE


FOLD_SEED = 0.15   # y_fp [mm] of the "fixed" diagram whose fold starts the fold curve


def fold_seed() -> Dict[str, Any]:
    """The "fixed" diagram at FOLD_SEED and the fold curves through its folds."""
    rundir = paths.rundir(f"fig16/fixed_y{FOLD_SEED:g}_folds")
    d = yfp_runs.diagram_in_V(rundir, f"fixed_y{FOLD_SEED:g}", "fixed", FOLD_SEED, uzr=(),
                        figure="fig16", **gear.parameters())
    return {"diagram": yfp_stored.stored_diagram(d),
            "fold_curves": yfp_stored.stored_curves(
                yfp_runs.fold_curves(rundir, "fold", [d], figure="fig16"), ("yfp", "V", "psi_amp"))}


def hopf_curves() -> List[Dict[str, Any]]:
    curves = yfp_runs.hopf_curves(paths.rundir("fig16/hopf_curves"), "hopf", "fixed",
                            figure="fig16", **gear.parameters())
    return yfp_stored.stored_curves(curves, ("yfp", "V", "freq"))


def parts() -> Dict[str, Any]:
    """One diagram in V per slice (the FOLD_SEED one with the fold curves),
    the Hopf curves in (y_fp, V) and the window points a, b, c."""
    work = {}
    for scaling, freeplays in FAMILY.items():
        for name, job in yfp_stored.diagram_jobs("fig16", scaling, freeplays, f"{scaling}_",
                                         uzr=(), **gear.parameters()).items():
            seed = scaling == "fixed" and name == f"fixed_y{FOLD_SEED:g}"
            work[name + "_folds" if seed else name] = fold_seed if seed else job
    return {**work, "hopf_curves": hopf_curves,
            "window": lambda: kappa_criterion.window_points(yfp_runs.FSTAR, **gear.parameters())}


def compute(parts: Any) -> Dict[str, Any]:
    done = parts.all()
    family = {scaling: yfp_stored.diagrams_of(done, f"{scaling}_")[0] for scaling in FAMILY}
    window = parts["window"]
    fold_curves = parts[f"fixed_y{FOLD_SEED:g}_folds"]["fold_curves"]
    return {"numbers": numbers(family, parts["hopf_curves"], window), "window": window,
            "family": family, "hopf_curves": parts["hopf_curves"], "fold_curves": fold_curves}


def crossing(curves: Sequence[Mapping[str, Any]], V: float) -> List[float]:
    """y_fp values where the stored AUTO curves cross speed V (linear
    interpolation)."""
    found = []
    for curve in curves:
        ys, Vs = numpy.asarray(curve["yfp"]), numpy.asarray(curve["V"])
        for i in numpy.nonzero(numpy.diff(numpy.sign(Vs - V)))[0]:
            t = (V - Vs[i]) / (Vs[i + 1] - Vs[i])
            found.append(ys[i] + t * (ys[i + 1] - ys[i]))
    return sorted(found)


def numbers(family: Any, hopf_curves: Sequence[Mapping[str, Any]],
            window: Mapping[str, Any]) -> Dict[str, Optional[float]]:
    """{quantity: value}: r1, r2, r3 (= a, b, c of kappa_criterion.window_points)
    with AUTO's Hopf curves as a check, and the Hopf and fold speeds of
    every slice."""
    out = {f"r{k + 1} = {name} [mm]": window[name] for k, name in enumerate("abc")}
    out.update({f"V at {name} [m/s]": window["V_" + name] for name in "abc"})
    for k, y in enumerate(crossing(hopf_curves, yfp_runs.V_LIMIT)):
        out[f"check: AUTO Hopf curves at V = 120, y_fp {k + 1} [mm]"] = y
    low = [min(c["yfp"]) for c in hopf_curves
           if max(c["freq"]) < kappa_criterion.BANDS["low"][1]]
    if low:   # a changed gear may have no low-frequency Hopf curve (rho = 20, mu = 5 deg)
        out["check: smallest y_fp of AUTO's low-frequency Hopf curve [mm]"] = min(low)
    for scaling, diagrams in family.items():
        out.update(yfp_stored.diagram_numbers(diagrams, f"{scaling} "))
    return out


def clipped(ys: ArrayLike, Vs: ArrayLike) -> Tuple[numpy.ndarray, numpy.ndarray]:
    """A curve with the points outside the plotted box (y_fp <= Y_MAX,
    V <= V_MAX) set to NaN: mplot3d does not clip."""
    outside = (ys > Y_MAX) | (Vs > yfp_runs.V_MAX)
    return numpy.where(outside, numpy.nan, ys), numpy.where(outside, numpy.nan, Vs)


def band(freq: float) -> str:
    """The frequency band (kappa_criterion.BANDS) of an orbit family: "low" or "high"."""
    return next(name for name, (lo, hi) in kappa_criterion.BANDS.items() if lo <= freq < hi)


def sheets(diagram: Mapping[str, Any]) -> Dict[str, Dict[str, Any]]:
    """{band: {"V", "amp", "stable"}}: the orbit family of each frequency
    band in a stored diagram (by the frequency at its Hopf point)."""
    out = {}
    for branch in diagram["branches"]:
        columns = branch["columns"]
        key = band(columns["freq"][0])
        if key in out:
            raise ValueError(f"fig16: two {key}-frequency orbit families at y_fp = "
                             f"{diagram['yfp']:g} mm; a surface takes one per slice")
        out[key] = {"V": columns["V"], "amp": columns["psi_amp"], "stable": branch["stable"]}
    return out


def apexes(hopf_curves: Sequence[Mapping[str, Any]]) -> Dict[str, List[Tuple[float, float]]]:
    """{band: [(V, y_fp)]}: the point of least y_fp of each Hopf curve, where
    its orbit sheet shrinks to a point (c for the low-frequency sheet)."""
    out = {}
    for curve in hopf_curves:
        k = int(numpy.argmin(curve["yfp"]))
        out.setdefault(band(curve["freq"][k]), []).append((curve["V"][k], curve["yfp"][k]))
    return out


def orbit_surface(ax: Any, diagrams: Sequence[Mapping[str, Any]],
                  hopf_curves: Sequence[Mapping[str, Any]]) -> None:
    """The orbit sheets lofted through the slices (surfaces.loft; psi
    amplitude in degrees), shaded by stability, and the slices of Figs. 13
    and 14 on them (solid stable, dashed unstable) with their folds."""
    slices = [(d["yfp"], sheets(d)) for d in diagrams]
    largest = max(numpy.max(c["amp"]) for _, s in slices for c in s.values())
    quads, stable = surfaces.loft(slices, apexes(hopf_curves), scale=(yfp_runs.V_MAX, largest))
    quads[..., 2] *= DEG
    ax.set_zlim(0.0, 1.05 * quads[..., 2].max())
    draw.surface(ax, quads, stable)
    for d in diagrams:
        if d["yfp"] not in HIGHLIGHT[d["scaling"]]:
            continue
        for branch in jobs.loaded(d["branches"]):
            for xs, zs, ok in branches.segments(branch, "V", "psi_amp"):
                ax.plot(xs, numpy.full_like(xs, d["yfp"]), zs * DEG, color=SLICE,
                        ls="-" if ok else "--", lw=1.3, zorder=3)
    for d in diagrams:
        for V, amp in d["folds"]:
            ax.scatter([V], [d["yfp"]], [amp * DEG], color=draw.NEUTRAL, s=5, zorder=4)


def plot(result: Mapping[str, Any]) -> None:
    paper.report("fig16", result["numbers"])
    family, window = result["family"], result["window"]
    fig = plt.figure(figsize=(13, 5.4))
    for n, scaling in enumerate(("ratio", "fixed")):
        ax = fig.add_subplot(1, 2, n + 1, projection="3d", computed_zorder=False)
        diagrams = family[scaling]
        ys = [d["yfp"] for d in diagrams]
        ax.set(xlim=(0, yfp_runs.V_MAX), ylim=(0, Y_MAX) if scaling == "fixed" else (0, max(ys)))
        orbit_surface(ax, diagrams, result["hopf_curves"] if scaling == "fixed" else [])
        if scaling == "ratio":
            # each Hopf point by name across the slices that have it (the
            # speeds do not move with y_fp; a changed gear's H1, H2 may
            # exist on some only) and the fold S1
            for name in dict.fromkeys(n for d in diagrams for n in d["hopf_names"]):
                at = [(V, d["yfp"]) for d in diagrams
                      for n, (V, _) in zip(d["hopf_names"], d["hopf"]) if n == name]
                ax.plot(*zip(*at), 0.0, zorder=3, **HOPF)
            folds = [(V, d["yfp"], amp * DEG) for d in diagrams for V, amp in d["folds"]
                     if V == dict(yfp_stored.named_folds(d)).get("S1")]
            if folds:
                ax.plot(*zip(*folds), zorder=4, **FOLD)
            ax.set_title(r"(a) $\epsilon$ = 0.1 $y_{fp}$", y=0.95)
        else:
            for curve in result["hopf_curves"]:
                ys, Vs = clipped(numpy.asarray(curve["yfp"]), numpy.asarray(curve["V"]))
                ax.plot(Vs, ys, 0.0 * Vs, zorder=3, **HOPF)
            for curve in result["fold_curves"]:
                ys, Vs = clipped(numpy.asarray(curve["yfp"]), numpy.asarray(curve["V"]))
                ax.plot(Vs, ys, numpy.asarray(curve["psi_amp"]) * DEG, zorder=4, **FOLD)
            for lo, hi, name in ((0.0, window["a"], "R1"), (window["b"], window["c"], "R2")):
                ax.add_collection3d(Poly3DCollection(
                    [[(0, lo, 0), (yfp_runs.V_LIMIT, lo, 0), (yfp_runs.V_LIMIT, hi, 0),
                      (0, hi, 0)]],
                    facecolor=draw.palette.ALLOWED, alpha=0.5, zorder=0))
                ax.text(60, 0.5 * (lo + hi), 0, name, fontsize=8, zorder=5)
            ax.set_title(r"(b) $\epsilon$ = 0.1 mm (R1, R2: stable up to 120 m/s)", y=0.95)
        ax.set(xlabel="V [m/s]", ylabel="$y_{fp}$ [mm]", zlabel=r"$\psi$ amplitude [deg]")
        for axis in (ax.xaxis, ax.yaxis):
            axis.labelpad = 18      # clear of the tick labels, which the view tilts
        ax.view_init(elev=22, azim=-55)
        ax.set_box_aspect(None, zoom=0.88)   # room for the axis labels inside the canvas
    handles = [Patch(color=draw.STABLE, label="stable orbits"),
               Patch(color=draw.UNSTABLE, label="unstable orbits (olive seen through a stable sheet)"),
               Line2D([], [], label="Hopf curves", **HOPF),
               Line2D([], [], label="fold-of-cycles curves (dots: folds of the slices)", **FOLD),
               Line2D([], [], color=SLICE, label="slices of Figs. 13 and 14 (dashed unstable)")]
    fig.legend(handles=handles, loc="lower center", ncol=5, fontsize=8, frameon=False)
    draw.figure_title(fig, "Fig. 16: periodic orbits over (V, $y_{fp}$), $F^*$ = 1", y=0.98)
    fig.subplots_adjust(left=0.0, right=0.97, bottom=0.02, top=1.0, wspace=0.02)
    draw.save(fig, "fig16")


if __name__ == "__main__":
    jobs.run_figure("fig16", compute, plot, parts)
