"""Fig. 10: F* = 1 with +-1 mm of torque-link freeplay (epsilon = 0.1 y_fp),
V in [0, 600]: straight rolling and its Hopf points, the low-frequency
orbits between the two low-speed Hopf points, the high-frequency orbits from
the third with their fold S, and the zero-freeplay orbits for reference.
Panels: torsional amplitude (with a zoom on small amplitudes) and frequency."""
import sys

import matplotlib.pyplot as plt
import numpy

import autoglue
import diagrams as dg
import paper_table

DEG = 180 / numpy.pi
V_MAX = 600.0
V_MIN = 0.5          # V = 0 is degenerate (the tyre states are undetermined)
COLLAPSED = 1e-8     # rad: a psi amplitude below this is straight rolling
SAME_FREQUENCY = 0.1  # relative: an orbit this close to a Hopf frequency collapses there


def speed_diagram(rundir, parameter_set="figures", skip_failed=False, **values):
    """Straight rolling in V at the given parameters, its Hopf points (found
    by the eigenvalue scan, located by AUTO), and the periodic orbits born at
    each Hopf point.  An orbit run is stopped just before every other Hopf
    speed: if its frequency there is that Hopf point's (within
    SAME_FREQUENCY), the branch collapses onto straight rolling there and
    that Hopf point starts no branch of its own; otherwise the branch only
    passes that speed and is continued past it as a further part (another
    entry of the result, same Hopf point).  With skip_failed, an orbit run
    ending in MX is reported and kept up to the MX point, and any other
    failed orbit run is reported and left out, instead of raising.
    Returns (equilibria, Hopf speeds, [(hopf point, orbits), ...])."""
    start = dg.Start(parameter_set, V=0.0, **values)
    eq = dg.equilibria(rundir, "eq", start, stop={"V": V_MAX})
    grid = numpy.linspace(V_MIN, V_MAX, 3000)
    hopfs = {v: omega / (2 * numpy.pi) for v, kind, omega
             in dg.stability_changes(parameter_set, "V", grid, **values) if kind == "HB"}
    branches, reached = [], set()
    for k, v in enumerate(hopfs):
        if v in reached:   # the orbits of an earlier branch end here
            continue
        point = dg.hopf_point(rundir, f"hb{k + 1}", parameter_set, "V", v, **values)
        origin, passed = point, {v}
        while origin is not None:
            name = f"po{k + 1}" + (f"_{len(passed) - 1}" if len(passed) > 1 else "")
            stops = [V_MIN, V_MAX] + [w + (0.01 if w < origin["V"] else -0.01)
                                      for w in hopfs if w not in passed]
            try:
                orbits = dg.periodic_from(rundir, name, origin, stop={"V": stops}, DS=0.05,
                                          DSMAX=1.0, NMX=2000, allow_mx=skip_failed)
            except autoglue.RunError as exc:
                if not skip_failed:
                    raise
                print(f"  orbits from {name} at V = {origin['V']:.4f} left out: {exc.brief}")
                break
            print(f"  orbits {name} from V = {origin['V']:.4f}: V in "
                  f"[{min(orbits[0]['V']):.2f}, {max(orbits[0]['V']):.2f}], folds at V = "
                  + (", ".join(f"{p['V']:.3f}" for p in orbits("LP")) or "none"))
            branches.append((point, orbits))
            # the last orbit of non-zero amplitude (an MX run may go on along
            # straight rolling after collapsing onto it at the next Hopf point)
            alive = numpy.flatnonzero(numpy.asarray(orbits[0]["psi_amp"]) > COLLAPSED)
            last = alive[-1] if len(alive) else len(orbits[0]["V"]) - 1
            end, freq = orbits[0]["V"][last], orbits[0]["freq"][last]
            origin = None
            for w in [w for w in hopfs if w not in passed and abs(w - end) < 0.02]:
                if abs(freq - hopfs[w]) <= SAME_FREQUENCY * hopfs[w]:
                    reached.add(w)
                else:
                    passed.add(w)
                    origin = orbits("UZ")[-1]
    return eq, list(hopfs), branches


