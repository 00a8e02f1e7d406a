"""Fig. 14: freeplay magnitude at a fixed smoothing width eps = 0.1 mm
(section IV.D.2), F* = 1: (a-f) diagrams in V for y_fp = 0.05, 0.098, 0.11,
0.15, 0.35, 1.0 mm beside their stiffness profiles, (g, h) amplitude and
frequency of the stable orbits at V = 15, 50, 80, 110 m/s continued in y_fp,
with the Hopf curves in (y_fp, V) dot-dashed in (h)."""
import sys

import matplotlib.pyplot as plt
import numpy

import autoglue
import diagrams as dg
import magnitude as mg
import mlgmodel
import paper_table

FREEPLAYS = (0.05, 0.098, 0.11, 0.15, 0.35, 1.0)


def compute(where="fig14"):
    rundir = dg.rundir(where)
    diagrams = {y: mg.diagram_in_V(rundir, f"y{y:g}", "fixed", y, figure="fig14")
                for y in FREEPLAYS}
    orbits = mg.orbits_in_yfp(rundir, diagrams[1.0], figure="fig14")
    curves = mg.hopf_curves(rundir, "hopf", "fixed", figure="fig14")
    return diagrams, orbits, curves


def lowest_orbit(runs, V):
    """(y_fp, kind): the smallest y_fp the orbits of speed V reach, and
    whether that is a Hopf point of straight rolling in y_fp ('Hopf'; AUTO
    may label the collapse there LP) or a fold in y_fp ('fold')."""
    ys, _, _ = mg.orbit_curve(runs, "psi_amp")
    y_min = float(ys.min())
    hopf = [y for y, k, _ in mg.yfp_thresholds("fixed", V) if k == "HB"]
    return y_min, "Hopf" if any(abs(y_min - y) < 2e-3 * y for y in hopf) else "fold"


def numbers(diagrams, orbits):
    """{quantity: value}: Hopf and fold speeds per y_fp; per orbit speed the
    smallest y_fp the orbits reach and the Hopf points in y_fp there."""
    out = {}
    for y, d in diagrams.items():
        for k, (V, _) in enumerate(d.hopf):
            out[f"y_fp = {y:g}: H{k + 1} [m/s]"] = V
        for k, (*_, V, _) in enumerate(d.folds()):
            out[f"y_fp = {y:g}: S{k + 1} [m/s]"] = V
        for run in d.branches:   # turning speed, whether or not AUTO labels it LP
            Vs = numpy.asarray(run[0]["V"])
            if Vs.min() < Vs[0] - 0.5:
                out[f"y_fp = {y:g}: smallest V of the orbits from H at {Vs[0]:.1f} [m/s]"] = \
                    Vs.min()
    for V, runs in orbits.items():
        y_min, kind = lowest_orbit(runs, V)
        out[f"V = {V:g}: orbits down to y_fp [mm] ({kind})"] = y_min
        hopf = [y for y, k, _ in mg.yfp_thresholds("fixed", V) if k == "HB"]
        for k, y in enumerate(hopf):
            out[f"V = {V:g}: Hopf point {k + 1} in y_fp [mm]"] = y
    return out


def plot(diagrams, orbits, curves):
    fig = plt.figure(figsize=(12, 12))
    grid = fig.add_gridspec(4, 6)
    k_tlk = mlgmodel.Model("figures")["k_tlk"]
    for n, (y, d) in enumerate(diagrams.items()):
        row, col = divmod(n, 2)
        ax = fig.add_subplot(grid[row, 3 * col:3 * col + 2])
        mg.plot_diagram(ax, d, None, None)
        ax.set(xlim=(0, mg.V_MAX), xlabel="V [m/s]", ylabel=r"$\psi$ amplitude [deg]",
               title=f"({'abcdef'[n]}) $y_{{fp}}$ = {y:g} mm")
        inset = fig.add_subplot(grid[row, 3 * col + 2])
        ys, force = mg.profile(y, "fixed", k_tlk, span=max(3.0, 0.6 / y))
        inset.plot(ys, force / 1e3, color="k", lw=1)
        inset.set(xlabel="$y_{tlk}$ [mm]", ylabel=r"$M_{k\psi}/r_{tlk}$ [kN]")
    ax_amp = fig.add_subplot(grid[3, 0:3])
    ax_freq = fig.add_subplot(grid[3, 3:6])
    mg.plot_orbits(ax_amp, ax_freq, orbits)
    label = "Hopf curves"
    for curve in curves:
        for run in curve:
            ax_freq.plot(run[0]["yfp"], 1.0 / numpy.asarray(run[0]["T"]), "k-.", lw=0.9,
                         label=label)
            label = None
    ax_freq.legend(fontsize=7)
    ax_amp.set(xscale="log", title="(g) orbits at fixed V continued in $y_{fp}$")
    ax_freq.set(xscale="log", ylim=(0, 45), title="(h) their frequency; Hopf curves dot-dashed")
    fig.suptitle(r"Fig. 14: $F^*$ = 1, $\epsilon$ = 0.1 mm (solid stable, dashed unstable; "
                 "circles H, squares S)")
    fig.tight_layout()
    dg.save(fig, "fig14")


def main():
    try:
        diagrams, orbits, curves = compute()
        ours = numbers(diagrams, orbits)
    except (autoglue.RunError, ValueError, RuntimeError) as exc:
        sys.exit(f"fig14: {exc}")
    paper_table.report("fig14", ours)
    plot(diagrams, orbits, curves)


if __name__ == "__main__":
    main()
