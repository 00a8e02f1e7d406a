"""Fig. 10 in the non-smooth limit: the periodic orbits of eq. (14) as
segmented boundary-value problems in AUTO (shared.segmented,
models/mlg_segmented.c), beside the smoothed eq. (15) at eps = 0.1 y_fp.
F* = 1, y_fp = 1 mm.

- Straight rolling lies in the gap, where eq. (14) is smooth: its Hopf
  points and stability by the eigenvalue scan (naming.scanned, spectrum).
- Each family of orbits (FAMILIES: high and low frequency) from an
  event-located simulation at its start speed (its last period gives the
  modes, gap, contact+, gap, contact-, and their durations), continued in
  V both ways until a contact segment's duration reaches zero (a
  grazing) or V leaves [V_MIN, V_MAX]: the high-frequency orbits up to
  600 m/s, and down through the fold S and back, unstable, to their
  grazing.  Stability from the monodromy, the product of the segments'
  (segmented.stability), at every saved solution.
- The check: at each family's check speeds, on its stable part, the psi
  amplitude and the frequency of AUTO's orbit against an independent
  event-located simulation from psi = 0.01 rad, within TOLERANCE.

    make segmented          # compute (about 7 min), the table and the figure
    make segmented-plot     # redraw from the cache
"""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Sequence, Tuple

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
# each family of orbits: the speed of the simulated orbit it starts from,
# and the speeds of the check, on its stable part [m/s]
FAMILIES = {"high-frequency": {"start": 100.0, "checks": (50.0, 80.0, 150.0, 300.0, 500.0)},
            "low-frequency": {"start": 15.0, "checks": (7.0, 10.0, 13.0, 18.0, 24.0)}}
TOLERANCE = 1e-4                # relative, AUTO against simulation
AT_SPEED = 1e-3                 # m/s: AUTO's UZ at a check speed lies this close (the
                                # simulation runs at its own V)
MARGINAL = 1e-5                 # |mu| - 1 of a multiplier at a fold (or a run's start there)
# the check's simulation: 40 s from psi = 0.01 rad, the last second sampled every
# 10 us (the amplitude's sampling error below 3e-7 at 45 Hz)
CHECK_RUN = ("--t-end", 40, "--dt-out", 1e-5, "--psi0", 0.01, *segmented.TOLERANCES)
COLUMNS = ("V", "psi_amp", "freq")
ZOOM_V = 160.0                  # m/s: panel (a2)'s range


def stability_mask(bd: Any, branch: Any,
                   model: Any) -> Tuple[numpy.ndarray, List[Tuple[float, str, float, float]]]:
    """(stable per point, [(V, kind, V before, V after)] of its changes): the
    monodromy's verdict at every saved solution, a change placed at the
    fold (LP) between two verdicts that differ, else midway, its kind from
    the multiplier that left the unit circle (TR: a complex pair, PD: -1)."""
    saved = branches.labelled_points(branch)
    verdicts = []
    for i, lab, ty in saved:
        solution = bd(lab)
        verdict = segmented.stability(model.set(V=solution["V"]), solution)
        if ty != "LP" and abs(verdict["largest"] - 1.0) > MARGINAL:   # not at a fold
            verdicts.append((i, verdict))
    folds = [i for i, _, ty in saved if ty == "LP"]
    mask = numpy.zeros(len(branch), dtype=bool)
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
        # a real multiplier through +1 away from a fold: a symmetric orbit's pitchfork
        kind = "TR" if abs(outside.imag).max() > 1e-6 else "PD" if outside.real.min() < 0 \
            else "BP"
        changes.append((float(0.5 * (branch["V"][a] + branch["V"][b])), kind,
                        float(branch["V"][a]), float(branch["V"][b])))
    if verdicts:
        mask[verdicts[-1][0]:] = verdicts[-1][1]["stable"]
        mask[:verdicts[0][0]] = verdicts[0][1]["stable"]
    return mask, changes


