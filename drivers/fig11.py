"""Fig. 11: the (V, F*) plane with +-1 mm of freeplay (epsilon = 0.1 y_fp):
the Hopf curves of straight rolling, the curves of folds of periodic orbits,
the pitchfork lines, and the zero-freeplay Hopf curve; regions shaded by the
attractors that coexist there.

The curves are AUTO continuations started from the Fig. 10 special points
(F* = 1).  The shading is computed, not drawn: on a set of loads the full
one-parameter diagram in V (fig10.speed_diagram) gives the V-intervals of
stable straight rolling and of stable low-frequency (< 8 Hz) and
high-frequency orbits; the off-centre-yaw band lies between the pitchforks."""
import sys

import matplotlib.pyplot as plt
from matplotlib.patches import Patch
import numpy

import autoglue
import diagrams as dg
import fig10

F_MIN, F_MAX = 0.02, 3.5
V_MIN, V_MAX = 0.5, 600.0
FREEPLAY = dict(yfp=1.0, eps_rel=0.1)
SLICES = numpy.arange(0.125, 3.5, 0.25)
LOW_FREQUENCY_HZ = 8.0
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
    folds = [p for _, orbits in branches for p in orbits("LP")]
    for k, point in enumerate(folds):
        for sign in (1, -1):
            out["fold"].append(dg.fold_curve(
                rundir, f"fold{k + 1}{'+-'[sign < 0]}", point, ("V", "Fstar"), stop=STOP,
                DS=0.05 * sign, DSMAX=0.5, NMX=1500, allow_mx=True))
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


def attractors(parameter_set="figures"):
    """Per load of SLICES: {name: [(V0, V1), ...]} of stable straight
    rolling, low- and high-frequency orbits, from the diagram in V."""
    out = []
    for Fstar in SLICES:
        print(f"fig11: slice F* = {Fstar:.3f}")
        eq, _, branches = fig10.speed_diagram(dg.rundir(f"fig11/slice_{Fstar:.3f}"),
                                              parameter_set, skip_failed=True, Fstar=Fstar,
                                              **FREEPLAY)
        found = {"straight": [], "low": [], "high": []}
        for xs, _, stable in dg.segments(eq[0], "V", "psi_amp"):
            if stable:
                found["straight"].append((xs.min(), xs.max()))
        for _, orbits in branches:
            for branch in orbits:
                for xs, ys, stable in dg.segments(branch, "V", "freq"):
                    if stable:
                        kind = "low" if numpy.median(ys) < LOW_FREQUENCY_HZ else "high"
                        found[kind].append((xs.min(), xs.max()))
        out.append(found)
    return out


REGIONS = [  # (attractors present, colour, key)
    ({"straight", "high"}, "tab:orange", "bistable: straight rolling / high-frequency shimmy"),
    ({"low", "high"}, "tab:purple", "bistable: low- / high-frequency shimmy"),
    ({"low"}, "tab:cyan", "low-frequency shimmy"),
    ({"high"}, "tab:red", "high-frequency shimmy"),
]


def shade(ax, slices, pitchforks):
    Vs = numpy.linspace(V_MIN, V_MAX, 1200)
    half = 0.5 * (SLICES[1] - SLICES[0])
    for Fstar, found in zip(SLICES, slices):
        present = {kind: numpy.zeros_like(Vs, dtype=bool) for kind in found}
        for kind, intervals in found.items():
            for lo, hi in intervals:
                present[kind] |= (Vs >= lo) & (Vs <= hi)
        for kinds, colour, _ in REGIONS:
            mask = numpy.ones_like(Vs, dtype=bool)
            for kind in present:
                mask &= present[kind] if kind in kinds else ~present[kind]
            ax.fill_between(Vs, Fstar - half, Fstar + half, where=mask, color=colour,
                            alpha=0.25, lw=0, step="mid")
    lo, hi = min(pitchforks), max(pitchforks)
    ax.axhspan(lo, hi, color="0.5", alpha=0.35, lw=0)


def plot(result):
    out, slices = result
    fig, ax = plt.subplots(figsize=(9, 6.5))
    shade(ax, slices, out["pitchfork"][1])
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
               Patch(color="0.5", alpha=0.35, label="off-centre yaw")]
    handles += [Patch(color=c, alpha=0.25, label=key) for _, c, key in REGIONS]
    ax.legend(handles=handles, fontsize=7, loc="upper right")
    ax.set_xlim(0, V_MAX)
    ax.set_ylim(0, F_MAX)
    ax.set_xlabel("V [m/s]")
    ax.set_ylabel(r"$F_z^*$")
    ax.set_title(r"Fig. 11: $y_{fp}$ = 1 mm, $\epsilon$ = 0.1 mm; white: only straight "
                 f"rolling stable (shading from diagrams in V at F* = {SLICES[0]:g}, "
                 f"{SLICES[1]:g}, ...)", fontsize=8)
    dg.save(fig, "fig11")


def main():
    try:
        result = curves(dg.rundir("fig11")), attractors()
    except (autoglue.RunError, ValueError, RuntimeError) as exc:
        sys.exit(f"fig11: {exc}")
    plot(result)


if __name__ == "__main__":
    main()
