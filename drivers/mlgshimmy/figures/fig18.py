"""Fig. 18: the points a, b, c of Fig. 17 continued in F* (eps = 0.1 mm), the
regions of the (y_fp/eps, F*) plane by what straight rolling does for V up to
120 m/s, and the largest envelope 0 < y_fp/eps < kappa*, F* in [0.1, 2],
inside R1.  Fig. 19 reads kappa* from its cached result.
`fig18.py --strut-variant 1` does the same with the printed strut spring
(build/fig18_v1/, build/figures/fig18_v1.*).

a, b, c and the region map come from the eigenvalues of straight rolling
(kappa_criterion.window_points, kappa_criterion.growth) on an F* grid; a and b are also
continued by AUTO as curves of Hopf points at V = 120 m/s in (y_fp, F*) as a
check, with their codimension-two points (shared.codim2).  The regions
drawn are bounded by the curves a, b, c and the pitchfork; the cells of the
eigenvalue grid only label them (shared.regions)."""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import matplotlib.pyplot as plt
import numpy
from matplotlib.colors import ListedColormap
from matplotlib.patches import Patch

from mlgshimmy.shared import freeplay
from mlgshimmy.shared import runerror
from mlgshimmy.shared import draw
from mlgshimmy.shared import gear
from mlgshimmy.shared import jobs
from mlgshimmy.shared import kappa_criterion
from mlgshimmy.shared import yfp_codim2
from mlgshimmy.shared import yfp_runs
from mlgshimmy.shared import paper
from mlgshimmy.shared import paths
from mlgshimmy.shared import regions
from mlgshimmy.shared.stage_switch import stage_switch_window

# What make, make help, make submit and the report know of this figure
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "fig18": {
        "help": "Fig. 18: a, b, c continued in F*, kappa*",
        "time": "70 s",
        "regress": True,
        "report": ("a, b, c continued in F*: regions of the (y_fp/eps, F*) plane and the "
                   "envelope y_fp/eps < kappa* for F* up to 2, a value the paper withholds "
                   "(IV.E)."),
        "held_out": {"kappa*": "kappa*"},
    },
    "fig18_v1": {
        "help": "Fig. 18 with the printed strut stage order",
        "time": "70 s",
        "options": "--strut-variant 1",
        "report": "Fig. 18 with the printed strut stage order (strut variant 1).",
    },
}

FSTARS = kappa_criterion.ENVELOPE_LOADS
MAP_KAPPA = numpy.geomspace(0.05, 8.0, 50)
MAP_SPEEDS = numpy.linspace(yfp_runs.V_MIN, yfp_runs.V_LIMIT, 30)
REGIONS = ("R1", "R2", "gentle oscillations", "high-frequency shimmy", "static yaw")
COLOURS = (draw.palette.ALLOWED, draw.palette.ALLOWED, draw.palette.ATTRACTOR["low"],
           draw.palette.ATTRACTOR["high"], draw.palette.ATTRACTOR["yaw"])
# (curve, colour, line style) of the threshold curves a, b, c and the pitchfork
CURVES = (("a", draw.STABLE, "-"), ("b", draw.STABLE, "--"), ("c", draw.palette.HOPF, "-"),
          ("p", draw.palette.PITCHFORK, ":"), ("a_end", draw.STABLE, "-."),
          ("next", draw.STABLE, "-."))
# a's window ends at b unless straight rolling is stable again below b: then
# its end, and the next window's start, are drawn (dash-dot)
LABELS = {"p": "pitchfork", "a_end": "stable again below b: its edges", "next": None}
NAMES = {"a_end": "end of a's window", "next": "next window"}


def region(Fstar: float, kappa: float, b: Optional[float], **model: float) -> int:
    """Index in REGIONS of what straight rolling does for V <= 120 m/s."""
    worst = {band: max(kappa_criterion.growth(Fstar, kappa * freeplay.EPSILON, V, **model)[band]
                       for V in MAP_SPEEDS)
             for band in kappa_criterion.BANDS}
    if worst["high"] > 0:
        return 3
    if worst["real"] > 0:
        return 4
    if worst["low"] > 0:
        return 2
    return 0 if b is None or kappa * freeplay.EPSILON < b else 1


