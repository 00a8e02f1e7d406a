"""The interval (a_12, b_12) of section IV.C: at V = 50 m/s, y_fp = 1 mm,
eps = 0.1 y_fp, the loads F* where straight rolling is stable and coexists
with stable high-frequency shimmy.  Computed here from a diagram in F*:
where straight rolling is stable (eigenvalue scan), the stable orbit of V = 50
at F* = 1 continued in F*, and the orbits born at the Hopf point in F* (the
unstable ones separate the two).  Plot: build/figures/bistable_v50.png."""
import sys

import matplotlib.pyplot as plt
import numpy

import autoglue
import diagrams as dg
import magnitude as mg

V = 50.0
YFP = 1.0
FSTAR_RANGE = (0.005, 3.0)   # F* = 0 lifts a wheel off


def compute(where="bistable_v50"):
    rundir = dg.rundir(where)
    vals = {"V": V, "yfp": YFP, **mg.SCALINGS["ratio"]}
    changes = dg.stability_changes("figures", "Fstar", numpy.linspace(*FSTAR_RANGE, 600), **vals)
    icp = ["Fstar", 11] + dg.MEASURES
    runs = {}
    for n, (Fstar, kind, _) in enumerate(changes):
        if kind != "HB":
            continue
        hb = dg.hopf_point(rundir, f"hb{n}", "figures", "Fstar", Fstar, **vals)
        runs[f"from Hopf F* = {Fstar:.4f}"] = dg.run(
            rundir, f"po_hb{n}", "periodic", data=hb, ICP=icp, UZSTOP={"Fstar": list(FSTAR_RANGE)},
            DS=1e-4, DSMAX=0.02, DSMIN=1e-9, NMX=4000, THU=mg.THU)
        mg.progress("bistable_v50", f"orbits from the Hopf point at F* = {Fstar:.4f}")
    diagram = mg.diagram_in_V(rundir, "y1", "ratio", YFP, uzr=(V,), figure="bistable_v50")
    (run, lab), = mg.stable_orbits(diagram, V)
    for d, ds in (("down", -1e-3), ("up", 1e-3)):
        runs[f"stable orbit of F* = 1, {d}"] = dg.run(
            rundir, f"orbit_{d}", "periodic", data=run(lab), ICP=icp,
            UZSTOP={"Fstar": list(FSTAR_RANGE)}, DS=ds, DSMAX=0.02, DSMIN=1e-9, NMX=4000,
            THU=mg.THU)
        mg.progress("bistable_v50", f"stable orbit at F* = 1 continued {d} in F*")
    return changes, runs


def stable_rolling(changes):
    """F* intervals of stable straight rolling, from the stability changes."""
    edges = [FSTAR_RANGE[0]] + [F for F, _, _ in changes] + [FSTAR_RANGE[1]]
    start_stable = max(mg.growth(FSTAR_RANGE[0], YFP, V, "ratio").values()) < 0
    return [(lo, hi) for k, (lo, hi) in enumerate(zip(edges[:-1], edges[1:]))
            if (k % 2 == 0) == start_stable]


def stable_orbit_intervals(runs):
    """F* intervals covered by stable orbits, merged over the runs:
    {"low": [...], "high": [...]} by frequency (magnitude.BANDS)."""
    pieces = {"low": [], "high": []}
    for run in runs.values():
        for branch in run:
            for xs, fs, stable in dg.segments(branch, "Fstar", "freq"):
                if stable:
                    band = "low" if numpy.mean(fs) <= mg.BANDS["low"][1] else "high"
                    pieces[band].append((float(min(xs)), float(max(xs))))
    return {band: merge(found) for band, found in pieces.items()}


def merge(intervals):
    out = []
    for lo, hi in sorted(intervals):
        if out and lo <= out[-1][1] + 1e-9:
            out[-1] = (out[-1][0], max(out[-1][1], hi))
        else:
            out.append((lo, hi))
    return out


def main():
    try:
        changes, runs = compute()
    except (autoglue.RunError, ValueError, RuntimeError) as exc:
        sys.exit(f"bistable_v50: {exc}")
    rolling = stable_rolling(changes)
    orbits = stable_orbit_intervals(runs)
    both = [(max(r[0], o[0]), min(r[1], o[1])) for r in rolling for o in orbits["high"]
            if max(r[0], o[0]) < min(r[1], o[1])]
    rows = [("stability changes of straight rolling in F* (V = 50)",
             ", ".join(f"{F:.4f} {k}" for F, k, _ in changes), "2 pitchforks, then Hopf")]
    rows += [("straight rolling stable for F* in", ", ".join(f"({lo:.4f}, {hi:.4f})"
                                                           for lo, hi in rolling), None)]
    rows += [(f"stable {band}-frequency orbits for F* in",
              ", ".join(f"({lo:.4f}, {hi:.4f})" for lo, hi in found), None)
             for band, found in orbits.items()]
    rows += [("(a_12, b_12): stable straight rolling and stable high-frequency shimmy",
              ", ".join(f"({lo:.4f}, {hi:.4f})" for lo, hi in both) or "empty", "not printed")]
    mg.write_numbers("bistable_v50", rows)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for run in runs.values():
        dg.plot_branch(axes[0], run, "Fstar", "psi_amp", scale=numpy.degrees(1.0))
        dg.plot_branch(axes[1], run, "Fstar", "freq")
    for lo, hi in rolling:
        axes[0].plot([lo, hi], [0, 0], color=dg.STABLE, lw=3)
    for lo, hi in both:
        for ax in axes:
            ax.axvspan(lo, hi, color="tab:cyan", alpha=0.3)
    axes[0].set(xlabel="$F_z^*$", ylabel=r"$\psi$ amplitude [deg]")
    axes[1].set(xlabel="$F_z^*$", ylabel="frequency [Hz]")
    fig.suptitle(r"V = 50 m/s, $y_{fp}$ = 1 mm, $\epsilon$ = 0.1 $y_{fp}$: shaded ($a_{12}$, $b_{12}$); "
                 "thick: stable straight rolling")
    fig.tight_layout()
    dg.save(fig, "bistable_v50")


if __name__ == "__main__":
    main()
