"""Drawing the freeplay-magnitude results of Figs. 13-19 (section IV.D):
orbits continued in y_fp and diagrams in V, from their cached records
(yfp_stored.stored_orbits, yfp_stored.stored_diagram)."""
from __future__ import annotations

from typing import Any, Mapping, Sequence, Tuple

import numpy
from matplotlib.lines import Line2D

from mlgshimmy.shared import draw, jobs
from mlgshimmy.shared.yfp_runs import V_ORBITS

ORBIT_COLOURS = dict(zip(V_ORBITS, draw.sequence(len(V_ORBITS))))


def orbits_in_yfp(ax_amp: Any, ax_freq: Any,
                  orbits: Sequence[Tuple[float, Mapping[str, Any]]]) -> None:
    """Torsional amplitude [deg] and frequency [Hz] against y_fp of stored
    orbits (stored_orbits; solid stable, dashed unstable), one colour per
    speed; the legend on ax_amp names the speeds and the two styles."""
    for V, curve in orbits:
        for ax, measure, scale in ((ax_amp, "psi_amp", draw.DEG), (ax_freq, "freq", 1.0)):
            draw.plot_stability(ax, curve["yfp"], numpy.asarray(curve[measure]) * scale,
                                curve["stable"], label=f"V = {V:g} m/s",
                                color=ORBIT_COLOURS[V], lw=1.5)
    ax_amp.set_ylabel(r"$\psi$ amplitude [deg]")
    ax_freq.set_ylabel("frequency [Hz]")
    for ax in (ax_amp, ax_freq):
        ax.set_xlabel("$y_{fp}$ [mm]")
    speeds = [Line2D([], [], color=ORBIT_COLOURS[V], lw=1.5, label=f"V = {V:g} m/s")
              for V in sorted({V for V, _ in orbits})]
    draw.legend(ax_amp, extra=speeds, color=draw.NEUTRAL, axes=[])


def diagram_in_V(ax_amp: Any, diagram: Mapping[str, Any], colour: Any, label: str) -> None:
    """psi amplitude [deg] against V of a stored Diagram (stored_diagram):
    its Hopf points H on the axis, the periodic branches (solid stable,
    dashed unstable; in `colour`, else STABLE/UNSTABLE), their folds S, and
    the stability changes AUTO labelled with nothing (draw.mark_specials)."""
    deg = draw.DEG
    style = {"color": colour} if colour else {}
    orbits = jobs.loaded(diagram["branches"])
    draw.plot_branch(ax_amp, orbits, "V", "psi_amp", scale=deg, **style)
    if label:
        ax_amp.plot([], [], color=colour, label=label)
    marker = colour or "k"
    for V, _ in diagram["hopf"]:
        draw.mark(ax_amp, V, 0.0, "HB", color=marker)
    for V, amp in diagram["folds"]:
        draw.mark(ax_amp, V, amp * deg, "LP", color=marker)
    draw.mark_specials(ax_amp, orbits, "V", "psi_amp", scale=deg, kinds=("TR",), color=marker)


# Section IV.E: where straight rolling is stable for all V up to V_LIMIT.
# The modes are told apart by frequency: the low-frequency torsional mode
# ('gentle' oscillations, 1.5-5 Hz at F* = 1), the high-frequency torsional
# mode (13-30 Hz) and real eigenvalues (pitchforks, static yaw).  The
# lightly damped axial pair (1.6 Hz, Re ~ -0.016) never crosses.