def compute(parameter_set="figures", where="fig10", zero_freeplay=True):
    rundir = dg.rundir(where)
    print(f"fig10: F* = 1, y_fp = 1 mm, eps = 0.1 mm ({parameter_set} set)")
    freeplay = speed_diagram(rundir, parameter_set, skip_failed=not zero_freeplay,
                             Fstar=1.0, yfp=1.0, eps_rel=0.1)
    if not zero_freeplay:
        return freeplay, None
    print("fig10: zero freeplay, for reference")
    zero = speed_diagram(dg.rundir(f"{where}/zero"), parameter_set, Fstar=1.0, yfp=0.0)
    return freeplay, zero


def numbers(result):
    """The special points of Fig. 10 as {quantity: value}."""
    (eq, hopf, branches), _ = result
    folds = sorted(p["V"] for _, orbits in branches for p in orbits("LP"))
    out = {f"H{k + 1} [m/s]": v for k, v in enumerate(hopf)}
    out.update({f"S{k + 1} [m/s]": v for k, v in enumerate(folds)})
    return out


def plot(result):
    (eq, hopf, branches), (_, _, zero_branches) = result
    fig = plt.figure(figsize=(10, 7))
    grid = fig.add_gridspec(2, 2, width_ratios=(1.6, 1))
    amp, zoom, freq = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1]), \
        fig.add_subplot(grid[1, :])
    for ax in (amp, zoom):
        for _, orbits in zero_branches:
            dg.plot_branch(ax, orbits, "V", "psi_amp", scale=DEG, color="0.5")
        dg.plot_branch(ax, eq, "V", "psi_amp", scale=DEG)
        for point, orbits in branches:
            dg.plot_branch(ax, orbits, "V", "psi_amp", scale=DEG)
            dg.mark_points(ax, orbits, "LP", "V", "psi_amp", scale=DEG, text="S")
        for v in hopf:
            ax.plot(v, 0.0, "ko", ms=3.5)
            ax.annotate("H", (v, 0.0), textcoords="offset points", xytext=(2, 4))
        ax.set_xlabel("V [m/s]")
        ax.set_ylabel(r"$\psi$ amplitude [deg]")
    amp.set_xlim(0, V_MAX)
    amp.set_title("(a) torsional amplitude (grey: zero freeplay)")
    zoom.set_xlim(0, 160)
    zoom.set_ylim(-0.01, 0.3)
    zoom.set_title("(a) zoom: small amplitudes")
    for _, orbits in zero_branches:
        dg.plot_branch(freq, orbits, "V", "freq", color="0.5")
    for point, orbits in branches:
        dg.plot_branch(freq, orbits, "V", "freq")
        freq.plot(point["V"], 1 / point["T"], "ko", ms=3.5)
        dg.mark_points(freq, orbits, "LP", "V", "freq", text="S")
    freq.set_xlim(0, V_MAX)
    freq.set_xlabel("V [m/s]")
    freq.set_ylabel("frequency [Hz]")
    freq.set_title("(b) frequency")
    fig.suptitle(r"Fig. 10: $F_z^*$ = 1, $y_{fp}$ = 1 mm, $\epsilon$ = 0.1 mm "
                 "(solid stable, dashed unstable)")
    fig.tight_layout()
    dg.save(fig, "fig10")


def main():
    try:
        result = compute()
    except (autoglue.RunError, ValueError, RuntimeError) as exc:
        sys.exit(f"fig10: {exc}")
    try:
        table = numbers(compute("table", where="fig10/table", zero_freeplay=False))
    except (autoglue.RunError, RuntimeError) as exc:
        print(f"fig10: the `table` set failed, its column stays empty: {exc}")
        table = {}
    paper_table.report("fig10", numbers(result), table)
    plot(result)


if __name__ == "__main__":
    main()
