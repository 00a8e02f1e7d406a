"""Fig. 19: the rescaled stiffness profiles allowed by y_fp/eps < kappa*
(kappa* of both strut variants from Fig. 18's cached results, fig18 and
fig18_v1): every allowed profile lies
between the kappa* profile and the eps -> infinity limit y* = x* (no
freeplay felt).  The two readings of the strut spring bound a band: the
profiles between their kappa* profiles are allowed by one only."""
from __future__ import annotations

import matplotlib.pyplot as plt
import numpy
from numpy.typing import ArrayLike

from mlgshimmy.shared import draw
from mlgshimmy.shared import freeplay as fp
from mlgshimmy.shared import jobs
from mlgshimmy.shared import paper

# What make, make help, make submit and the report know of this figure
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "fig19": {
        "help": "Fig. 19: profiles allowed by kappa*, after fig18, fig18_v1",
        "time": "+ 5 s",
        "cached": False,
        "needs": ["library"],
        "after": ["fig18", "fig18_v1"],
        "report": ("The rescaled profiles allowed by y_fp/eps < kappa* (eq. 17), between the "
                   "kappa* profile and eps -> infinity (IV.E)."),
    },
}

SPAN = 3.0


def rescaled(kappa: float, x: ArrayLike) -> numpy.ndarray:
    """Eq. (15) rescaled (x* = y_tlk/y_fp, y* = M_kpsi/(r_tlk k_tlk y_fp)) for
    y_fp/eps = kappa: the profile of y_fp = 1 mm, eps = 1/kappa mm; kappa = 0
    (no freeplay allowed) is its eps -> infinity limit y* = x*."""
    if kappa == 0:
        return numpy.array(x, dtype=float)
    return fp.force(1e-3 * numpy.asarray(x), 1e-3, 1e-3 / kappa) / 1e-3


def read_kappa(name: str) -> float:
    try:
        return jobs.read(name)["kappa_star"]
    except jobs.MissingResult as exc:
        raise SystemExit(f"fig19: {exc}")


def main() -> None:
    kappa, kappa_printed = read_kappa("fig18"), read_kappa("fig18_v1")
    x = numpy.linspace(-SPAN, SPAN, 601)
    limit, printed = rescaled(kappa, x), rescaled(kappa_printed, x)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    both = (rf"$y_{{fp}}/\epsilon < {kappa_printed:.3f}$" if kappa_printed > 0
            else r"none ($\kappa^*$ = 0: unstable without freeplay)")
    ax.fill_between(x, printed, x, color=draw.palette.ALLOWED, alpha=0.4,
                    label=f"allowed by both: {both}")
    ax.fill_between(x, limit, printed, color=draw.palette.ALLOWED_PART, alpha=0.5,
                    label=rf"allowed in the monotone order only: ${kappa_printed:.3f} \leq "
                          rf"y_{{fp}}/\epsilon < {kappa:.3f}$")
    ax.plot(x, limit, color=draw.STABLE, lw=1.4,
            label=rf"$\kappa^*$ = {kappa:.3f} ({draw.STRUT_ORDER[0]})")
    ax.plot(x, printed, color=draw.UNSTABLE, lw=1.4,
            label=rf"$\kappa^*$ = {kappa_printed:.3f} ({draw.STRUT_ORDER[1]})")
    ax.plot(x, x, color=draw.NEUTRAL, ls="--", lw=1, label=r"$\epsilon \to \infty$")
    ax.plot(x, rescaled(10.0, x), color=draw.palette.LIFTOFF, lw=1,
            label=r"$y_{fp}/\epsilon$ = 10 (section IV.B)")
    ax.set(xlim=(-SPAN, SPAN), xlabel=r"$x^* = y_{tlk}/y_{fp}$",
           ylabel=r"$y^* = M_{k\psi}/(r_{tlk}\,k_{tlk}\,y_{fp})$")
    draw.figure_title(ax, "Fig. 19: allowed rescaled freeplay profiles, both strut readings")
    ax.legend(fontsize=7)
    paper.report("fig19", {
        "kappa*, strut variant 0": kappa, "kappa*, strut variant 1": kappa_printed,
        "slope of the kappa* profile at x* = 0": numpy.gradient(limit, x)[len(x) // 2],
        "slope of the variant-1 kappa* profile at x* = 0":
            numpy.gradient(printed, x)[len(x) // 2]})
    draw.save(fig, "fig19")


if __name__ == "__main__":
    main()
