"""Fig. 15: the stiffness profiles of Figs. 13 and 14 rescaled,
x* = y_tlk / y_fp and y* = M_kpsi / (r_tlk k_tlk y_fp): (a) eps = 0.1 y_fp,
where all coincide, (b) eps = 0.1 mm, where they do not.  Eq. (15), or the
gear's freeplay law (FREEPLAY=): no continuation, no AUTO import and
nothing to cache (it draws in seconds)."""
from __future__ import annotations

from typing import Sequence, Tuple

import matplotlib.pyplot as plt
import numpy

from mlgshimmy.shared import draw
from mlgshimmy.shared import freeplay as fp
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import paper

# What make, make help, make submit and the report know of this figure
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "fig15": {
        "help": "Fig. 15: the profiles of Figs. 13 and 14 rescaled",
        "time": "5 s",
        "cached": False,
        "needs": ["library"],
        "report": ("The profiles of Figs. 13 and 14 rescaled: they coincide for eps/y_fp fixed "
                   "and do not for eps fixed (IV.D)."),
    },
}

SPAN = 3.0   # x* range: |x*| <= SPAN


def rescaled(yfp: float, scaling: str, k_tlk: float) -> Tuple[numpy.ndarray, numpy.ndarray]:
    y, force = fp.profile(yfp, scaling, k_tlk, span=SPAN)
    return y / yfp, force / (k_tlk * 1e-3 * yfp)


def spread(scaling: str, freeplays: Sequence[float], k_tlk: float) -> float:
    """Largest difference between the rescaled profiles on a common x* grid."""
    curves = [rescaled(y, scaling, k_tlk)[1] for y in freeplays]
    return float(numpy.max(numpy.ptp(numpy.array(curves), axis=0)))


def main() -> None:
    k_tlk = mlgmodel.Model("figures")["k_tlk"]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2), sharey=True)
    ours = {}
    for ax, scaling, freeplays, title in (
            (axes[0], "ratio", fp.FIG13_FREEPLAYS, r"(a) $\epsilon$ = 0.1 $y_{fp}$ (Fig. 13)"),
            (axes[1], "fixed", fp.FIG14_FREEPLAYS, r"(b) $\epsilon$ = 0.1 mm (Fig. 14)")):
        for y, colour in zip(freeplays, draw.sequence(len(freeplays))):
            ax.plot(*rescaled(y, scaling, k_tlk), lw=1.2, color=colour,
                    label=f"$y_{{fp}}$ = {y:g} mm")
        ax.plot([-SPAN, -1, 1, SPAN], [1 - SPAN, 0, 0, SPAN - 1], color=draw.NEUTRAL, ls="--",
                lw=0.8,
                label=r"$\epsilon$ = 0 (eq. 14)")
        ax.set(title=title, xlabel=r"$x^* = y_{tlk}/y_{fp}$", xlim=(-SPAN, SPAN))
        ax.legend(fontsize=7)
        ours[f"{title[:3]} largest spread of the rescaled profiles"] = \
            spread(scaling, freeplays, k_tlk)
    paper.report("fig15", ours)
    axes[0].set_ylabel(r"$y^* = M_{k\psi}/(r_{tlk}\,k_{tlk}\,y_{fp})$")
    draw.figure_title(fig, "Fig. 15: rescaled torque-link stiffness profiles, "
                      + fp.law_label())
    fig.tight_layout()
    draw.save(fig, "fig15")


if __name__ == "__main__":
    main()
