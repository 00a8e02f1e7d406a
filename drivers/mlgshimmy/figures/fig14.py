"""Fig. 14: freeplay magnitude at a fixed smoothing width eps = 0.1 mm
(section IV.D.2), F* = 1: (a-f) diagrams in V for y_fp = 0.05, 0.098, 0.11,
0.15, 0.35, 1.0 mm beside their stiffness profiles, (g, h) amplitude and
frequency of the stable orbits at V = 15, 50, 80, 110 m/s continued in y_fp,
with the Hopf curves in (y_fp, V) dot-dashed in (h) and their
codimension-two points (shared.codim2) marked."""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import matplotlib.pyplot as plt
import numpy

from mlgshimmy.shared import draw
from mlgshimmy.shared import freeplay
from mlgshimmy.shared import gear
from mlgshimmy.shared import jobs
from mlgshimmy.shared import yfp_runs
from mlgshimmy.shared import yfp_codim2
from mlgshimmy.shared import yfp_stored
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import paper
from mlgshimmy.shared import paths
from mlgshimmy.shared.draw import magnitude as draw_magnitude

# What make, make help, make submit and the report know of this figure
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "fig14": {
        "help": "Fig. 14: eps = 0.1 mm, y_fp = 0.05-1 mm, Hopf curves",
        "time": "1.5 min",
        "regress": True,
        "parts": True,
        "report": ("eps = 0.1 mm: diagrams for y_fp = 0.05-1 mm whose bifurcation points move "
                   "with y_fp; orbits exist only beyond a freeplay threshold (IV.D.2)."),
    },
}

FREEPLAYS = freeplay.FIG14_FREEPLAYS


def hopf_curves() -> List[Dict[str, Any]]:
    curves = yfp_runs.hopf_curves(paths.rundir("fig14/hopf_curves"), "hopf", "fixed",
                            figure="fig14", **gear.parameters())
    return yfp_stored.stored_curves(curves, ("yfp", "V", "freq"))


def parts() -> Dict[str, Any]:
    """One diagram in V per y_fp (the orbits in y_fp with the y_fp = 1 one)
    and the Hopf curves in (y_fp, V)."""
    return {**yfp_stored.diagram_jobs("fig14", "fixed", FREEPLAYS, orbits_at=1.0,
                              **gear.parameters()),
            "hopf_curves": hopf_curves}


def compute(parts: Any) -> Dict[str, Any]:
    diagrams, orbits = yfp_stored.diagrams_of(parts.all())
    codim2 = yfp_codim2.codim2_points(parts["hopf_curves"], "fixed", "V", **gear.parameters())
    return {"numbers": numbers(diagrams, orbits), "diagrams": diagrams, "orbits": orbits,
            "hopf_curves": parts["hopf_curves"], "codim2": codim2,
            # each GH point's l2 against the folds of the diagrams beside it
            "codim2_folds": [yfp_codim2.fold_check(p, diagrams, "fixed", **gear.parameters())
                             if p["type"] == "GH" else None for p in codim2]}


def lowest_orbit(curve: Mapping[str, Any], V: float) -> Tuple[float, str]:
    """(y_fp, kind): the smallest y_fp the orbits of speed V reach, and
    whether that is a Hopf point of straight rolling in y_fp ('Hopf'; AUTO
    may label the collapse there LP) or a fold in y_fp ('fold')."""
    y_min = float(min(curve["yfp"]))
    hopf = [y for y, k, _ in yfp_runs.yfp_thresholds("fixed", V, **gear.parameters())
            if k == "HB"]
    return y_min, "Hopf" if any(abs(y_min - y) < 2e-3 * y for y in hopf) else "fold"


