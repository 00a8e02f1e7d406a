"""Shared pieces of the MLG figure drivers: starting runs at given
parameters, the standard continuations, and plotting branches by stability.

    start = Start("figures", Fstar=1.0)        # parameters + equilibrium
    eq = equilibria(rundir, "eq_F1", start)    # straight rolling in V
    po = periodic_from(rundir, "po_F1", eq("HB1"), stop={"V": 600})
"""
import os

import matplotlib
import matplotlib.pyplot as plt
import numpy

import autoglue
import mlgmodel

ROOT = autoglue.ROOT
MODEL = os.path.join(autoglue.BUILD, "models", "mlg")
CONSTANTS = os.path.join(ROOT, "constants", "c.mlg")
RUN_CONSTANTS = os.path.join(ROOT, "constants", "runs")
MEASURES = mlgmodel.MEASURES     # PAR(21) onwards (c/parameters.h MLG_MEASURES)

matplotlib.rcParams.update({"figure.dpi": 110, "savefig.dpi": 150, "font.size": 9,
                            "axes.grid": True, "grid.alpha": 0.3})
STABLE, UNSTABLE = "tab:green", "tab:red"


class Start:
    """Parameters of a run and the straight-rolling equilibrium there,
    validated by the c/ library before AUTO starts."""

    def __init__(self, parameter_set="figures", **values):
        self.model = mlgmodel.Model(parameter_set, **values)
        self.model.check()
        self.U = self.model.equilibrium()
        self.PAR = self.model.par()


def run(rundir, name, kind=None, **kw):
    """autoglue.run on the MLG model: the base constants, then the run-type
    file constants/runs/c.<kind> if given, then the keyword overrides."""
    files = [CONSTANTS] + ([os.path.join(RUN_CONSTANTS, f"c.{kind}")] if kind else [])
    rundir = autoglue.claim(rundir)           # emptied on first use: claim, then write
    mlgmodel.write_constants_files(rundir)    # constants set from Python (PAR(15))
    return autoglue.run(rundir, name, constants=files, e=MODEL, **kw)


def equilibria(rundir, name, start, parameter="V", stop=None, **kw):
    """Straight rolling continued in `parameter` from `start`."""
    return run(rundir, name, "equilibria", PAR=start.PAR, U=start.U,
               ICP=[parameter] + MEASURES, UZSTOP=stop or {}, **kw)


def periodic_from(rundir, name, point, parameter="V", stop=None, **kw):
    """The periodic orbits born at the Hopf point `point`, continued in `parameter`."""
    return run(rundir, name, "periodic", data=point, ICP=[parameter, 11] + MEASURES,
               UZSTOP=stop or {}, **kw)


def hopf_curve(rundir, name, point, parameters=("Fstar", "V"), stop=None, **kw):
    """Continue the Hopf point `point` in two parameters."""
    return run(rundir, name, "hopf_curve", data=point, ICP=list(parameters) + MEASURES,
               UZSTOP=stop or {}, **kw)


def fold_icp(parameters):
    """ICP of a fold-of-cycles continuation in two parameters: the period
    PAR(11) must come third, or AUTO keeps it fixed (periodic.f90, INITPS:
    the period is free only if ICP(3) = 11 or exactly two parameters are
    listed), and the curve found is one of folds at constant period."""
    return list(parameters) + [11] + MEASURES


def fold_curve(rundir, name, point, parameters=("V", "Fstar"), stop=None, **kw):
    """Continue the fold of periodic orbits `point` (an LP label of an orbit
    run) in two parameters.  AUTO 0.9.2 first only generates the extended
    system's starting data (5 steps, ending in EP); the curve is continued
    from there."""
    icp = fold_icp(parameters)
    first = run(rundir, f"{name}_start", "periodic", data=point, ISW=2, ICP=icp, DS=0.01,
                DSMAX=0.05)
    return run(rundir, name, "periodic", data=first("EP1"), ISW=2, ICP=icp,
               UZSTOP=stop or {}, **kw)


