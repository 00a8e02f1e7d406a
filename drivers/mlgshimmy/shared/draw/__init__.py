"""Plot styles and helpers shared by the figure drivers (no AUTO import):
branches drawn by stability, special points marked and named, a legend
that explains both, figures saved.

    plot_branch(ax, diagram, "V", "psi_amp", scale=DEG)   # stable / unstable
    mark_specials(ax, orbits, "V", "psi_amp", scale=DEG)  # S, TR, ... of the branches
    mark(ax, V, 0.0, "HB", name="H1")                     # one point
    legend(ax)                       # stable, unstable and every point kind marked
    figure_title(fig, "Fig. 10: ...")   # left out with MLG_PAPER_STYLE=1
    save(fig, "fig10")          # $MLG_RUN_ROOT/figures/fig10.png and .pdf

Stability is told by colour *and* line style, colour-blind safe and
legible in grey scale: stable solid dark blue, unstable dashed orange
(STABLE, UNSTABLE).  Special points have one marker and one name in every
figure (POINTS): H Hopf (circle), S fold of periodic orbits (square), P
pitchfork (diamond), TR torus point (open triangle), and a stability change
of an orbit branch that AUTO labelled with nothing (open circle).  Their
names are placed when the figure is saved (labels.place), clear of each
other, of the markers and of the curves where possible; points of one
name that nearly coincide are named once.

MLG_PAPER_STYLE=1 in the environment (`make <fig> PAPER=1`) leaves out the
"Fig. N: ..." titles (figure_title) for use in a paper; panel titles stay.
"""
from __future__ import annotations

import os
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import matplotlib
import matplotlib.pyplot as plt
import numpy
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.legend import Legend
from matplotlib.lines import Line2D
from matplotlib.text import Text
from numpy.typing import ArrayLike

from mlgshimmy.shared import branches
from mlgshimmy.shared import gear
from mlgshimmy.shared import paths
from mlgshimmy.shared.draw import labels, overlap, palette
from mlgshimmy.shared.draw.palette import NEUTRAL, STABLE, UNSTABLE, sequence  # noqa: F401
from mlgshimmy.shared.jobs.atomic import write_atomic

STYLE = os.path.join(os.path.dirname(__file__), "mlg.mplstyle")
plt.style.use(STYLE)
# stable solid, unstable dashed: told apart by colour and by line style
STABLE_STYLE = {"color": STABLE, "linestyle": "-"}
UNSTABLE_STYLE = {"color": UNSTABLE, "linestyle": "--"}
# curves of bifurcation points in two parameters (Figs. 9, 14(h), 16, 17),
# dot-dashed as in the paper
HOPF_CURVE = {"color": palette.HOPF, "ls": "-.", "lw": 1.3}
FOLD_CURVE = {"color": palette.FOLD, "ls": "-.", "lw": 1.5}
DEG = numpy.degrees(1.0)
# the strut spring's two stage orders (switch strut_variant), in a reader's words
STRUT_ORDER = {0: "the strut's stages in the monotone order",
               1: "the strut's stages in the printed order"}

# AUTO type -> how it is drawn and named; "change": a stability change of
# an orbit branch with no AUTO label (AUTO's TR test fires only when its
# multiplier count and test function change in one step; docs/reproduction.md)
POINTS = {
    "HB": {"name": "H", "marker": "o", "mfc": palette.MARKER, "ms": 4.0, "legend": "Hopf point"},
    "LP": {"name": "S", "marker": "s", "mfc": palette.MARKER, "ms": 4.0,
           "legend": "fold of periodic orbits"},
    "BP": {"name": "P", "marker": "D", "mfc": palette.MARKER, "ms": 4.0, "legend": "pitchfork"},
    "LPeq": {"name": "F", "marker": "s", "mfc": palette.OPEN, "ms": 4.5,
             "legend": "fold of stationary states"},
    "TR": {"name": "TR", "marker": "^", "mfc": palette.OPEN, "ms": 5.0,
           "legend": "torus (Neimark-Sacker) point"},
    "PD": {"name": "PD", "marker": "v", "mfc": palette.OPEN, "ms": 5.0,
           "legend": "period doubling"},
    "GR": {"name": "G", "marker": "p", "mfc": palette.OPEN, "ms": 5.5,
           "legend": "grazing (a contact segment's duration reaches zero)"},
    "BEP": {"name": "B", "marker": "8", "mfc": palette.OPEN, "ms": 5.5,
            "legend": "boundary-equilibrium point (an equilibrium on a switching surface)"},
    "change": {"name": "", "marker": "o", "mfc": palette.OPEN, "ms": 4.5,
               "legend": "stability change AUTO did not label"},
    # codimension-two points on curves of Hopf points (shared.codim2)
    "GH": {"name": "GH", "marker": "*", "mfc": "k", "ms": 8.0,
           "legend": "generalised Hopf point (l1 = 0)"},
    "BT": {"name": "BT", "marker": "P", "mfc": "k", "ms": 6.0, "legend": "Bogdanov-Takens point"},
    "ZH": {"name": "ZH", "marker": "X", "mfc": "k", "ms": 6.0, "legend": "zero-Hopf point"},
    "HH": {"name": "HH", "marker": "h", "mfc": "k", "ms": 6.0, "legend": "Hopf-Hopf point"},
}
SPECIAL = ("LP", "BP", "TR")
START_ZONE = 1e-3   # relative distance from a branch's start inside which changes are noise   # the labelled points mark_specials marks on branches


