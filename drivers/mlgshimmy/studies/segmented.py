"""Fig. 10 in the non-smooth limit: the periodic orbits of eq. (14) as
segmented boundary-value problems in AUTO (shared.segmented,
models/mlg_segmented.c), beside the smoothed eq. (15) at eps = 0.1 y_fp.
F* = 1, y_fp = 1 mm.

- Straight rolling lies in the gap, where eq. (14) is smooth: its Hopf
  points and stability by the eigenvalue scan (naming.scanned, spectrum).
- The high-frequency orbits: started from an event-located simulation at
  START (its last period gives the modes gap, contact+, gap, contact- and
  their durations), continued in V both ways: up to V_MAX, and down
  through the fold S and back along the unstable orbits to where the
  contact segments' durations reach zero (the grazing).  Stability from
  the monodromy, the product of the segments' (segmented.stability), at
  every saved solution.
- The check: at CHECKS on the stable branch, the psi amplitude and the
  frequency of AUTO's orbit against an independent event-located
  simulation from psi = 0.01 rad, within TOLERANCE (relative).

    make segmented          # compute (about 7 min), the table and the figure
    make segmented-plot     # redraw from the cache
"""
import numpy

from mlgshimmy.shared import branches, gear, jobs, mlgmodel, naming, paths, segmented
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import simulator, spectrum

DECLARED = {
    "segmented": {
        "help": "Fig. 10 under eq. (14): segmented AUTO orbits, grazing, checked by simulation",
        "time": "7 min",
        "report": {
            "command": "make segmented",
            "text": ("Fig. 10's diagram in the non-smooth limit (eq. 14): periodic orbits as "
                     "segmented boundary-value problems (one segment per mode, durations "
                     "unknown), their fold and grazing, checked against the event-located "
                     "simulation, beside eq. (15) at eps = 0.1 y_fp."),
            "tables": ["tables/segmented.txt"],
            "figures": ["figures/segmented.png"],
        },
    },
}
FIGURE = "segmented"
CASE = {"Fstar": 1.0, "yfp": 1.0, "eps_abs": 0.0, "eps_rel": 0.0}   # eq. (14) has no eps
SMOOTHED = {"Fstar": 1.0, "yfp": 1.0, "eps_abs": 0.0, "eps_rel": 0.1}
START = 100.0                   # m/s: the simulated orbit the branch starts from
CHECKS = (50.0, 80.0, 150.0, 300.0, 500.0)   # m/s, on the stable high-frequency branch
TOLERANCE = 1e-4                # relative, AUTO against simulation
# the check's simulation: 40 s from psi = 0.01 rad, the last second sampled every
# 10 us (the amplitude's sampling error below 3e-7 at 45 Hz)
CHECK_RUN = ("--t-end", 40, "--dt-out", 1e-5, "--psi0", 0.01, *segmented.TOLERANCES)
COLUMNS = ("V", "psi_amp", "freq")


