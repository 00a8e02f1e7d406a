"""Fig. 13: freeplay magnitude at a fixed scaled profile, eps = 0.1 y_fp
(section IV.D.1), F* = 1: (a) diagrams in V for y_fp = 0.2, 0.5, 1, 2 mm,
(b) their stiffness profiles, (c, d) amplitude and frequency of the stable
orbits at V = 15, 50, 80, 110 m/s continued in y_fp."""
from __future__ import annotations

from typing import Any, Dict, Mapping, Optional, Sequence, Tuple

import matplotlib.pyplot as plt
import numpy
from numpy.typing import ArrayLike

from mlgshimmy.shared import runerror
from mlgshimmy.shared import draw
from mlgshimmy.shared import freeplay
from mlgshimmy.shared import gear
from mlgshimmy.shared import jobs
from mlgshimmy.shared import yfp_runs
from mlgshimmy.shared import yfp_stored
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import paper
from mlgshimmy.shared.draw import magnitude as draw_magnitude

# What make, make help, make submit and the report know of this figure
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "fig13": {
        "help": "Fig. 13: eps = 0.1 y_fp, y_fp = 0.2-2 mm",
        "time": "1 min",
        "regress": True,
        "parts": True,
        "report": ("eps = 0.1 y_fp: diagrams in V for y_fp = 0.2-2 mm scale with y_fp while "
                   "the bifurcation speeds stay fixed; orbit amplitudes linear in y_fp, "
                   "frequencies constant (IV.D.1)."),
        # IV.D.1: the Fig. 10 diagram is the y_fp = 1 mm slice of Fig. 13
        "paper": {"y_fp = 1: H1 [m/s]": 1.5, "y_fp = 1: H2 [m/s]": 28.1,
                  "y_fp = 1: H3 [m/s]": 142.5, "y_fp = 1: S1 [m/s]": 41.5},
        # Fig. 10's printed numbers: the scorecard counts them once, there
        "repeats": {"y_fp = 1: H1 [m/s]": ["fig10", "H1 [m/s]"],
                    "y_fp = 1: H2 [m/s]": ["fig10", "H2 [m/s]"],
                    "y_fp = 1: H3 [m/s]": ["fig10", "H3 [m/s]"],
                    "y_fp = 1: S1 [m/s]": ["fig10", "S1 [m/s]"]},
    },
}

FREEPLAYS = freeplay.FIG13_FREEPLAYS
COLOURS = draw.sequence(len(FREEPLAYS))
FIT_RANGE = (0.05, 2.0)   # y_fp range of the linear fits [mm]
ORBITS_FROM = 1.0         # y_fp [mm] the orbits at fixed V are continued from


def parts() -> Dict[str, Any]:
    """One diagram in V per y_fp (the orbits in y_fp with the y_fp = 1 one),
    each in its own run directory build/fig13/<part>/."""
    return yfp_stored.diagram_jobs("fig13", "ratio", FREEPLAYS, orbits_at=ORBITS_FROM,
                           **gear.parameters())


def compute(parts: Any) -> Dict[str, Any]:
    diagrams, orbits = yfp_stored.diagrams_of(parts.all())
    return {"numbers": numbers(diagrams, orbits), "diagrams": diagrams, "orbits": orbits}


def stable_piece(stable: ArrayLike, start: int) -> numpy.ndarray:
    """A mask of the stable points of an orbit curve (ordered) next to each
    other around index `start` (none if that point is unstable)."""
    mask = numpy.zeros(len(stable), dtype=bool)
    if not stable[start]:
        return mask
    lo, hi = start, start
    while lo > 0 and stable[lo - 1]:
        lo -= 1
    while hi < len(stable) - 1 and stable[hi + 1]:
        hi += 1
    mask[lo:hi + 1] = True
    return mask