def gap(Fstar: float, **model: float) -> Dict[str, Optional[float]]:
    """{"a_end", "next"}: the end of a's window of high-frequency
    instability in y_fp (b itself if straight rolling is not stable again
    below b at every V <= 120) and the start of the next window (None if
    there is none), from kappa_criterion.unstable_windows; None each if the
    mode is never unstable."""
    windows = kappa_criterion.unstable_windows(Fstar, "high", **model)
    if len(windows) > 2:
        yfp_runs.progress("fig18", f"F* = {Fstar:g}: {len(windows) - 1} bands of stable "
                                   "straight rolling between a and b; the first is drawn")
    return {"a_end": windows[0][1] if windows else None,
            "next": windows[1][0] if len(windows) > 1 else None}


def auto_check(rundir: str, points: Sequence[Mapping[str, Any]],
               **model: float) -> Tuple[Dict[str, List[Any]], Dict[str, List[Any]]]:
    """a and b continued by AUTO in (y_fp, F*) at V = 120 from F* = 1:
    ({name: [runs]}, {name: [(F*, AUTO's y_fp or RunError, the scan's)]});
    where a run stops, the point is located by AUTO at every scanned load
    on V = 120 instead (yfp_runs.window_point_values)."""
    window = kappa_criterion.window_points(yfp_runs.FSTAR, **model)
    curves, values = {}, {}
    for name in ("a", "b"):
        curves[name] = []
        if not numpy.isfinite(window[name]):
            yfp_runs.progress("fig18", f"AUTO: {name} lies beyond the scan (y_fp > "
                                       f"{yfp_runs.YFP_MAX:g} mm) at F* = "
                                       f"{yfp_runs.FSTAR:g}: not continued")
            continue
        curve = yfp_runs.window_point_curve(rundir, name, window[name], yfp_runs.FSTAR,
                                      (FSTARS[0], FSTARS[-1]), **model)
        for d, run in curve.items():
            if isinstance(run, runerror.RunError):
                yfp_runs.progress("fig18", f"AUTO: {name} continued {d} in F* stops: "
                                           f"{run.brief}")
            else:
                curves[name].append(run)
                yfp_runs.progress("fig18", f"AUTO: {name} continued {d} in F*")
        if len(curves[name]) < len(curve):
            values[name] = yfp_runs.window_point_values(rundir, f"{name}_at", name, points,
                                                        **model)
            failed = [F for F, found, _ in values[name] if isinstance(found, runerror.RunError)]
            yfp_runs.progress("fig18", f"AUTO: {name} located at {len(values[name])} loads "
                                       "on V = 120 instead, one run each"
                              + (f"; not at F* = {', '.join(f'{F:g}' for F in failed)}"
                                 if failed else ""))
    return curves, values


def runs(where: str = "fig18", **model: float) -> Tuple[List[Dict[str, Any]], numpy.ndarray, Any]:
    """(window points per F*, region map, AUTO's check runs)."""
    rundir = paths.rundir(where)
    points = []
    for Fstar in FSTARS:
        points.append(kappa_criterion.window_points(Fstar, **model))
        p = points[-1]
        p.update(gap(Fstar, **model))
        yfp_runs.progress(where, f"F* = {Fstar:.2f}: a {p['a']}, b {p['b']}, c {p['c']:.5g} "
                           f"(V {'-' if p['V_c'] is None else format(p['V_c'], '.3g')}), "
                           f"pitchfork {p['p']:.5g}")
    grid = numpy.array([[region(p["Fstar"], k, p["b"], **model) for k in MAP_KAPPA]
                        for p in points])
    yfp_runs.progress(where, "region map done")
    return points, grid, auto_check(rundir, points, **model)


def kappa_star(points: Sequence[Mapping[str, Any]],
               **model: float) -> Tuple[float, Dict[str, Any]]:
    """min over F* of the smallest y_fp/eps with unstable straight rolling:
    the grid minimum, refined on a grid 10 times finer around it."""
    return kappa_criterion.kappa_star(lambda F: kappa_criterion.window_points(F, **model), FSTARS,
                                      model, points)


