"""Fig. 14 at several fixed smoothing widths eps and in the non-smooth limit
eq. (14) (docs/model.md 9.3), F* = 1: the Hopf curves of straight rolling
in (y_fp, V) and the stable orbit at V = ORBIT_SPEED continued in y_fp, one
colour per eps, with eq. (14)'s Hopf speeds and simulated orbits.

A law of one shape depends on y_fp and eps only through eps / y_fp in its
Hopf points (docs/model.md 9.4), so the curves of a smaller eps are those
of a larger one moved to smaller y_fp; eq. (14) has no eps, its Hopf
speeds do not depend on y_fp at all, and its orbits scale with y_fp.

    make smoothing_fig14          # compute (a few minutes) and draw
    make smoothing_fig14-plot     # redraw from the cache
"""
from __future__ import annotations

from typing import Any, Dict, Mapping, Optional, Tuple

import numpy

from mlgshimmy.shared import gear, jobs, mlgmodel, naming, paths, simulator
from mlgshimmy.shared import runerror, yfp_runs, yfp_stored

DECLARED = {
    "smoothing_fig14": {
        "help": "Fig. 14's Hopf curves and orbits at several eps and with eq. (14)",
        "time": "5 min",
        "report": {
            "command": "make smoothing_fig14",
            "text": ("Fig. 14 (eps fixed in mm) at eps = 1, 0.2, 0.1 and 0.02 mm and with the "
                     "non-smooth eq. (14): Hopf curves in (y_fp, V) and the orbit at 50 m/s "
                     "continued in y_fp."),
            "tables": [],
            "figures": ["figures/smoothing_fig14.png"],
        },
    },
}
FIGURE = "smoothing_fig14"
WIDTHS = (1.0, 0.2, 0.1, 0.02)        # eps [mm]
ORBIT_SPEED = 50.0                    # m/s: one of Fig. 14's orbit speeds
# eq. (14)'s orbits simulated at these freeplays [mm] (shared.simulator)
LIMIT_FREEPLAYS = (0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0)
# as studies.smoothing, from psi = 0.01 rad per mm of freeplay (about five
# times the freeplay angle y_fp / r_tlk)
SIMULATION = ("--t-end", 16, "--dt-out", 1e-5, "--rtol", 1e-10, "--atol", 1e-12)


def seeds(eps: float) -> Tuple[float, ...]:
    """Fig. 14's seed freeplays (1 and 0.15 mm at eps = 0.1 mm) at the same
    eps / y_fp, within the curves' range."""
    return tuple(min(yfp_runs.YFP_MAX, y * eps / 0.1) for y in (1.0, 0.15))


def orbit_curve(rundir: str, eps: float, model: Mapping[str, Any]) -> Optional[Dict[str, list]]:
    """The stable orbit at ORBIT_SPEED of the diagram at the larger seed
    freeplay, continued in y_fp (stored as yfp_stored.stored_orbits does);
    None if that diagram has no stable orbit there."""
    yfp = seeds(eps)[0]
    d = yfp_runs.diagram_in_V(rundir, "d", "fixed", yfp, uzr=(ORBIT_SPEED,), figure=FIGURE,
                        eps_abs=eps, **model)
    found = yfp_runs.stable_orbits(d, ORBIT_SPEED)
    if not found:
        print(f"{FIGURE}: eps = {eps:g} mm: no stable orbit at {ORBIT_SPEED:g} m/s "
              f"(y_fp = {yfp:g} mm)")
        return None
    run, lab = max(found, key=lambda f: f[0](f[1])["psi_amp"])
    runs = yfp_runs.orbit_in_yfp(rundir, "orbit", run(lab), "fixed", ORBIT_SPEED, FIGURE,
                           eps_abs=eps, **model)
    return yfp_stored.stored_orbits({ORBIT_SPEED: runs})[0][1]


