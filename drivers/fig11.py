"""Fig. 11: the (V, F*) plane with +-1 mm of freeplay (epsilon = 0.1 y_fp):
the Hopf curves of straight rolling, the curves of folds of periodic orbits,
the pitchfork lines, and the zero-freeplay Hopf curve; regions shaded by the
attractors that coexist there.

The curves are AUTO continuations started from the Fig. 10 special points
(F* = 1).  The shading is computed, not drawn: the stability of straight
rolling from the eigenvalues of the exact Jacobian on a fine (V, F*) grid,
and the stable low-frequency (< 8 Hz) and high-frequency orbits from the
one-parameter diagrams in V (continuation.speed_diagram and the
large-amplitude family) on a set of loads, each holding over its band of F*; the
off-centre-yaw band lies between the pitchforks."""
import matplotlib.pyplot as plt
from matplotlib.patches import Patch
import numpy

import autoglue
import branches
import continuation as ct
import paths
import plotting
import results
import spectrum

F_MIN, F_MAX = 0.02, 3.5
V_MIN, V_MAX = 0.5, 600.0
FREEPLAY = dict(yfp=1.0, eps_rel=0.1)
# loads of the diagrams in V: denser where the low-load structure is
SLICES = numpy.concatenate((numpy.arange(0.0625, 2.0, 0.125), numpy.arange(2.125, 3.5, 0.25)))
F_GRID = numpy.arange(F_MIN, F_MAX + 1e-9, 0.01)
V_GRID = numpy.arange(V_MIN, V_MAX + 1e-9, 0.5)
LOW_FREQUENCY_HZ = 8.0
FOLD_TIME_LIMIT = 120  # s, guard for a fold-curve run (they take 20-40 s)
STOP = {"Fstar": [F_MIN, F_MAX], "V": [V_MIN, V_MAX]}
V_SCAN = numpy.linspace(V_MIN, V_MAX, 3000)


def curves(rundir, parameter_set="figures"):
    """Hopf and fold curves continued from the F* = 1 points of Fig. 10, the
    pitchfork loads (at three speeds: they do not depend on V) and the
    zero-freeplay Hopf curve."""
    out = {"hopf": [], "fold": [], "zero": []}
    points = ct.hopf_points(rundir, "hb", parameter_set, "V", V_SCAN, Fstar=1.0, **FREEPLAY)
    for k, point in enumerate(points):
        for sign in (1, -1):
            out["hopf"].append(ct.hopf_curve(
                rundir, f"hopf{k + 1}{'+-'[sign < 0]}", point, ("Fstar", "V"), stop=STOP,
                DS=0.002 * sign, DSMAX=0.02, NMX=5000, allow_mx=True))
    # the fold S, located on an orbit run with the base step sizes (the fold
    # located on Fig. 10's finer-stepped run does not start the fold curve)
    high = ct.periodic_from(rundir, "po_fold", points[-1], stop={"V": [30.0, 200.0]},
                            NMX=400, expect=["LP"])
    for k, point in enumerate(high("LP")):
        for sign in (1, -1):
            out["fold"].append(ct.fold_curve(
                rundir, f"fold{k + 1}{'+-'[sign < 0]}", point, ("V", "Fstar"), stop=STOP,
                DS=0.05 * sign, DSMAX=1.0, NMX=400, allow_mx=True))
    zero, = ct.hopf_points(rundir, "hb_zero", parameter_set, "V", V_SCAN, Fstar=1.0, yfp=0.0)
    for sign in (1, -1):
        out["zero"].append(ct.hopf_curve(rundir, f"hopf_zero{'+-'[sign < 0]}", zero,
                                         ("Fstar", "V"), stop=STOP, DS=0.02 * sign,
                                         allow_mx=True))
    out["pitchfork"] = []
    for V in (5.0, 50.0, 300.0):
        loads = [f for f, kind, _ in spectrum.stability_changes(
            parameter_set, "Fstar", numpy.linspace(F_MIN, F_MAX, 800), V=V, **FREEPLAY)
            if kind == "BP"]
        print(f"fig11: pitchforks at V = {V:g}: F* = " + ", ".join(f"{f:.6f}" for f in loads))
        out["pitchfork"].append(loads)
    return out