def stability_mask(bd, branch, n, model):
    """(stable per point of the first n, [(V, kind)] of its changes): the
    monodromy's verdict at every saved solution, a change placed at the
    fold (LP) between two verdicts that differ, else midway, its kind from
    the multiplier that left the unit circle (TR: a complex pair, PD: -1)."""
    saved = [(i, lab, ty) for i, lab, ty in branches.labelled_points(branch) if i < n]
    verdicts = []
    for i, lab, ty in saved:
        if ty == "LP":
            continue      # a multiplier at 1: no verdict
        solution = bd(lab)
        verdicts.append((i, segmented.stability(model.set(V=solution["V"]), solution)))
    folds = [i for i, _, ty in saved if ty == "LP"]
    mask = numpy.zeros(n, dtype=bool)
    changes = []
    for (a, sa), (b, sb) in zip(verdicts, verdicts[1:]):
        mask[a:b] = sa["stable"]
        if sa["stable"] == sb["stable"]:
            continue
        at = next((f for f in folds if a < f < b), None)
        if at is not None:
            mask[at:b] = sb["stable"]
            continue
        mask[(a + b) // 2:b] = sb["stable"]
        unstable = sb if sa["stable"] else sa
        mu = unstable["multipliers"]
        outside = mu[abs(mu) > 1.0]
        kind = "TR" if abs(outside.imag).max() > 1e-6 else "PD" if outside.real.min() < 0 \
            else "LP"
        changes.append((float(0.5 * (branch["V"][a] + branch["V"][b])), kind,
                        float(branch["V"][a]), float(branch["V"][b])))
    if verdicts:
        mask[verdicts[-1][0]:] = verdicts[-1][1]["stable"]
        mask[:verdicts[0][0]] = verdicts[0][1]["stable"]
    return mask, changes


def orbit_branches(rundir, values, orbit):
    """The segmented orbits through `orbit` at START, up and down in V:
    stored branches, folds, grazings, stability changes and the checked
    solutions at CHECKS."""
    model = mlgmodel.Model("figures", **segmented.law14(values))
    out = {"branches": [], "folds": [], "grazings": [], "changes": [], "at": []}
    for name, ds, stop in (("up", 0.5, {"V": ct.V_MAX}), ("down", -0.5, {"V": ct.V_MIN})):
        bd = segmented.follow(rundir, name, values, orbit, START, stop=stop, DS=ds,
                              at=[v for v in CHECKS if (v - START) * ds > 0])
        for branch in bd:
            n = segmented.physical(branch, orbit["modes"])
            mask, changes = stability_mask(bd, branch, n, model)
            out["branches"].append({
                "columns": {c: numpy.asarray(branch[c])[:n] for c in COLUMNS},
                "stable": mask, "labels": []})
            out["changes"] += changes
            for i, lab, ty in branches.labelled_points(branch):
                point = bd(lab)
                if ty == "LP" and i < n:
                    out["folds"].append({c: point[c] for c in COLUMNS})
                if ty == "UZ" and i < n and mask[i]:
                    out["at"].append({"V": point["V"],
                                      "psi_amp": segmented.amplitude(point),
                                      "freq": 1.0 / segmented.period(point)})
            out["grazings"] += segmented.grazings([branch], COLUMNS)
    return out


def _sorted(xs, ys):
    order = numpy.argsort(xs)
    return numpy.asarray(xs)[order], numpy.asarray(ys)[order]


def check(values, solutions):
    """The solutions at CHECKS against the event-located simulation there:
    [{V, AUTO's and the simulation's psi amplitude and frequency, relative
    errors}]."""
    rows = []
    for point in sorted(solutions, key=lambda p: p["V"]):
        sim = simulator.simulate(None, "--set", "figures", "--V", point["V"], *CHECK_RUN,
                                 params=segmented.law14(values))
        rows.append({"V": point["V"], "amp_auto": point["psi_amp"],
                     "amp_sim": sim["psi_amplitude_rad"], "freq_auto": point["freq"],
                     "freq_sim": sim["frequency_hz"],
                     "amp_rel": point["psi_amp"] / sim["psi_amplitude_rad"] - 1.0,
                     "freq_rel": point["freq"] / sim["frequency_hz"] - 1.0})
        print(f"segmented: V = {point['V']:g} m/s: psi amplitude {point['psi_amp']:.10e} "
              f"(simulation {sim['psi_amplitude_rad']:.10e}), frequency {point['freq']:.8f} "
              f"Hz (simulation {sim['frequency_hz']:.8f})", flush=True)
    return rows


def rolling(values):
    """Straight rolling of eq. (14): its Hopf points by name and the speeds
    where it is stable."""
    law = segmented.law14(values)
    hopf = naming.scanned("figures", "V", ct.SPEED_SCAN, **law)
    changes = [v for v, _, _ in spectrum.stability_changes("figures", "V", ct.SPEED_SCAN, **law)]
    return {"hopf": hopf, "stable": spectrum.stable_intervals("figures", "V", changes, ct.V_MIN,
                                                              ct.V_MAX, **law)}


def compute():
    at = gear.parameters()
    values = {**at, **CASE}
    rundir = paths.rundir(FIGURE)
    print(f"segmented: the orbit of eq. (14) at V = {START:g} m/s by simulation", flush=True)
    orbit = segmented.simulated(values, START)
    print("segmented: modes " + ", ".join(segmented.MODE_NAMES[m] for m in orbit["modes"])
          + ", durations " + ", ".join(f"{T:.6e}" for T in orbit["durations"]) + " s",
          flush=True)
    orbits = orbit_branches(rundir, values, orbit)
    rows = check(values, orbits.pop("at"))
    print("segmented: eq. (15) at eps = 0.1 y_fp, for the overlay", flush=True)
    smooth = ct.speed_diagram(paths.rundir(f"{FIGURE}/smoothed"), "figures", {**at, **SMOOTHED},
                              figure=FIGURE, **ct.SPEED_ORBIT_STEPS)
    return {"orbits": orbits, "check": rows, "rolling": rolling(values),
            "modes": [segmented.MODE_NAMES[m] for m in orbit["modes"]],
            "smoothed": [jobs.stored(run, COLUMNS) for _, run in smooth.parts],
            "smoothed_hopf": smooth.hopf}


def text(result) -> str:
    orbits = result["orbits"]
    lines = ["segmented: Fig. 10 (F* = 1, y_fp = 1 mm) under eq. (14), segments "
             + ", ".join(result["modes"]), ""]
    lines += [f"  {name} = {v:.6f} m/s (straight rolling, eigenvalue scan)"
              for name, v in result["rolling"]["hopf"].items()]
    lines += [f"  S = {p['V']:.6f} m/s (fold of the segmented orbits, psi amplitude "
              f"{p['psi_amp']:.6e} rad)" for p in orbits["folds"]]
    lines += [f"  grazing at V = {g['V']:.6f} m/s (the duration of segment"
              f"{'s' if len(g['segments']) > 1 else ''} "
              f"{', '.join(map(str, g['segments']))} reaches 0)" for g in orbits["grazings"]]
    lines += [f"  stability change ({kind}) between V = {a:.3f} and {b:.3f} m/s"
              for _, kind, a, b in orbits["changes"]]
    lines += ["", f"  the stable orbit against the event-located simulation (tolerance "
              f"{TOLERANCE:g} relative):",
              "  V [m/s]  psi amp AUTO [rad]  psi amp sim. [rad]  rel.      "
              "freq AUTO [Hz]  freq sim. [Hz]  rel."]
    for r in result["check"]:
        lines.append(f"  {r['V']:<7g}  {r['amp_auto']:.10e}    {r['amp_sim']:.10e}    "
                     f"{r['amp_rel']:+.2e} {r['freq_auto']:.8f}     {r['freq_sim']:.8f}     "
                     f"{r['freq_rel']:+.2e}")
    return "\n".join(lines) + "\n"


def plot(result):
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from mlgshimmy.shared import draw

    table = text(result)
    jobs.write_text(f"{paths.tables_dir()}/{FIGURE}.txt", table)
    print(table, end="")
    orbits = result["orbits"]
    ours = jobs.loaded(orbits["branches"])
    smoothed = [jobs.loaded(run) for run in result["smoothed"]]
    fig = plt.figure(figsize=(10, 7.4))
    grid = fig.add_gridspec(2, 2, width_ratios=(1.6, 1))
    amp, zoom, freq = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1]), \
        fig.add_subplot(grid[1, :])
    stable = result["rolling"]["stable"]
    edges = sorted({ct.V_MIN, ct.V_MAX, *[v for ab in stable for v in ab],
                    *result["rolling"]["hopf"].values()})
    for ax, column, scale in ((amp, "psi_amp", draw.DEG), (zoom, "psi_amp", draw.DEG),
                              (freq, "freq", 1.0)):
        for runs in smoothed:
            draw.plot_branch(ax, runs, "V", column, scale=scale, color=draw.palette.GUIDE)
        draw.plot_branch(ax, ours, "V", column, scale=scale)
        if column == "psi_amp":
            for a, b in zip(edges, edges[1:]):
                ok = any(lo <= 0.5 * (a + b) <= hi for lo, hi in stable)
                ax.plot([a, b], [0, 0], **draw.style_of(ok))
        for k, p in enumerate(orbits["folds"]):
            draw.mark(ax, p["V"], p[column] * scale, "LP", name=f"S{k + 1}" if k else "S")
        for g in orbits["grazings"]:
            draw.mark(ax, g["V"], g[column] * scale, "GR")
        for V, kind, _, _ in orbits["changes"]:
            y = numpy.interp(V, *_sorted(numpy.concatenate([b["V"] for b in ours]),
                                         numpy.concatenate([b[column] for b in ours])))
            draw.mark(ax, V, y * scale, kind)
        if column == "psi_amp":
            for name, V in result["rolling"]["hopf"].items():
                draw.mark(ax, V, 0.0, "HB", name=name)
        ax.set_xlabel("V [m/s]")
    for r in result["check"]:
        amp.plot(r["V"], r["amp_sim"] * draw.DEG, "x", color=draw.palette.MARKER, ms=6)
        freq.plot(r["V"], r["freq_sim"], "x", color=draw.palette.MARKER, ms=6)
    for ax in (amp, zoom):
        ax.set_ylabel(r"$\psi$ amplitude [deg]")
    amp.set_xlim(0, ct.V_MAX)
    amp.set_title("(a1) torsional amplitude")
    zoom.set_xlim(0, 160)
    zoom.set_ylim(-0.01, 0.3)
    zoom.set_title("(a2) zoom of (a1)")
    freq.set_xlim(0, ct.V_MAX)
    freq.set_ylabel("frequency [Hz]")
    freq.set_title("(b) frequency")
    extra = [Line2D([], [], color=draw.palette.GUIDE,
                    label=r"eq. (15), $\epsilon$ = 0.1 $y_{fp}$ (stable solid, unstable dashed)"),
             Line2D([], [], ls="", marker="x", color=draw.palette.MARKER,
                    label="event-located simulation")]
    draw.legend(freq, extra=extra, axes=(amp, zoom, freq), loc="lower right", ncol=2)
    draw.figure_title(fig, r"Fig. 10 under eq. (14): $F_z^*$ = 1, $y_{fp}$ = 1 mm, "
                      "segmented orbits")
    fig.tight_layout()
    draw.save(fig, FIGURE)


if __name__ == "__main__":
    jobs.run_figure(FIGURE, compute, plot, module="mlgshimmy.studies.segmented")