def numbers(diagrams: Sequence[Mapping[str, Any]],
            orbits: Optional[Sequence[Tuple[float, Mapping[str, Any]]]]) -> Dict[str, float]:
    """{quantity: value}: Hopf and fold speeds per y_fp, and per orbit speed
    the slope of psi_amp against y_fp (fit through 0), its largest relative
    residual, the intercept of a free linear fit, and the frequency range."""
    out = yfp_stored.diagram_numbers(diagrams)
    for (V, curve), name in zip(orbits, yfp_stored.orbit_names(orbits)):
        ys, amp, freq, stable = (numpy.asarray(curve[c]) for c in ("yfp", "psi_amp", "freq",
                                                                    "stable"))
        inside = (ys >= FIT_RANGE[0]) & (ys <= FIT_RANGE[1])
        if not stable[inside].all():
            # side-stay angles break the scaling with y_fp (the links' static
            # offset does not scale): fit the stable orbits continued from the start
            piece = stable_piece(stable, int(numpy.argmin(numpy.abs(ys - ORBITS_FROM))))
            if not piece.any():
                raise runerror.RunError(f"fig13: the orbit at {name} is unstable where it "
                                        f"starts, y_fp = {ORBITS_FROM:g} mm")
            inside &= piece
            out[f"{name}: stable from y_fp [mm]"] = ys[piece].min()
            out[f"{name}: stable up to y_fp [mm]"] = ys[piece].max()
        s0, residual, _, c = yfp_runs.linear_fit(ys[inside], amp[inside])
        out[f"{name}: psi_amp/y_fp [rad/mm]"] = s0
        out[f"{name}: largest rel. residual"] = residual
        out[f"{name}: intercept of free fit [rad]"] = c
        out[f"{name}: freq min [Hz]"] = freq[inside].min()
        out[f"{name}: freq max [Hz]"] = freq[inside].max()
    return out


def plot(result: Mapping[str, Any]) -> None:
    paper.report("fig13", paper.in_degrees(result["numbers"]))
    fig, axes = plt.subplots(2, 2, figsize=(10, 7.5))
    k_tlk = mlgmodel.Model("figures")["k_tlk"]
    for d, colour in zip(result["diagrams"], COLOURS):
        y = d["yfp"]
        draw_magnitude.diagram_in_V(axes[0][0], d, colour, f"$y_{{fp}}$ = {y:g} mm")
        ys, force = freeplay.profile(y, "ratio", k_tlk, span=1.0 / y * 3.0)
        axes[0][1].plot(ys, force / 1e3, color=colour, label=f"$y_{{fp}}$ = {y:g} mm")
    axes[0][0].set(xlabel="V [m/s]", ylabel=r"$\psi$ amplitude [deg]", xlim=(0, yfp_runs.V_MAX),
                   title="(a) diagrams in V")
    draw.legend(axes[0][0], extra=axes[0][0].get_legend_handles_labels()[0], color=draw.NEUTRAL,
                loc="upper left", ncol=2)
    axes[0][1].set(xlabel="$y_{tlk}$ [mm]", ylabel=r"$M_{k\psi}/r_{tlk}$ [kN]", xlim=(-3, 3),
                   title=r"(b) stiffness profiles, $\epsilon$ = 0.1 $y_{fp}$")
    axes[0][1].legend(fontsize=7)
    draw_magnitude.orbits_in_yfp(axes[1][0], axes[1][1], result["orbits"])
    axes[1][0].set_title("(c) orbits at fixed V continued in $y_{fp}$")
    axes[1][1].set_title("(d) their frequency")
    axes[1][1].set_ylim(0, None)
    for ax in axes[1]:
        ax.set_xlim(0, yfp_runs.YFP_MAX)
    draw.figure_title(fig, r"Fig. 13: $F^*$ = 1, $\epsilon/y_{fp}$ = 0.1")
    fig.tight_layout()
    draw.save(fig, "fig13")


if __name__ == "__main__":
    jobs.run_figure("fig13", compute, plot, parts)