def large_orbits(rundir, parameter_set="figures"):
    """{slice load: orbit diagram in V} of the large-amplitude shimmy family.
    Away from F* = 1 it need not be connected to a Hopf point of straight
    rolling inside V <= 600, so it is followed from the stable orbit at
    F* = 1, V = 300 m/s: continued in F* to every slice load, then in V."""
    hopf = spectrum.hopf_scan(parameter_set, "V", V_SCAN, Fstar=1.0, **FREEPLAY)
    point = ct.hopf_point(rundir, "large_hb", parameter_set, "V", hopf[-1][0], Fstar=1.0,
                          **FREEPLAY)
    seed = ct.periodic_from(rundir, "large_seed", point, stop={"V": [V_MIN, 300.0]})
    out = {}
    for sign in (1, -1):
        family = ct.periodic_from(rundir, f"large_F{'+-'[sign < 0]}", seed("UZ1"), "Fstar",
                                  stop={"Fstar": [F_MIN, F_MAX]}, UZR={"Fstar": list(SLICES)},
                                  DS=0.02 * sign, DSMAX=0.1, allow_mx=True)
        for start in family("UZ"):
            Fstar = min(SLICES, key=lambda f: abs(f - start["Fstar"]))
            if abs(Fstar - start["Fstar"]) > 1e-4 or Fstar in out:
                continue
            out[Fstar] = [ct.periodic_from(rundir, f"large_{Fstar:.3f}{'+-'[d < 0]}", start,
                                           stop={"V": [V_MIN, V_MAX]}, DS=2.0 * d, DSMAX=5.0,
                                           allow_mx=True) for d in (1, -1)]
    return out


def straight_rolling_stable(parameter_set="figures"):
    """[F*, V] on F_GRID x V_GRID: True where straight rolling is stable."""
    return spectrum.stable_on_grid(parameter_set, "Fstar", F_GRID, "V", V_GRID, **FREEPLAY)


ORBIT_COLUMNS = ("V", "freq", "psi_amp")


def slice_rundir(Fstar):
    return paths.rundir(f"fig11/slice_{Fstar:.4f}")


def slice_diagram(Fstar, parameter_set="figures"):
    """The diagram in V at one slice load: its orbit branches (stored) and
    its folds of high-frequency orbits [(run name, label)] (to start fold
    curves from)."""
    print(f"fig11: slice F* = {Fstar:.4f}")
    diagram = ct.speed_diagram(slice_rundir(Fstar), parameter_set, {"Fstar": Fstar, **FREEPLAY},
                               V_SCAN, allow_failed=True, figure="fig11", DS=0.05, DSMAX=1.0,
                               NMX=2000)
    return {"branches": [b for run in diagram.branches
                         for b in results.stored(run, ORBIT_COLUMNS)],
            "folds": [(diagram.name_of(run), lab) for run, lab, _, _ in diagram.folds()
                      if run(lab)["freq"] >= LOW_FREQUENCY_HZ]}


def large_family(parameter_set="figures"):
    """large_orbits stored: {slice load as "%.4f": [stored branches]}."""
    return {f"{Fstar:.4f}": [b for run in runs for b in results.stored(run, ORBIT_COLUMNS)]
            for Fstar, runs in large_orbits(paths.rundir("fig11/large"), parameter_set).items()}


def stable_orbits(stored):
    """{"low"|"high": [(V0, V1), ...]}: the V-intervals of stable low- (< 8
    Hz) and high-frequency orbits on stored branches of one slice load."""
    found = {"low": [], "high": []}
    for branch in results.loaded(stored):
        V, freq = branch["V"], branch["freq"]
        # stable orbits of non-zero amplitude
        keep = branches.stable_mask(branch) & (branch["psi_amp"] > ct.COLLAPSED)
        for run in branches.runs_of(keep, overlap=False):
            if keep[run.start]:
                kind = "low" if numpy.median(freq[run]) < LOW_FREQUENCY_HZ else "high"
                found[kind].append((V[run].min(), V[run].max()))
    return found