def numbers(points: Sequence[Mapping[str, Any]], curves: Mapping[str, Any],
            values: Mapping[str, Any], kappa: float,
            best: Mapping[str, Any]) -> Dict[str, Optional[float]]:
    out = {"kappa*": kappa, "kappa*: at F*": best["Fstar"], "kappa*: at V [m/s]": best["first_V"]}
    for p in points:
        if round(p["Fstar"] * 10, 6) % 2 == 0:
            for k in "abcp":
                if p[k] is not None and numpy.isfinite(p[k]):
                    out[f"F* = {p['Fstar']:.1f}: {k} [y_fp/eps]"] = p[k] / freeplay.EPSILON
            for k in (("a_end", "next") if p.get("next") is not None else ()):
                out[f"F* = {p['Fstar']:.1f}: {NAMES[k]} [y_fp/eps]"] = p[k] / freeplay.EPSILON
    for name, runs in curves.items():
        # where the scan's point lies on V = 120 (b may lie at lower V)
        at_limit = [p for p in points
                    if p["V_" + name] == yfp_runs.V_LIMIT and numpy.isfinite(p[name])]
        for run in runs:
            Fs, ys = numpy.asarray(run[0]["Fstar"]), numpy.asarray(run[0]["yfp"])
            order = numpy.argsort(Fs)
            grid = [p for p in at_limit if Fs.min() <= p["Fstar"] <= Fs.max()]
            diff = [abs(numpy.interp(p["Fstar"], Fs[order], ys[order]) - p[name]) for p in grid]
            out[f"check: AUTO {name}, F* {Fs.min():.2f}-{Fs.max():.2f} ({len(grid)} grid "
                "points at V = 120), largest |AUTO - scan| [mm]"] = max(diff, default=None)
    for name, found in values.items():
        located = [abs(y - scan) for _, y, scan in found if not isinstance(y, runerror.RunError)]
        out[f"check: AUTO {name} located at {len(located)} of {len(found)} loads at V = 120, "
            "one run each, largest |AUTO - scan| [mm]"] = max(located, default=None)
    return out


def compute(name: str = "fig18", variant: int = 0) -> Dict[str, Any]:
    model = {"strut_variant": float(variant)} if variant else {}
    model.update(gear.parameters())   # the side-stay geometry ({} at the paper's)
    points, grid, (curves, values) = runs(name, **model)
    kappa, best = kappa_star(points, **model)
    yfp_runs.progress(name, "kappa* refined")
    drawn = [{"yfp": run[0]["yfp"], "Fstar": run[0]["Fstar"]}
             for name_runs in curves.values() for run in name_runs]
    return {"name": name, "variant": variant,
            "numbers": numbers(points, curves, values, kappa, best),
            "kappa_star": kappa,
            "kappa_star_Fstar": best["Fstar"], "points": points, "grid": grid,
            "auto": drawn,
            "auto_located": [{"yfp": y, "Fstar": F} for found in values.values()
                             for F, y, _ in found if not isinstance(y, runerror.RunError)],
            "codim2": yfp_codim2.codim2_points(drawn, "fixed", "Fstar", {"V": yfp_runs.V_LIMIT}, **model),
            "stage_switch": stage_switch_window(float(FSTARS[0]), float(FSTARS[-1]), **model)}


RASTER_KAPPA = numpy.geomspace(MAP_KAPPA[0], MAP_KAPPA[-1], 600)
EDGES = ("a", "b", "c", "p", "a_end", "next")   # the curves bounding the regions
BEYOND = 10.0                  # a point at infinity is drawn this far beyond the plot


def edge_curves(points: Sequence[Mapping[str, Any]]) -> Dict[str, Tuple[List[float], List[float]]]:
    """The curves a, b, c, p as (y_fp/eps, F*) polylines; a point that does
    not exist (None: no crossing for y_fp up to YFP_MAX, beyond the plot) is
    placed beyond the plot's right edge, so the curve leaves through it."""
    Fs = [p["Fstar"] for p in points]
    return {name: ([BEYOND * MAP_KAPPA[-1] if p.get(name) is None or not numpy.isfinite(p[name])
                    else p[name] / freeplay.EPSILON for p in points], Fs) for name in EDGES}


def painted_regions(points: Sequence[Mapping[str, Any]], grid: numpy.ndarray,
                    raster_F: numpy.ndarray) -> Tuple[numpy.ndarray, Dict[str, Any]]:
    """[F*, y_fp/eps] on raster_F x RASTER_KAPPA: the region index of each
    piece between the curves a, b, c, p, labelled by the eigenvalue grid's
    cells inside it (regions.paint); and the check of the labels."""
    samples = numpy.full((len(raster_F), len(RASTER_KAPPA)), -1, dtype=int)
    rows = numpy.rint(regions.index_of(raster_F, FSTARS)).astype(int)
    cols = numpy.rint(regions.index_of(RASTER_KAPPA, MAP_KAPPA)).astype(int)
    samples[numpy.ix_(rows, cols)] = grid
    edges = regions.curve_pixels(RASTER_KAPPA, raster_F, edge_curves(points).values())
    return regions.paint(edges, samples)