def orbit_branches(rundir: str, family: str, values: Mapping[str, float]) -> Dict[str, Any]:
    """One family of orbits (FAMILIES), from its simulated orbit up and down
    in V: its modes, stored branches, folds, grazings, stability changes and
    the solutions at its check speeds."""
    start, checks = FAMILIES[family]["start"], FAMILIES[family]["checks"]
    print(f"segmented: {family} orbit of eq. (14) at V = {start:g} m/s by simulation",
          flush=True)
    orbit = segmented.simulated(values, start)
    print("segmented: modes " + ", ".join(segmented.MODE_NAMES[m] for m in orbit["modes"])
          + ", durations " + ", ".join(f"{T:.6e}" for T in orbit["durations"]) + " s",
          flush=True)
    model = mlgmodel.Model("figures", **segmented.law14(values))
    out = {"modes": [segmented.MODE_NAMES[m] for m in orbit["modes"]], "branches": [],
           "folds": [], "grazings": [], "changes": [], "at": []}
    for name, ds, stop in (("up", 0.5, {"V": ct.V_MAX}), ("down", -0.5, {"V": ct.V_MIN})):
        for bd in segmented.follow(rundir, f"{family}-{name}", values, orbit, start, stop=stop,
                                   DS=ds, at=[v for v in checks if (v - start) * ds > 0]):
            for branch in bd:
                mask, changes = stability_mask(bd, branch, model)
                out["branches"].append({"columns": {c: numpy.asarray(branch[c]) for c in COLUMNS},
                                        "stable": mask, "labels": []})
                out["changes"] += changes
                for i, lab, ty in branches.labelled_points(branch):
                    point = bd(lab)
                    grazed = segmented.grazing(point, orbit["modes"])
                    if ty == "LP" or (ty == "UZ" and grazed):
                        out["grazings" if grazed else "folds"].append(
                            {"segments": grazed, **{c: point[c] for c in COLUMNS}})
                    checked = any(abs(point["V"] - v) < AT_SPEED for v in checks)
                    if ty == "UZ" and mask[i] and checked:
                        out["at"].append({"V": point["V"],
                                          "psi_amp": segmented.amplitude(point),
                                          "freq": 1.0 / segmented.period(point)})
    return out


def _sorted(xs, ys):
    order = numpy.argsort(xs)
    return numpy.asarray(xs)[order], numpy.asarray(ys)[order]


def check(values: Mapping[str, float],
          solutions: Sequence[Mapping[str, Any]]) -> List[Dict[str, Any]]:
    """The solutions (at the check speeds) against the event-located
    simulation there:
    [{V, AUTO's and the simulation's psi amplitude and frequency, relative
    errors}]."""
    rows = []
    for point in sorted(solutions, key=lambda p: p["V"]):
        sim = simulator.simulate(None, "--set", "figures", "--V", point["V"], *CHECK_RUN,
                                 params=segmented.law14(values))
        rows.append({"family": point["family"], "V": point["V"], "amp_auto": point["psi_amp"],
                     "amp_sim": sim["psi_amplitude_rad"], "freq_auto": point["freq"],
                     "freq_sim": sim["frequency_hz"],
                     "amp_rel": point["psi_amp"] / sim["psi_amplitude_rad"] - 1.0,
                     "freq_rel": point["freq"] / sim["frequency_hz"] - 1.0})
        print(f"segmented: V = {point['V']:g} m/s: psi amplitude {point['psi_amp']:.10e} "
              f"(simulation {sim['psi_amplitude_rad']:.10e}), frequency {point['freq']:.8f} "
              f"Hz (simulation {sim['frequency_hz']:.8f})", flush=True)
    return rows


def rolling(values: Mapping[str, float]) -> Dict[str, Any]:
    """Straight rolling of eq. (14): its Hopf points by name and the speeds
    where it is stable."""
    law = segmented.law14(values)
    hopf = naming.scanned("figures", "V", ct.SPEED_SCAN, **law)
    changes = [v for v, _, _ in spectrum.stability_changes("figures", "V", ct.SPEED_SCAN, **law)]
    return {"hopf": hopf, "stable": spectrum.stable_intervals("figures", "V", changes, ct.V_MIN,
                                                              ct.V_MAX, **law)}