def numbers(diagrams: Sequence[Mapping[str, Any]],
            orbits: Optional[Sequence[Tuple[float, Mapping[str, Any]]]]) -> Dict[str, float]:
    """{quantity: value}: Hopf and fold speeds per y_fp; per orbit speed the
    smallest y_fp the orbits reach and the Hopf points in y_fp there."""
    out = yfp_stored.diagram_numbers(diagrams)
    for d in diagrams:
        for first, smallest in d["turns"]:   # whether or not AUTO labels the turn LP
            if smallest < first - 0.5:
                out[f"y_fp = {d['yfp']:g}: smallest V of the orbits from H at {first:.1f} "
                    "[m/s]"] = smallest
    for (V, curve), name in zip(orbits, yfp_stored.orbit_names(orbits)):
        y_min, kind = lowest_orbit(curve, V)
        out[f"{name}: orbits down to y_fp [mm] ({kind})"] = y_min
        if name != f"V = {V:g}":
            continue   # a second orbit at V: its Hopf points came with the first
        hopf = [y for y, k, _ in yfp_runs.yfp_thresholds("fixed", V, **gear.parameters())
                if k == "HB"]
        for k, y in enumerate(hopf):
            out[f"V = {V:g}: Hopf point {k + 1} in y_fp [mm]"] = y
    return out


def plot(result: Mapping[str, Any]) -> None:
    paper.report("fig14", result["numbers"],
                 notes=yfp_codim2.codim2_lines(result["codim2"], checks=result["codim2_folds"]))
    fig = plt.figure(figsize=(12, 12))
    grid = fig.add_gridspec(4, 6)
    k_tlk = mlgmodel.Model("figures")["k_tlk"]
    diagram_axes = []
    for n, d in enumerate(result["diagrams"]):
        y = d["yfp"]
        row, col = divmod(n, 2)
        ax = fig.add_subplot(grid[row, 3 * col:3 * col + 2])
        draw_magnitude.diagram_in_V(ax, d, None, None)
        diagram_axes.append(ax)
        ax.set(xlim=(0, yfp_runs.V_MAX), xlabel="V [m/s]", ylabel=r"$\psi$ amplitude [deg]",
               title=f"({'abcdef'[n]}) $y_{{fp}}$ = {y:g} mm")
        inset = fig.add_subplot(grid[row, 3 * col + 2])
        ys, force = freeplay.profile(y, "fixed", k_tlk, span=max(3.0, 0.6 / y))
        inset.plot(ys, force / 1e3, color=draw.NEUTRAL, lw=1)
        inset.set(xlabel="$y_{tlk}$ [mm]", ylabel=r"$M_{k\psi}/r_{tlk}$ [kN]")
    ax_amp = fig.add_subplot(grid[3, 0:3])
    ax_freq = fig.add_subplot(grid[3, 3:6])
    draw_magnitude.orbits_in_yfp(ax_amp, ax_freq, result["orbits"])
    label = "Hopf curves"
    for curve in result["hopf_curves"]:
        ax_freq.plot(curve["yfp"], curve["freq"], label=label, **{**draw.HOPF_CURVE, "lw": 0.9})
        label = None
    for point in result["codim2"]:
        draw.mark(ax_freq, point["yfp"], point["omega"] / (2 * numpy.pi), point["type"])
    kinds = sorted({p["type"] for p in result["codim2"]})
    draw.legend(ax_freq, extra=[h for h in ax_freq.get_legend_handles_labels()[0]
                                if h.get_label() == "Hopf curves"] + draw.point_handles(kinds),
                stability=False, axes=[])
    ax_amp.set(xscale="log", title="(g) orbits at fixed V continued in $y_{fp}$")
    ax_freq.set(xscale="log", ylim=(0, 45), title="(h) their frequency; Hopf curves dot-dashed")
    draw.figure_title(fig, r"Fig. 14: $F^*$ = 1, $\epsilon$ = 0.1 mm")
    fig.tight_layout()
    draw.legend(fig, axes=diagram_axes)   # below the panels: styles and points of (a)-(f)
    draw.save(fig, "fig14")


if __name__ == "__main__":
    jobs.run_figure("fig14", compute, plot, parts)