def paper_style() -> bool:
    """True when figures are drawn for a paper (MLG_PAPER_STYLE=1)."""
    return os.environ.get("MLG_PAPER_STYLE", "").strip() not in ("", "0")


def figure_title(target: Union[Figure, Axes], text: str, **options: Any) -> Optional[Text]:
    """The figure's title ("Fig. N: ..."): fig.suptitle for a Figure, the
    title of an Axes otherwise; nothing in paper style."""
    if paper_style():
        return None
    if isinstance(target, matplotlib.figure.Figure):
        return target.suptitle(text, **options)
    return target.set_title(text, **options)


def sci(value: float, digits: int = 2) -> str:
    """A number for mathtext in scientific notation: 3.9e7 -> 3.9 x 10^7
    (as "$3.9 \\times 10^{7}$")."""
    mantissa, exponent = f"{value:.{digits - 1}e}".split("e")
    exponent = int(exponent)
    return f"${mantissa}$" if exponent == 0 else f"${mantissa} \\times 10^{{{exponent}}}$"


def style_of(stable: bool, color: Any = None, lw: float = 1.4) -> Dict[str, Any]:
    """Line keywords of a stable or unstable piece; with `color` given (a
    figure whose colours mean something else) only the style changes."""
    base = dict(STABLE_STYLE if stable else UNSTABLE_STYLE)
    if color is not None:
        base["color"] = color
    base["lw"] = lw
    return base


def plot_stability(ax: Axes, xs: ArrayLike, ys: ArrayLike, stable: ArrayLike,
                   label: Optional[str] = None, **style: Any) -> None:
    """A curve given as arrays with a stability mask: stable parts solid,
    unstable dashed, in STABLE / UNSTABLE unless `color` is given."""
    xs, ys, stable = numpy.asarray(xs), numpy.asarray(ys), numpy.asarray(stable)
    for s in branches.runs_of(stable):
        ok = bool(stable[s.start])
        ax.plot(xs[s], ys[s], label=label,
                **style_of(ok, style.get("color"), style.get("lw", 1.4)))
        label = None


def plot_branch(ax: Axes, diagram: Sequence[Any], x: str, y: str, scale: float = 1.0,
                label: Optional[str] = None, **style: Any) -> None:
    """Every branch of a diagram by stability (plot_stability)."""
    for branch in diagram:
        plot_stability(ax, branch[x], numpy.asarray(branch[y]) * scale,
                       branches.stable_mask(branch), label=label, **style)
        label = None


def mark(ax: Axes, x: float, y: float, kind: str, name: Optional[str] = None,
         color: Any = palette.MARKER, zorder: float = 5) -> None:
    """One special point of type `kind` (a key of POINTS) at (x, y), named
    `name` (default the kind's name; "" for none) when the figure is saved."""
    point = POINTS[kind]
    line, = ax.plot([x], [y], linestyle="", marker=point["marker"], ms=point["ms"],
                    mfc=(point["mfc"] if color == palette.MARKER or point["mfc"] == palette.OPEN
                         else color),
                    mec=color, mew=0.9, zorder=zorder)
    kinds = ax.__dict__.setdefault("_mlg_kinds", [])
    if kind not in kinds:
        kinds.append(kind)
    labels.register(ax, x, y, point["name"] if name is None else name, line)


def mark_points(ax: Axes, diagram: Sequence[Any], kind: str, x: str, y: str, scale: float = 1.0,
                text: Optional[str] = None, color: Any = palette.MARKER) -> None:
    """Mark and name the labelled points of one AUTO type (e.g. 'HB', 'LP')
    on every branch of a diagram (named `text`, default POINTS' name)."""
    for branch in diagram:
        for index, _, _ in branches.labelled_points(branch, kind):
            mark(ax, branch[x][index], branch[y][index] * scale, kind, name=text, color=color)