def compute() -> Dict[str, Any]:
    at = gear.parameters()
    values = {**at, **CASE}
    rundir = paths.rundir(FIGURE)
    families = {family: orbit_branches(rundir, family, values) for family in FAMILIES}
    rows = check(values, [{**p, "family": f} for f, o in families.items() for p in o.pop("at")])
    print("segmented: eq. (15) at eps = 0.1 y_fp, for the overlay", flush=True)
    smooth = ct.speed_diagram(paths.rundir(f"{FIGURE}/smoothed"), "figures", {**at, **SMOOTHED},
                              figure=FIGURE, **ct.SPEED_ORBIT_STEPS)
    return {"families": families, "check": rows, "rolling": rolling(values),
            "smoothed": [jobs.stored(run, COLUMNS) for _, run in smooth.parts],
            "smoothed_hopf": smooth.hopf}


def text(result: Mapping[str, Any]) -> str:
    lines = ["segmented: Fig. 10 (F* = 1, y_fp = 1 mm) under eq. (14)", ""]
    lines += [f"  {name} = {v:.6f} m/s (straight rolling, eigenvalue scan)"
              for name, v in result["rolling"]["hopf"].items()]
    for family, orbits in result["families"].items():
        lines += ["", f"  {family} orbits, segments " + ", ".join(orbits["modes"]) + ":"]
        lines += [f"  S = {p['V']:.6f} m/s (fold, psi amplitude {p['psi_amp']:.6e} rad)"
                  for p in orbits["folds"]]
        lines += [f"  grazing at V = {g['V']:.6f} m/s (the duration of segment"
                  f"{'s' if len(g['segments']) > 1 else ''} "
                  f"{', '.join(map(str, g['segments']))} reaches 0)"
                  for g in orbits["grazings"]]
        lines += [f"  stability change ({kind}) between V = {a:.3f} and {b:.3f} m/s"
                  for _, kind, a, b in orbits["changes"]]
    lines += ["", f"  the stable orbits against the event-located simulation (tolerance "
              f"{TOLERANCE:g} relative):",
              "  orbits          V [m/s]  psi amp AUTO [rad]  psi amp sim. [rad]  rel.      "
              "freq AUTO [Hz]  freq sim. [Hz]  rel."]
    for r in result["check"]:
        lines.append(f"  {r['family']:<14}  {r['V']:<7g}  {r['amp_auto']:.10e}    "
                     f"{r['amp_sim']:.10e}    {r['amp_rel']:+.2e} {r['freq_auto']:.8f}     "
                     f"{r['freq_sim']:.8f}     {r['freq_rel']:+.2e}")
    return "\n".join(lines) + "\n"


def plot(result: Mapping[str, Any]) -> None:
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from mlgshimmy.shared import draw

    table = text(result)
    jobs.write_text(f"{paths.tables_dir()}/{FIGURE}.txt", table)
    print(table, end="")
    families = result["families"].values()
    ours = [jobs.loaded(orbits["branches"]) for orbits in families]
    folds = [p for orbits in families for p in orbits["folds"]]
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
        for branch in ours:
            draw.plot_branch(ax, branch, "V", column, scale=scale)
        if column == "psi_amp":
            for a, b in zip(edges, edges[1:]):
                ok = any(lo <= 0.5 * (a + b) <= hi for lo, hi in stable)
                ax.plot([a, b], [0, 0], **draw.style_of(ok))
        for k, p in enumerate(folds):
            draw.mark(ax, p["V"], p[column] * scale, "LP", name=f"S{k + 1}" if k else "S")
        for orbits, branch in zip(families, ours):
            # in (a1) the points below the zoom's 160 m/s are left to the zoom
            low = ZOOM_V if ax is amp else 0.0
            for g in orbits["grazings"]:
                if g["V"] > low:
                    draw.mark(ax, g["V"], g[column] * scale, "GR")
            for V, kind, _, _ in [c for c in orbits["changes"] if c[0] > low]:
                y = numpy.interp(V, *_sorted(numpy.concatenate([b["V"] for b in branch]),
                                             numpy.concatenate([b[column] for b in branch])))
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
    zoom.set_xlim(0, ZOOM_V)
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