def on_curves(point, curves, tol=0.01):
    """Whether the fold `point` lies on one of the computed fold curves
    (distance in V/V_MAX and F*/F_MAX below tol)."""
    return any(numpy.min(numpy.hypot((numpy.asarray(branch["V"]) - point["V"]) / V_MAX,
                                     (numpy.asarray(branch["Fstar"]) - point["Fstar"]) / F_MAX))
               < tol for curve in curves for branch in curve)


def upper_folds(rundir, first, folds):
    """Curves of folds of high-frequency orbits that the fold S curve
    (`first`, stored) does not reach: continued both ways from each fold on
    the lowest slice above its top load (folds: {slice load: [(run name,
    label)]}) that no curve computed so far passes through.  A direction
    that fails (or stalls: FOLD_TIME_LIMIT) is reported and left out."""
    top = max(numpy.max(branch["Fstar"]) for diagram in first
              for branch in results.loaded(diagram))
    above = [f for f in SLICES if f > top and folds[f]]
    if not above:
        return []
    out = []
    points = [ct.load(slice_rundir(above[0]), name)(lab) for name, lab in folds[above[0]]]
    for k, point in enumerate(points):
        if on_curves(point, out):
            continue
        for sign in (1, -1):
            name = f"fold_upper{k + 1}{'+-'[sign < 0]}"
            try:
                out.append(ct.fold_curve(rundir, name, point, ("V", "Fstar"), stop=STOP,
                                         DS=0.05 * sign, DSMAX=1.0, NMX=400, allow_mx=True,
                                         time_limit=FOLD_TIME_LIMIT))
            except autoglue.RunError as exc:
                print(f"REPORTED: {name} left out: {exc.brief}")
    return out


ATTRACTORS = {"straight": 1, "low": 2, "high": 4}   # bits of an attractor map code


def code(kinds):
    """The attractor map code of a set of attractors."""
    return sum(ATTRACTORS[kind] for kind in kinds)


def attractor_map(sr_stable, orbits):
    """[F*, V] on the grid: the code of the set of stable attractors other
    than the off-centre yaw ("straight", "low", "high") at each point.
    Straight rolling comes from the eigenvalue grid; the orbits of a slice
    hold over its band of loads (half way to the neighbouring slices)."""
    edges = numpy.concatenate(([-numpy.inf], 0.5 * (SLICES[1:] + SLICES[:-1]), [numpy.inf]))
    band = numpy.searchsorted(edges, F_GRID) - 1
    found = numpy.zeros(sr_stable.shape, dtype=int)
    for i, k in enumerate(band):
        present = {kind: numpy.zeros(len(V_GRID), dtype=bool) for kind in orbits[k]}
        for kind, intervals in orbits[k].items():
            for lo, hi in intervals:
                present[kind] |= (V_GRID >= lo) & (V_GRID <= hi)
        for j in range(len(V_GRID)):
            found[i, j] = code([kind for kind in present if present[kind][j]]
                               + (["straight"] if sr_stable[i, j] else []))
    return found


REGIONS = [  # (attractors present, colour, key); white: straight rolling only
    ({"straight", "high"}, "tab:orange", "bistable: straight rolling / high-frequency shimmy"),
    ({"straight", "low"}, "tab:olive", "bistable: straight rolling / low-frequency shimmy"),
    ({"low", "high"}, "tab:purple", "bistable: low- / high-frequency shimmy"),
    ({"straight", "low", "high"}, "tab:brown", "straight rolling, low- and high-frequency"),
    ({"low"}, "tab:cyan", "low-frequency shimmy"),
    ({"high"}, "tab:red", "high-frequency shimmy"),
    (set(), "tab:gray", "no stable equilibrium or orbit found (beyond torus points)"),
]


def shade(ax, found, pitchforks):
    """Fill each region of the attractor map; returns the legend patches of
    the regions present."""
    handles = []
    for kinds, colour, key in REGIONS:
        mask = found == code(kinds)
        if not mask.any():
            continue
        alpha = 0.3 if kinds else 0.15
        ax.contourf(V_GRID, F_GRID, mask.astype(float), levels=[0.5, 1.5], colors=[colour],
                    alpha=alpha)
        handles.append(Patch(color=colour, alpha=alpha, label=key))
    lo, hi = min(pitchforks), max(pitchforks)
    ax.axhspan(lo, hi, color="0.3", alpha=0.35, lw=0)
    return handles