def drawn_values(points: Sequence[Mapping[str, Any]], name: str) -> numpy.ndarray:
    """y_fp/eps of the curve `name` at each load, NaN where it is not drawn:
    where it does not exist, and a's window's end where it is b (drawn as
    b) but at the loads next to where it is not, so that it meets b."""
    ys = numpy.array([numpy.nan if p.get(name) is None else p[name] / freeplay.EPSILON
                      for p in points])
    if name == "a_end":
        apart = numpy.array([p.get("next") is not None for p in points])
        near = apart | numpy.r_[apart[1:], False] | numpy.r_[False, apart[:-1]]
        ys[~near] = numpy.nan
    return ys


def plot(result: Mapping[str, Any]) -> None:
    paper.report(result["name"], result["numbers"],
                 notes=yfp_codim2.codim2_lines(result["codim2"], "Fstar"))
    points, auto, kappa = result["points"], result["auto"], result["kappa_star"]
    raster_F = numpy.linspace(FSTARS[0], FSTARS[-1], 400)   # where the curves are known
    painted, check = painted_regions(points, numpy.asarray(result["grid"]), raster_F)
    print(f"{result['name']}: {check['disagree']} of {check['samples']} grid cells disagree "
          "with the region between the curves that holds them")
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    ax.grid(False)
    ax.pcolormesh(RASTER_KAPPA, raster_F, painted, cmap=ListedColormap(COLOURS), vmin=-0.5,
                  vmax=len(REGIONS) - 0.5, alpha=0.8, shading="nearest", rasterized=True)
    Fs = [p["Fstar"] for p in points]
    for name, colour, line in CURVES:
        ys = drawn_values(points, name)
        if numpy.isfinite(ys).any():   # a curve with no point (no pitchfork at a geometry)
            ax.plot(ys, Fs, color=colour, ls=line, lw=1.6, label=LABELS.get(name, name))
    for run in auto:
        ax.plot(numpy.asarray(run["yfp"]) / freeplay.EPSILON, run["Fstar"], color=draw.palette.ON_FILL,
                ls=":", lw=1)
    located = result.get("auto_located", [])
    if located:
        ax.plot([p["yfp"] / freeplay.EPSILON for p in located], [p["Fstar"] for p in located],
                ls="none", marker="o", ms=3, mfc=draw.palette.ON_FILL, mec=draw.palette.GUIDE,
                mew=0.6,
                label="AUTO, one run per load")
    for point in result["codim2"]:
        draw.mark(ax, point["yfp"] / freeplay.EPSILON, point["Fstar"], point["type"])
    switch = result.get("stage_switch")
    if switch and switch[0] <= result["kappa_star_Fstar"] <= switch[1]:
        # kappa* is set inside the oleo's stage switch, narrower than the
        # loads' grid (a dips there between two loads): its value hangs on
        # how steep the model's switch is
        for k, f in enumerate(switch):
            ax.axhline(f, color=draw.palette.GUIDE, lw=0.6,
                       label=None if k else r"the oleo's stage switch, where $\kappa^*$ is set")
    ax.add_patch(plt.Rectangle((MAP_KAPPA[0], FSTARS[0]), kappa - MAP_KAPPA[0],
                               FSTARS[-1] - FSTARS[0], fill=False, hatch="//", lw=1.2))
    shown = set(numpy.unique(painted)) | ({1} if 0 in painted else set())   # R1, R2: one entry
    handles = ax.get_legend_handles_labels()[0] + [
        Patch(facecolor=colour, edgecolor=draw.palette.GUIDE, alpha=0.8, label=name)
        for k, colour, name in zip(range(1, len(REGIONS)), COLOURS[1:],
                                   ("R1, R2: straight rolling stable",) + REGIONS[2:])
        if k in shown
    ] + draw.point_handles(draw.marked_kinds(ax))
    ax.set(xscale="log", xlim=(MAP_KAPPA[0], MAP_KAPPA[-1]), ylim=(FSTARS[0], FSTARS[-1]),
           xlabel=r"$y_{fp}/\epsilon$", ylabel="$F_z^*$")
    draw.figure_title(ax, r"Fig. 18: straight rolling for V $\leq$ 120 m/s, $\epsilon$ = 0.1 mm"
                          "\n" + draw.STRUT_ORDER[result["variant"]]
                          + rf"; hatched: $y_{{fp}}/\epsilon < \kappa^*$ = {kappa:.3f}")
    ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    draw.save(fig, result["name"])


if __name__ == "__main__":
    jobs.run_variant_figure("fig18", __doc__.splitlines()[0], compute, plot)
