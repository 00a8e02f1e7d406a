"""Fig. 6: torque-link force profiles M_kpsi / r_tlk against y_tlk, eq. (15)
(or the gear's freeplay law, FREEPLAY=) for epsilon = 2, 1, 0.5, 0.2, 0.1
y_fp and the non-smooth eq. (14) dashed; panel (b) zooms on one corner to
show the smoothing region, whose half-width is about epsilon."""
from __future__ import annotations

import matplotlib.pyplot as plt
import numpy
from numpy.typing import ArrayLike

from mlgshimmy.shared import draw
from mlgshimmy.shared import freeplay as fp
from mlgshimmy.shared import mlgmodel

# What make, make help, make submit and the report know of this figure
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "fig06": {
        "help": "Fig. 6: torque-link force profiles, eqs. (14), (15)",
        "time": "5 s",
        "cached": False,
        "needs": ["library"],
        "report": ("Torque-link force profiles, eq. (15) for five smoothing widths against the "
                   "non-smooth eq. (14) (section III)."),
    },
}

RATIOS = (2.0, 1.0, 0.5, 0.2, 0.1)      # epsilon / y_fp


def profile(yfp_m: float, eps_m: float, y: ArrayLike) -> numpy.ndarray:
    return fp.force(y, yfp_m, eps_m, mlgmodel.Model("figures")["k_tlk"])


def main() -> None:
    yfp = 1e-3
    y = numpy.linspace(-3 * yfp, 3 * yfp, 1201)
    fig, (full, zoom) = plt.subplots(1, 2, figsize=(10, 4.2))
    for ratio, colour in zip(RATIOS, draw.sequence(len(RATIOS))):
        for ax in (full, zoom):
            ax.plot(y * 1e3, profile(yfp, ratio * yfp, y) / 1e3, lw=1.3, color=colour,
                    label=rf"$\epsilon$ = {ratio:g} $y_{{fp}}$")
    for ax in (full, zoom):
        ax.plot(y * 1e3, profile(yfp, 0.0, y) / 1e3, ls="--", color=draw.NEUTRAL, lw=1.2,
                label="eq. (14)")
        ax.set_xlabel(r"$y_{tlk}$ [mm]")
        ax.set_ylabel(r"$M_{k\psi} / r_{tlk}$ [kN]")
    eps = 0.1 * yfp
    zoom.set_xlim(0.5, 1.6)
    zoom.set_ylim(-4.5, 25)
    zoom.axvspan((yfp - eps) * 1e3, (yfp + eps) * 1e3, color=draw.palette.BAND, zorder=0)
    # below the curves (all >= 0 here), on the shaded band it names
    zoom.annotate(r"$y_{fp} \pm \epsilon$ ($\epsilon$ = 0.1 $y_{fp}$)", (1.0, -3.2),
                  ha="center", va="center", fontsize=8)
    k_tlk = mlgmodel.Model("figures")["k_tlk"]
    full.set_title(rf"(a) {fp.law_label()}, $y_{{fp}}$ = 1 mm, $k_{{tlk}}$ = {draw.sci(k_tlk)} N/m")
    zoom.set_title("(b) the smoothing region at the contact corner")
    full.legend(fontsize=8)
    draw.figure_title(fig, "Fig. 6: torque-link force profiles")
    fig.tight_layout()
    draw.save(fig, "fig06")


if __name__ == "__main__":
    main()
