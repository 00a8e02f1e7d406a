"""Plot styles and helpers shared by the figure drivers (no AUTO import):
branches drawn by stability, special points marked, figures saved.

    plot_branch(ax, diagram, "V", "psi_amp", scale=DEG)   # green/red
    save(fig, "fig10")          # $MLG_RUN_ROOT/figures/fig10.png and .pdf
"""
import os

import matplotlib
import matplotlib.pyplot as plt
import numpy

from mlgshimmy.shared import branches
from mlgshimmy.shared import geometry
from mlgshimmy.shared import paths
from mlgshimmy.shared.jobs.atomic import write_atomic

matplotlib.rcParams.update({"figure.dpi": 110, "savefig.dpi": 150, "font.size": 9,
                            "axes.grid": True, "grid.alpha": 0.3})
STABLE, UNSTABLE = "tab:green", "tab:red"
DEG = numpy.degrees(1.0)


def plot_stability(ax, xs, ys, stable, label=None, **style):
    """A curve given as arrays with a stability mask: stable parts solid,
    unstable dashed, green/red unless `color` is given."""
    xs, ys, stable = numpy.asarray(xs), numpy.asarray(ys), numpy.asarray(stable)
    for s in branches.runs_of(stable):
        ok = bool(stable[s.start])
        ax.plot(xs[s], ys[s], color=style.get("color", STABLE if ok else UNSTABLE),
                linestyle="-" if ok else "--", lw=style.get("lw", 1.4), label=label)
        label = None


def plot_branch(ax, diagram, x, y, scale=1.0, label=None, **style):
    """Every branch of a diagram by stability (plot_stability)."""
    for branch in diagram:
        plot_stability(ax, branch[x], numpy.asarray(branch[y]) * scale,
                       branches.stable_mask(branch), label=label, **style)
        label = None


def mark_points(ax, diagram, kind, x, y, scale=1.0, text=None):
    """Mark and label the special points of one type (e.g. 'HB', 'LP') on
    every branch of a diagram."""
    for branch in diagram:
        for index, _, _ in branches.labelled_points(branch, kind):
            at = (branch[x][index], branch[y][index] * scale)
            ax.plot(*at, "ko", ms=3.5)
            ax.annotate(text or kind[0], at, textcoords="offset points", xytext=(3, 4),
                        fontsize=8)


def surface(ax, quads, stable, alpha=(0.45, 0.85), light=(-0.4, -1.0, 1.2)):
    """Quadrilaterals (n, 4, 3) in the data coordinates of a 3-D axes (its
    limits set) as one polygon collection, so that mplot3d sorts them by
    depth together: green where `stable`, red where not (alpha: their
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


def save(fig, name):
    """Write $MLG_RUN_ROOT/figures/<name>.png and .pdf (each written beside
    and renamed, so a reader never sees half a file) and close fig.  A figure
    made at a side-stay geometry says so in its title (geometry.stamp)."""
    geometry.stamp(fig)
    written = [write_atomic(os.path.join(paths.figures_dir(), f"{name}.{ext}"),
                            lambda out, ext=ext: fig.savefig(out, format=ext, bbox_inches="tight"),
                            mode="wb")
               for ext in ("png", "pdf")]
    plt.close(fig)
    print(f"{name}: wrote " + ", ".join(os.path.relpath(p, paths.ROOT) for p in written))