def stability_changes(branch: Any, near: int = 2) -> List[int]:
    """Point indices where an orbit branch changes stability with no AUTO
    label within `near` points (the change lies between index and index+1).
    The first and last `near` steps are left out: a branch from a Hopf
    point starts there with the Hopf point's own, arbitrary, flag."""
    stable = branches.stable_mask(branch)
    labelled = [index for index, _, _ in branches.labelled_points(branch)]
    return [int(i) for i in numpy.flatnonzero(stable[1:] != stable[:-1])
            if near <= i < len(stable) - 1 - near
            and all(abs(i - j) > near and abs(i + 1 - j) > near for j in labelled)]


def mark_specials(ax: Axes, diagram: Sequence[Any], x: str, y: str, scale: float = 1.0,
                  kinds: Sequence[str] = SPECIAL, changes: bool = True,
                  color: Any = palette.MARKER) -> None:
    """Every labelled special point of `kinds` on the branches of an orbit
    diagram (folds S, pitchforks P, torus points TR), and with `changes` the
    stability changes AUTO labelled with nothing (at the middle of the step
    across which the stability flips): a fold S where the branch turns back
    in x there (AUTO labels a fold only when its test function changes sign
    within one step), the open circle otherwise."""
    for kind in kinds:
        mark_points(ax, diagram, kind, x, y, scale, color=color)
    if changes:
        for branch in diagram:
            xs, ys = numpy.asarray(branch[x]), numpy.asarray(branch[y]) * scale
            for i in stability_changes(branch):
                at = 0.5 * (xs[i] + xs[i + 1])
                # next to the Hopf point a branch starts from, the flag flips
                # spuriously (multipliers at 1; as AUTO's fold test there)
                if abs(at - xs[0]) > START_ZONE * max(abs(xs[0]), 1e-12):
                    kind = "LP" if turns_back(xs, i) else "change"
                    mark(ax, at, 0.5 * (ys[i] + ys[i + 1]), kind, color=color)


def turns_back(xs: ArrayLike, i: int, near: int = 2) -> bool:
    """Whether the branch's x reverses its direction within `near` steps of
    the step from i to i+1."""
    steps = numpy.sign(numpy.diff(numpy.asarray(xs)[max(i - near, 0):i + near + 2]))
    return bool((steps > 0).any() and (steps < 0).any())


def stability_handles(color: Any = None) -> List[Line2D]:
    """Legend entries of the two stability styles (in `color` if given)."""
    return [Line2D([], [], label="stable", **style_of(True, color)),
            Line2D([], [], label="unstable", **style_of(False, color))]


def point_handles(kinds: Sequence[str]) -> List[Line2D]:
    """Legend entries of special point kinds: marker and "H: Hopf point"."""
    out = []
    for kind in kinds:
        point = POINTS[kind]
        label = f"{point['name']}: {point['legend']}" if point["name"] else point["legend"]
        out.append(Line2D([], [], linestyle="", marker=point["marker"], ms=point["ms"],
                          mfc=point["mfc"], mec=palette.MARKER, mew=0.9, label=label))
    return out


def marked_kinds(*axes: Axes) -> List[str]:
    """The point kinds marked on the given axes, in POINTS' order."""
    found = {k for ax in axes for k in ax.__dict__.get("_mlg_kinds", [])}
    return [k for k in POINTS if k in found]


def legend(target: Union[Figure, Axes], extra: Sequence[Any] = (),
           axes: Optional[Sequence[Axes]] = None, color: Any = None, stability: bool = True,
           **options: Any) -> Legend:
    """A legend on an Axes, or below the panels of a Figure: the stability
    styles (in `color` if the figure's colours mean something else;
    stability=False: none), `extra` handles, then every special point kind
    marked on `axes` (default: the Axes, or all axes of the Figure)."""
    is_figure = isinstance(target, matplotlib.figure.Figure)
    if axes is None:
        axes = target.axes if is_figure else [target]
    handles = (stability_handles(color) if stability else []) + list(extra)
    handles += point_handles(marked_kinds(*list(axes)))
    options.setdefault("fontsize", 7)
    options.setdefault("framealpha", 0.9)
    if is_figure:
        options.setdefault("loc", "upper center")
        options.setdefault("bbox_to_anchor", (0.5, 0.0))
        options.setdefault("ncol", 3)
        options.setdefault("frameon", False)
        options["fontsize"] = max(options["fontsize"], 8)
    return target.legend(handles=handles, **options)


