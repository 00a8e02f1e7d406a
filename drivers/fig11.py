"""Fig. 11: the (V, F*) plane with +-1 mm of freeplay (epsilon = 0.1 y_fp):
the Hopf curves of straight rolling, the curves of folds of periodic orbits,
the pitchfork lines, and the zero-freeplay Hopf curve; regions shaded by the
attractors that coexist there.

The curves are AUTO continuations started from the Fig. 10 special points
(F* = 1).  The shading is computed, not drawn: the stability of straight
rolling from the eigenvalues of the exact Jacobian on a fine (V, F*) grid,
and the stable low-frequency (< 8 Hz) and high-frequency orbits from the
one-parameter diagrams in V (fig10.speed_diagram and the large-amplitude
family) on a set of loads, each holding over its band of F*; the
off-centre-yaw band lies between the pitchforks."""
import sys

import matplotlib.pyplot as plt
from matplotlib.patches import Patch
import numpy

import autoglue
import diagrams as dg
import fig10
import mlgmodel

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


def curves(rundir, parameter_set="figures"):
    """Hopf and fold curves continued from the F* = 1 points of Fig. 10, the
    pitchfork loads (at three speeds: they do not depend on V) and the
    zero-freeplay Hopf curve."""
    eq, hopf, branches = fig10.speed_diagram(dg.rundir("fig11/F1"), parameter_set,
                                             Fstar=1.0, **FREEPLAY)
    out = {"hopf": [], "fold": [], "zero": []}
    points = [dg.hopf_point(rundir, f"hb{k + 1}", parameter_set, "V", v, Fstar=1.0, **FREEPLAY)
              for k, v in enumerate(hopf)]
    for k, point in enumerate(points):
        for sign in (1, -1):
            out["hopf"].append(dg.hopf_curve(
                rundir, f"hopf{k + 1}{'+-'[sign < 0]}", point, ("Fstar", "V"), stop=STOP,
                DS=0.002 * sign, DSMAX=0.02, NMX=5000, allow_mx=True))
    # the fold S, located on an orbit run with the base step sizes (the fold
    # located on Fig. 10's finer-stepped run does not start the fold curve)
    high = dg.periodic_from(rundir, "po_fold", points[-1], stop={"V": [30.0, 200.0]},
                            NMX=400, expect=["LP"])
    for k, point in enumerate(high("LP")):
        for sign in (1, -1):
            out["fold"].append(dg.fold_curve(
                rundir, f"fold{k + 1}{'+-'[sign < 0]}", point, ("V", "Fstar"), stop=STOP,
                DS=0.05 * sign, DSMAX=1.0, NMX=400, allow_mx=True))
    zero = dg.hopf_point(rundir, "hb_zero", parameter_set, "V", 346.1, Fstar=1.0, yfp=0.0)
    for sign in (1, -1):
        out["zero"].append(dg.hopf_curve(rundir, f"hopf_zero{'+-'[sign < 0]}", zero,
                                         ("Fstar", "V"), stop=STOP, DS=0.02 * sign,
                                         allow_mx=True))
    out["pitchfork"] = []
    for V in (5.0, 50.0, 300.0):
        loads = [f for f, kind, _ in dg.stability_changes(
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
    hopf = [v for v, kind, _ in dg.stability_changes(parameter_set, "V", numpy.linspace(
        V_MIN, V_MAX, 3000), Fstar=1.0, **FREEPLAY) if kind == "HB"]
    point = dg.hopf_point(rundir, "large_hb", parameter_set, "V", hopf[-1], Fstar=1.0,
                          **FREEPLAY)
    seed = dg.periodic_from(rundir, "large_seed", point, stop={"V": [V_MIN, 300.0]})
    out = {}
    for sign in (1, -1):
        family = dg.periodic_from(rundir, f"large_F{'+-'[sign < 0]}", seed("UZ1"), "Fstar",
                                  stop={"Fstar": [F_MIN, F_MAX]}, UZR={"Fstar": list(SLICES)},
                                  DS=0.02 * sign, DSMAX=0.1, allow_mx=True)
        for start in family("UZ"):
            Fstar = min(SLICES, key=lambda f: abs(f - start["Fstar"]))
            if abs(Fstar - start["Fstar"]) > 1e-4 or Fstar in out:
                continue
            out[Fstar] = [dg.periodic_from(rundir, f"large_{Fstar:.3f}{'+-'[d < 0]}", start,
                                           stop={"V": [V_MIN, V_MAX]}, DS=2.0 * d, DSMAX=5.0,
                                           allow_mx=True) for d in (1, -1)]
    return out


def straight_rolling_stable(parameter_set="figures"):
    """[F*, V] on F_GRID x V_GRID: True where every eigenvalue of the exact
    Jacobian of straight rolling has a negative real part.  The equilibrium
    depends on F* only (it is checked at both ends of the V range)."""
    model = mlgmodel.Model(parameter_set, **FREEPLAY)
    stable = numpy.zeros((len(F_GRID), len(V_GRID)), dtype=bool)
    for i, Fstar in enumerate(F_GRID):
        model.set(Fstar=Fstar, V=V_GRID[-1])
        u = model.equilibrium()
        model.set(V=V_GRID[0])
        if max(abs(a - b) for a, b in zip(u.values(), model.equilibrium().values())) > 1e-9:
            raise RuntimeError(f"straight rolling at F* = {Fstar:g} depends on V")
        for j, V in enumerate(V_GRID):
            model.set(V=V)
            stable[i, j] = numpy.linalg.eigvals(numpy.array(model.jacobian(u))).real.max() < 0
    return stable


def stable_orbits(parameter_set="figures"):
    """Per load of SLICES: {"low"|"high": [(V0, V1), ...]}, the V-intervals
    of stable low- (< 8 Hz) and high-frequency orbits, from the diagram in V
    (all orbits born at Hopf points) and the large-amplitude family."""
    large = large_orbits(dg.rundir("fig11/large"), parameter_set)
    out, folds = [], {}
    for Fstar in SLICES:
        print(f"fig11: slice F* = {Fstar:.4f}")
        _, _, branches = fig10.speed_diagram(dg.rundir(f"fig11/slice_{Fstar:.4f}"),
                                             parameter_set, skip_failed=True, Fstar=Fstar,
                                             **FREEPLAY)
        found = {"low": [], "high": []}
        folds[Fstar] = [p for _, orbits in branches for p in orbits("LP")
                        if p["freq"] >= LOW_FREQUENCY_HZ]
        for orbits in [orbits for _, orbits in branches] + large.get(Fstar, []):
            for branch in orbits:
                V, freq = numpy.asarray(branch["V"]), numpy.asarray(branch["freq"])
                # stable orbits of non-zero amplitude, split into runs
                keep = dg.stable_mask(branch) & (numpy.asarray(branch["psi_amp"])
                                                 > fig10.COLLAPSED)
                runs = numpy.split(numpy.arange(len(V)), numpy.flatnonzero(numpy.diff(keep)) + 1)
                for run in runs:
                    if keep[run[0]]:
                        kind = "low" if numpy.median(freq[run]) < LOW_FREQUENCY_HZ else "high"
                        found[kind].append((V[run].min(), V[run].max()))
        out.append(found)
    return out, folds


def on_curves(point, curves, tol=0.01):
    """Whether the fold `point` lies on one of the computed fold curves
    (distance in V/V_MAX and F*/F_MAX below tol)."""
    return any(numpy.min(numpy.hypot((numpy.asarray(branch["V"]) - point["V"]) / V_MAX,
                                     (numpy.asarray(branch["Fstar"]) - point["Fstar"]) / F_MAX))
               < tol for curve in curves for branch in curve)


def upper_folds(rundir, first, folds):
    """Curves of folds of high-frequency orbits that the fold S curve
    (`first`) does not reach: continued both ways from each fold on the
    lowest slice above its top load that no curve computed so far passes
    through.  A direction that fails (or stalls: FOLD_TIME_LIMIT) is
    reported and left out."""
    top = max(numpy.max(branch["Fstar"]) for diagram in first for branch in diagram)
    above = [f for f in SLICES if f > top and folds[f]]
    if not above:
        return []
    out = []
    for k, point in enumerate(folds[above[0]]):
        if on_curves(point, out):
            continue
        for sign in (1, -1):
            name = f"fold_upper{k + 1}{'+-'[sign < 0]}"
            try:
                out.append(dg.fold_curve(rundir, name, point, ("V", "Fstar"), stop=STOP,
                                         DS=0.05 * sign, DSMAX=1.0, NMX=400, allow_mx=True,
                                         time_limit=FOLD_TIME_LIMIT))
            except autoglue.RunError as exc:
                print(f"REPORTED: {name} left out: {exc.brief}")
    return out


def attractor_map(sr_stable, orbits):
    """[F*, V] on the grid: the set of stable attractors other than the
    off-centre yaw ("straight", "low", "high") at each point.  Straight
    rolling comes from the eigenvalue grid; the orbits of a slice hold over
    its band of loads (half way to the neighbouring slices)."""
    edges = numpy.concatenate(([-numpy.inf], 0.5 * (SLICES[1:] + SLICES[:-1]), [numpy.inf]))
    band = numpy.searchsorted(edges, F_GRID) - 1
    found = numpy.empty(sr_stable.shape, dtype=object)
    for i, k in enumerate(band):
        present = {kind: numpy.zeros(len(V_GRID), dtype=bool) for kind in orbits[k]}
        for kind, intervals in orbits[k].items():
            for lo, hi in intervals:
                present[kind] |= (V_GRID >= lo) & (V_GRID <= hi)
        for j in range(len(V_GRID)):
            found[i, j] = frozenset([kind for kind in present if present[kind][j]]
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
        mask = numpy.vectorize(lambda f: f == frozenset(kinds))(found)
        if not mask.any():
            continue
        alpha = 0.3 if kinds else 0.15
        ax.contourf(V_GRID, F_GRID, mask.astype(float), levels=[0.5, 1.5], colors=[colour],
                    alpha=alpha)
        handles.append(Patch(color=colour, alpha=alpha, label=key))
    lo, hi = min(pitchforks), max(pitchforks)
    ax.axhspan(lo, hi, color="0.3", alpha=0.35, lw=0)
    return handles


def plot(result):
    out, found = result
    fig, ax = plt.subplots(figsize=(9, 6.5))
    regions = shade(ax, found, out["pitchfork"][1])
    for diagram in out["hopf"]:
        for branch in diagram:
            ax.plot(branch["V"], branch["Fstar"], "k-", lw=1.4)
    for diagram in out["fold"]:
        for branch in diagram:
            ax.plot(branch["V"], branch["Fstar"], "b--", lw=1.4)
    for diagram in out["zero"]:
        for branch in diagram:
            ax.plot(branch["V"], branch["Fstar"], "k:", lw=1.4)
    for f in out["pitchfork"][1]:
        ax.axhline(f, color="g", lw=1.4, ls="-.")
    for diagram in out["hopf"] + out["fold"] + out["zero"]:
        for point in diagram("MX"):
            ax.plot(point["V"], point["Fstar"], "rx", ms=8)
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
    dg.save(fig, "fig11")


def main():
    try:
        out = curves(dg.rundir("fig11"))
        orbits, folds = stable_orbits()
        out["fold"] += upper_folds(dg.rundir("fig11"), out["fold"], folds)
        found = attractor_map(straight_rolling_stable(), orbits)
    except (autoglue.RunError, ValueError, RuntimeError) as exc:
        sys.exit(f"fig11: {exc}")
    plot((out, found))


if __name__ == "__main__":
    main()
