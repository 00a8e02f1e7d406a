"""Fig. 7: zero-freeplay diagrams in V for F* = 0.2 and F* = 1: straight
rolling, its Hopf point H and the periodic orbits born there; torsional and
lateral amplitudes."""
import sys

import matplotlib.pyplot as plt

import autoglue
import diagrams as dg

LOADS = (0.2, 1.0)


def compute(parameter_set="figures", where="fig07"):
    """{F*: (equilibria, periodic orbits)} for both loads."""
    rundir = dg.rundir(where)
    result = {}
    for Fstar in LOADS:
        tag = f"F{Fstar:g}"
        start = dg.Start(parameter_set, Fstar=Fstar, V=0.0)
        eq = dg.equilibria(rundir, f"eq_{tag}", start, stop={"V": 600.0}, expect=["HB"])
        po = dg.periodic_from(rundir, f"po_{tag}", eq("HB1"), stop={"V": 600.0})
        result[Fstar] = (eq, po)
    return result


def plot(result):
    fig, axes = plt.subplots(2, 2, figsize=(9, 6), sharex=True)
    for col, Fstar in enumerate(LOADS):
        eq, po = result[Fstar]
        for row, (measure, name) in enumerate((("psi_amp", r"$\psi$"), ("delta_amp", r"$\delta$"))):
            ax = axes[row][col]
            dg.plot_branch(ax, eq, "V", measure, scale=180 / 3.141592653589793)
            dg.plot_branch(ax, po, "V", measure, scale=180 / 3.141592653589793)
            dg.mark_points(ax, eq, "HB", "V", measure, text="H")
            ax.set_title(f"({'ab'[col]}{row + 1}) $F_z^*$ = {Fstar:g}")
            ax.set_ylabel(f"{name} amplitude [deg]")
            ax.set_xlim(0, 600)
            ax.axvspan(0, 80, color="0.9", zorder=0)
        axes[1][col].set_xlabel("V [m/s]")
    fig.suptitle("Fig. 7: zero freeplay (grey: operating region V ≤ 80 m/s; "
                 "solid stable, dashed unstable)")
    dg.save(fig, "fig07")


def main():
    try:
        result = compute()
    except (autoglue.RunError, ValueError, RuntimeError) as exc:
        sys.exit(f"fig07: {exc}")
    for Fstar, (eq, po) in result.items():
        print(f"fig07: F* = {Fstar:g}: Hopf at V = {eq('HB1')['V']:.3f} m/s; "
              f"orbit at V = {po['V'][-1]:.1f}: psi amplitude {po['psi_amp'][-1]:.4f} rad")
    plot(result)


if __name__ == "__main__":
    main()