def smooth(xs: ArrayLike, ys: ArrayLike, span: Tuple[float, float] = (1.0, 1.0),
           per_step: int = 12) -> Tuple[numpy.ndarray, numpy.ndarray]:
    """A curve through stored points (xs, ys), drawn smoothly: a centripetal
    Catmull-Rom spline (no loops or cusps, no overshoot beyond its
    neighbours' hull in practice) in coordinates scaled by `span` (the
    axes' ranges), `per_step` samples per stored step.  It passes through
    every stored point: a drawing aid, the data are unchanged."""
    p = numpy.c_[numpy.asarray(xs, float) / span[0], numpy.asarray(ys, float) / span[1]]
    if len(p) < 3:
        return numpy.asarray(xs, float), numpy.asarray(ys, float)
    ext = numpy.vstack([2 * p[0] - p[1], p, 2 * p[-1] - p[-2]])
    out = [p[:1]]
    for k in range(1, len(ext) - 2):
        p0, p1, p2, p3 = ext[k - 1:k + 3]
        t0 = 0.0
        t1 = t0 + max(numpy.linalg.norm(p1 - p0) ** 0.5, 1e-12)
        t2 = t1 + max(numpy.linalg.norm(p2 - p1) ** 0.5, 1e-12)
        t3 = t2 + max(numpy.linalg.norm(p3 - p2) ** 0.5, 1e-12)
        t = numpy.linspace(t1, t2, per_step + 1)[1:, None]
        a1 = (t1 - t) / (t1 - t0) * p0 + (t - t0) / (t1 - t0) * p1
        a2 = (t2 - t) / (t2 - t1) * p1 + (t - t1) / (t2 - t1) * p2
        a3 = (t3 - t) / (t3 - t2) * p2 + (t - t2) / (t3 - t2) * p3
        b1 = (t2 - t) / (t2 - t0) * a1 + (t - t0) / (t2 - t0) * a2
        b2 = (t3 - t) / (t3 - t1) * a2 + (t - t1) / (t3 - t1) * a3
        out.append((t2 - t) / (t2 - t1) * b1 + (t - t1) / (t2 - t1) * b2)
    curve = numpy.vstack(out)
    return curve[:, 0] * span[0], curve[:, 1] * span[1]


def surface(ax: Any, quads: numpy.ndarray, stable: ArrayLike,
            alpha: Tuple[float, float] = (0.45, 0.85),
            light: Tuple[float, float, float] = (-0.4, -1.0, 1.2)) -> None:
    """Quadrilaterals (n, 4, 3) in the data coordinates of a 3-D axes (its
    limits set) as one polygon collection, so that mplot3d sorts them by
    depth together: STABLE where `stable`, UNSTABLE where not (alpha: their
    opacities, the stable one lower so that unstable sheets under stable
    ones show), each darkened by the angle between its normal (in the axes'
    box units) and the light."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    box = numpy.array([numpy.ptp(lim) or 1.0 for lim in
                       (ax.get_xlim3d(), ax.get_ylim3d(), ax.get_zlim3d())])
    q = quads / box
    normal = numpy.cross(q[:, 2] - q[:, 0], q[:, 3] - q[:, 1])
    length = numpy.linalg.norm(normal, axis=1)
    light = numpy.asarray(light) / numpy.linalg.norm(light)
    facing = numpy.where(length > 0, numpy.abs(normal @ light) / numpy.maximum(length, 1e-300),
                         1.0)
    base = numpy.where(numpy.asarray(stable)[:, None], matplotlib.colors.to_rgb(STABLE),
                       matplotlib.colors.to_rgb(UNSTABLE))
    opacity = numpy.where(stable, alpha[0], alpha[1])
    colours = numpy.c_[base * (0.55 + 0.45 * facing[:, None]), opacity]
    ax.add_collection3d(Poly3DCollection(quads, facecolors=colours, edgecolors=colours,
                                         linewidths=0.2, zorder=1))


def save(fig: Figure, name: str) -> None:
    """Name the marked points (labels.place), then write
    $MLG_RUN_ROOT/figures/<name>.png and .pdf (each written beside and
    renamed, so a reader never sees half a file) and close fig.  A figure
    made for a changed gear says so in its title (gear.stamp); text that
    overlaps other text is reported, one line a pair (overlap.overlaps)."""
    gear.stamp(fig)
    labels.place(fig)
    for a, b in overlap.overlaps(fig):
        print(f"{name}: overlapping text: {a!r} and {b!r}")
    written = [write_atomic(os.path.join(paths.figures_dir(), f"{name}.{ext}"),
                            lambda out, ext=ext: fig.savefig(out, format=ext, bbox_inches="tight"),
                            mode="wb")
               for ext in ("png", "pdf")]
    plt.close(fig)
    print(f"{name}: wrote " + ", ".join(os.path.relpath(p, paths.ROOT) for p in written))