def stored_curves():
    out = curves(paths.rundir("fig11/curves"))
    return {**{kind: [results.stored(d, ("V", "Fstar")) for d in out[kind]]
               for kind in ("hopf", "fold", "zero")}, "pitchfork": out["pitchfork"]}


def parts():
    """The curves from F* = 1, the large-amplitude family, the eigenvalue
    grid and one diagram in V per slice load: independent jobs."""
    jobs = {"curves": stored_curves, "large": large_family, "grid": straight_rolling_stable}
    jobs.update({f"slice_{Fstar:.4f}": lambda Fstar=Fstar: slice_diagram(Fstar)
                 for Fstar in SLICES})
    return jobs


def compute(parts):
    """The parts assembled: the second fold curve (from a slice above the
    fold S curve's top) and the attractor map."""
    stored = parts["curves"]
    slices = {Fstar: parts[f"slice_{Fstar:.4f}"] for Fstar in SLICES}
    large = parts["large"]
    upper = upper_folds(paths.rundir("fig11/upper_folds"), stored["fold"],
                        {Fstar: part["folds"] for Fstar, part in slices.items()})
    orbits = [stable_orbits(part["branches"] + large.get(f"{Fstar:.4f}", []))
              for Fstar, part in slices.items()]
    found = attractor_map(numpy.asarray(parts["grid"], dtype=bool), orbits)
    drawn = {kind: stored[kind] for kind in ("hopf", "fold", "zero")}
    drawn["fold"] += [results.stored(d, ("V", "Fstar")) for d in upper]
    return {"curves": drawn, "pitchfork": stored["pitchfork"], "map": found}


def plot(result):
    found = numpy.asarray(result["map"])
    curves = {kind: [results.loaded(d) for d in diagrams]
              for kind, diagrams in result["curves"].items()}
    fig, ax = plt.subplots(figsize=(9, 6.5))
    regions = shade(ax, found, result["pitchfork"][1])
    for kind, style in (("hopf", "k-"), ("fold", "b--"), ("zero", "k:")):
        for diagram in curves[kind]:
            for branch in diagram:
                ax.plot(branch["V"], branch["Fstar"], style, lw=1.4)
    for f in result["pitchfork"][1]:
        ax.axhline(f, color="g", lw=1.4, ls="-.")
    for diagram in curves["hopf"] + curves["fold"] + curves["zero"]:
        for branch in diagram:
            for index, _, _ in branches.labelled_points(branch, "MX"):
                ax.plot(branch["V"][index], branch["Fstar"][index], "rx", ms=8)
    handles = [plt.Line2D([], [], color="k", label="Hopf (y_fp = 1 mm)"),
               plt.Line2D([], [], color="b", ls="--", label="fold of periodic orbits"),
               plt.Line2D([], [], color="g", ls="-.", label="pitchfork"),
               plt.Line2D([], [], color="k", ls=":", label="Hopf, zero freeplay"),
               plt.Line2D([], [], color="r", marker="x", ls="", label="continuation stopped (MX)"),
               Patch(color="0.3", alpha=0.35, label="off-centre yaw")]
    ax.legend(handles=handles + regions, fontsize=7, loc="upper right", framealpha=0.9)
    ax.set_xlim(0, V_MAX)
    ax.set_ylim(0, F_MAX)
    ax.set_xlabel("V [m/s]")
    ax.set_ylabel(r"$F_z^*$")
    ax.set_title(r"Fig. 11: $y_{fp}$ = 1 mm, $\epsilon$ = 0.1 mm; white: only straight "
                 "rolling stable; orbit shading from diagrams in V at "
                 f"F* = {SLICES[0]:g}, {SLICES[1]:g}, ..., {SLICES[-1]:g}", fontsize=8)
    plotting.save(fig, "fig11")


if __name__ == "__main__":
    results.run_figure("fig11", compute, plot, parts)