def stability_changes(parameter_set, parameter, grid, **values):
    """Where straight rolling changes stability along `grid` of `parameter`,
    from the eigenvalues of the exact Jacobian (c/ library), refined by
    bisection: [(value, kind, omega)], kind "HB" (complex pair, omega its
    imaginary part in rad/s) or "BP" (real eigenvalue).

    AUTO's Hopf test function follows the eigenvalue nearest the imaginary
    axis; on this model that is usually the lightly damped axial pair
    (Re ~ -0.016), so AUTO misses a torsional crossing unless a step lands
    within |Re| < 0.016 of it.  This scan finds every crossing; hopf_point()
    then has AUTO locate it."""
    def unstable(value):
        """(number of real, number of complex eigenvalues with Re > 0)."""
        model = mlgmodel.Model(parameter_set, **{**values, parameter: value})
        eig = numpy.linalg.eigvals(numpy.array(model.jacobian(model.equilibrium())))
        real = numpy.abs(eig.imag) <= 1e-9 * numpy.maximum(1.0, numpy.abs(eig.real))
        return int(numpy.sum(real & (eig.real > 0))), int(numpy.sum(~real & (eig.real > 0))), eig

    changes = []
    previous, counts = grid[0], unstable(grid[0])[:2]
    for value in grid[1:]:
        new = unstable(value)[:2]
        for kind, k in (("BP", 0), ("HB", 1)):
            if new[k] == counts[k]:
                continue
            lo, hi = previous, value
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                if unstable(mid)[k] == counts[k]:
                    lo = mid
                else:
                    hi = mid
            at = 0.5 * (lo + hi)
            eig = unstable(at)[2]
            critical = eig[numpy.argmin(numpy.abs(eig.real))]
            changes.append((at, kind, abs(critical.imag) if kind == "HB" else 0.0))
        previous, counts = value, new
    return sorted(changes)


def hopf_point(rundir, name, parameter_set, parameter, value, width=None, **values):
    """AUTO's HB solution at the Hopf point near `value` (from
    stability_changes): straight rolling continued through a narrow window
    around it with steps small enough for AUTO's Hopf test."""
    width = width or 0.01 * max(abs(value), 1.0)
    start = Start(parameter_set, **{**values, parameter: value - width})
    bd = equilibria(rundir, name, start, parameter, stop={parameter: value + width},
                    DS=width / 100, DSMAX=width / 100, NMX=1000, expect=["HB"])
    point = bd("HB1")
    if abs(point[parameter] - value) > 1e-4 * max(abs(value), 1.0):
        raise autoglue.RunError(f"run {name}: AUTO's HB at {parameter} = {point[parameter]:.6g}, "
                                f"the eigenvalue scan's at {value:.6g}")
    return point


def stable_mask(branch):
    """Per point: True where stable.  AUTO's stability() lists the last point
    index of each run of equal stability, negative for stable runs."""
    mask = numpy.zeros(len(branch), dtype=bool)
    start = 0
    for end in branch.stability():
        mask[start:abs(end)] = end < 0
        start = abs(end)
    return mask


def segments(branch, x, y):
    """Split one branch into runs of equal stability: [(xs, ys, stable), ...]."""
    xs, ys = numpy.asarray(branch[x]), numpy.asarray(branch[y])
    stable = stable_mask(branch)
    out, start = [], 0
    for i in range(1, len(xs) + 1):
        if i == len(xs) or stable[i] != stable[start]:
            # overlap one point so that the segments join
            out.append((xs[start:i + 1], ys[start:i + 1], bool(stable[start])))
            start = i
    return out


def plot_branch(ax, diagram, x, y, scale=1.0, label=None, **style):
    """Every branch of a diagram: stable parts solid green, unstable dashed red
    (or in `color`, keeping the line styles)."""
    for branch in diagram:
        for xs, ys, stable in segments(branch, x, y):
            ax.plot(xs, ys * scale, color=style.get("color", STABLE if stable else UNSTABLE),
                    linestyle="-" if stable else "--", lw=style.get("lw", 1.4), label=label)
            label = None


def mark_points(ax, diagram, kind, x, y, scale=1.0, text=None):
    """Mark and label the special points of one type (e.g. 'HB', 'LP')."""
    for point in diagram(kind):
        ax.plot(point[x], point[y] * scale, "ko", ms=3.5)
        ax.annotate(text or kind[0], (point[x], point[y] * scale), textcoords="offset points",
                    xytext=(3, 4), fontsize=8)


def save(fig, name):
    os.makedirs(autoglue.FIGURES_DIR, exist_ok=True)
    paths = [os.path.join(autoglue.FIGURES_DIR, f"{name}.{ext}") for ext in ("png", "pdf")]
    for path in paths:  # written beside, then renamed: a reader never sees half a file
        partial = f"{path}.{os.getpid()}.partial"
        fig.savefig(partial, bbox_inches="tight", format=path.rsplit(".", 1)[1])
        os.replace(partial, path)
    plt.close(fig)
    print(f"{name}: wrote " + ", ".join(os.path.relpath(p, ROOT) for p in paths))


def rundir(name):
    """$MLG_RUN_ROOT/<name> (default build/<name>), claimed by this process
    (autoglue.claim: emptied on first use, never written by another)."""
    return autoglue.claim(os.path.join(autoglue.RUN_ROOT, name))
