"""Fig. 13: freeplay magnitude at a fixed scaled profile, eps = 0.1 y_fp
(section IV.D.1), F* = 1: (a) diagrams in V for y_fp = 0.2, 0.5, 1, 2 mm,
(b) their stiffness profiles, (c, d) amplitude and frequency of the stable
orbits at V = 15, 50, 80, 110 m/s continued in y_fp."""
import sys

import matplotlib.pyplot as plt

import autoglue
import diagrams as dg
import magnitude as mg
import mlgmodel

FREEPLAYS = (0.2, 0.5, 1.0, 2.0)
COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red")
FIT_RANGE = (0.05, 2.0)   # y_fp range of the linear fits [mm]


def compute(where="fig13"):
    rundir = dg.rundir(where)
    diagrams = {y: mg.diagram_in_V(rundir, f"y{y:g}", "ratio", y, figure="fig13")
                for y in FREEPLAYS}
    orbits = mg.orbits_in_yfp(rundir, diagrams[1.0], figure="fig13")
    return diagrams, orbits


def numbers(diagrams, orbits):
    rows = []
    paper_hopf = {1.0: "1.5, 28.1, 142.5"}
    for y, d in diagrams.items():
        rows.append((f"Hopf speeds, y_fp = {y:g} mm [m/s]",
                     ", ".join(f"{V:.4f}" for V, _ in d.hopf), paper_hopf.get(y)))
        rows.append((f"fold speeds, y_fp = {y:g} mm [m/s]",
                     ", ".join(f"{V:.4f}" for *_, V, _ in d.folds()), "41.5" if y == 1.0 else None))
    for V, runs in orbits.items():
        ys, amp, stable = mg.orbit_curve(runs, "psi_amp")
        _, freq, _ = mg.orbit_curve(runs, "freq")
        inside = (ys >= FIT_RANGE[0]) & (ys <= FIT_RANGE[1])
        if not stable[inside].all():
            raise autoglue.RunError(f"fig13: orbit at V = {V:g} loses stability in y_fp")
        s0, residual, s, c = mg.linear_fit(ys[inside], amp[inside])
        rows.append((f"V = {V:g}: psi_amp / y_fp, fit through 0 [rad/mm]",
                     f"{s0:.6g} (max rel. residual {residual:.2e})", "linear (figure)"))
        rows.append((f"V = {V:g}: fit with intercept [rad/mm, rad]", f"{s:.6g}, {c:.3g}", None))
        rows.append((f"V = {V:g}: frequency over y_fp in {FIT_RANGE} [Hz]",
                     f"{freq[inside].min():.4f} - {freq[inside].max():.4f}", "nearly constant"))
    return rows


def plot(diagrams, orbits):
    fig, axes = plt.subplots(2, 2, figsize=(10, 7.5))
    k_tlk = mlgmodel.Model("figures")["k_tlk"]
    for (y, d), colour in zip(diagrams.items(), COLOURS):
        mg.plot_diagram(axes[0][0], d, colour, f"$y_{{fp}}$ = {y:g} mm")
        ys, force = mg.profile(y, "ratio", k_tlk, span=1.0 / y * 3.0)
        axes[0][1].plot(ys, force, color=colour, label=f"$y_{{fp}}$ = {y:g} mm")
    axes[0][0].set(xlabel="V [m/s]", ylabel=r"$\psi$ amplitude [deg]", xlim=(0, mg.V_MAX),
                   title="(a) diagrams in V (circles H, squares S)")
    axes[0][0].legend(fontsize=7)
    axes[0][1].set(xlabel="$y_{tlk}$ [mm]", ylabel=r"$M_{k\psi}/r_{tlk}$ [N]", xlim=(-3, 3),
                   title=r"(b) stiffness profiles, $\epsilon$ = 0.1 $y_{fp}$")
    axes[0][1].legend(fontsize=7)
    mg.plot_orbits(axes[1][0], axes[1][1], orbits)
    axes[1][0].set_title("(c) orbits at fixed V continued in $y_{fp}$")
    axes[1][1].set_title("(d) their frequency")
    axes[1][1].set_ylim(0, None)
    for ax in axes[1]:
        ax.set_xlim(0, mg.YFP_MAX)
    fig.suptitle(r"Fig. 13: $F^*$ = 1, $\epsilon/y_{fp}$ = 0.1 (solid stable, dashed unstable)")
    fig.tight_layout()
    dg.save(fig, "fig13")


def main():
    try:
        diagrams, orbits = compute()
        rows = numbers(diagrams, orbits)
    except (autoglue.RunError, ValueError, RuntimeError) as exc:
        sys.exit(f"fig13: {exc}")
    mg.write_numbers("fig13", rows)
    plot(diagrams, orbits)


if __name__ == "__main__":
    main()