def compute() -> Dict[str, Any]:
    model = gear.parameters()
    out = {"widths": {}}
    for eps in WIDTHS:
        rundir = paths.rundir(f"{FIGURE}/eps{eps:g}")
        try:
            curves = yfp_runs.hopf_curves(rundir, "hopf", "fixed", seeds=seeds(eps), figure=FIGURE,
                                    eps_abs=eps, **model)
        except runerror.RunError as exc:   # the figure keeps the other widths
            print(f"{FIGURE}: eps = {eps:g} mm: the Hopf curves stop: {exc.brief}")
            curves = []
        try:
            orbit = orbit_curve(rundir, eps, model)
        except runerror.RunError as exc:
            print(f"{FIGURE}: eps = {eps:g} mm: the orbit in y_fp stops: {exc.brief}")
            orbit = None
        out["widths"][f"{eps:g}"] = {"hopf_curves": yfp_stored.stored_curves(curves, ("yfp", "V")),
                                     "orbit": orbit}
    law14 = {**model, "Fstar": yfp_runs.FSTAR, "eps_abs": 0.0, "eps_rel": 0.0,
             "freeplay_law": mlgmodel.LAWS.index("nonsmooth")}
    out["limit_hopf"] = naming.scanned("figures", "V", yfp_runs.V_SCAN, **law14, yfp=1.0)
    out["limit_orbits"] = [
        (y, simulator.simulate(None, "--V", ORBIT_SPEED, "--psi0", 0.01 * y, *SIMULATION,
                               params={**law14, "yfp": y})["psi_amplitude_rad"])
        for y in LIMIT_FREEPLAYS]
    return out


def plot(result: Mapping[str, Any]) -> None:
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from mlgshimmy.shared import draw

    fig, (ax_orbit, ax_hopf) = plt.subplots(1, 2, figsize=(12, 5))
    widths = result["widths"]
    colours = dict(zip(widths, draw.sequence(len(widths))))
    handles = []
    for eps, data in widths.items():
        for curve in data["hopf_curves"]:
            ax_hopf.plot(curve["yfp"], curve["V"], color=colours[eps], lw=1.3)
        if data["orbit"]:
            o = data["orbit"]
            draw.plot_stability(ax_orbit, o["yfp"], numpy.asarray(o["psi_amp"]) * draw.DEG,
                                o["stable"], color=colours[eps])
        handles.append(Line2D([], [], color=colours[eps], lw=1.3,
                              label=rf"$\epsilon$ = {eps} mm"))
    for name, V in result["limit_hopf"].items():
        ax_hopf.axhline(V, color=draw.palette.NEUTRAL, ls=":", lw=1.0)
        ax_hopf.annotate(f"{name} (eq. 14)", (yfp_runs.YFP_MAX, V), xytext=(-4, 3),
                         textcoords="offset points", ha="right", fontsize=7)
    limit_style = {"ls": "", "marker": "D", "ms": 4.5, "mfc": draw.palette.OPEN,
                   "mec": draw.palette.NEUTRAL, "zorder": 6}
    ys, amps = zip(*result["limit_orbits"])
    ax_orbit.plot(ys, numpy.asarray(amps) * draw.DEG, **limit_style)
    handles += [Line2D([], [], label="eq. (14), simulated (switches located)", **limit_style),
                Line2D([], [], color=draw.palette.NEUTRAL, ls=":", lw=1.0,
                       label="eq. (14): Hopf speeds, every $y_{fp}$ > 0")]
    ax_orbit.set(xscale="log", yscale="log", xlim=(yfp_runs.YFP_MIN, yfp_runs.YFP_MAX), xlabel="$y_{fp}$ [mm]",
                 ylabel=r"$\psi$ amplitude [deg]",
                 title=f"(a) the stable orbit at V = {ORBIT_SPEED:g} m/s "
                       "continued in $y_{fp}$")
    ax_hopf.set(xscale="log", xlim=(yfp_runs.YFP_MIN, yfp_runs.YFP_MAX), ylim=(0, yfp_runs.V_MAX),
                xlabel="$y_{fp}$ [mm]", ylabel="V [m/s]",
                title="(b) Hopf curves of straight rolling in $(y_{fp}, V)$")
    draw.legend(ax_orbit, extra=handles, color=draw.palette.NEUTRAL, loc="lower right")
    draw.figure_title(fig, r"Fig. 14 at several smoothing widths $\epsilon$ and eq. (14): "
                      r"$F^*$ = 1")
    fig.tight_layout()
    draw.save(fig, FIGURE)


if __name__ == "__main__":
    jobs.run_figure(FIGURE, compute, plot, module="mlgshimmy.studies.smoothing_fig14")
