"""Fig. 17: the Hopf and fold-of-cycles curves of Fig. 16(b) (eps = 0.1 mm,
F* = 1) in the plane (V, y_fp/eps), with R1 and R2 and the points a, b, c
that bound them (defined in kappa_criterion.window_points).  Drawn from Fig. 16's
cached result: no computation of its own."""
from __future__ import annotations

from typing import Any, Dict, Mapping

import matplotlib.pyplot as plt
import numpy

from mlgshimmy.shared import draw
from mlgshimmy.shared import freeplay
from mlgshimmy.shared import jobs
from mlgshimmy.shared import yfp_runs
from mlgshimmy.shared import paper

# What make, make help, make submit and the report know of this figure
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "fig17": {
        "help": "Fig. 17: Fig. 16's curves in (V, y_fp/eps), after fig16",
        "time": "+ 5 s",
        "regress": "with fig16",
        "after": ["fig16"],
        "report": ("The curves of Fig. 16(b) in (V, y_fp/eps) with the points a, b, c that "
                   "bound R1 and R2 (IV.E)."),
    },
}


def compute() -> Dict[str, Any]:
    """Fig. 16's curves and window, and the numbers of a, b, c."""
    fig16 = jobs.read("fig16")
    window = fig16["window"]
    numbers = {}
    for name in "abc":
        numbers[f"{name}: V [m/s]"] = window["V_" + name]
        numbers[f"{name}: y_fp/eps"] = window[name] / freeplay.EPSILON
    return {"numbers": numbers, "window": window, "hopf_curves": fig16["hopf_curves"],
            "fold_curves": fig16["fold_curves"]}


def plot(result: Mapping[str, Any]) -> None:
    paper.report("fig17", result["numbers"])
    window = result["window"]
    fig, ax = plt.subplots(figsize=(7, 5))
    eps = freeplay.EPSILON
    for kind, style, label in (("hopf_curves", draw.HOPF_CURVE, "Hopf"),
                               ("fold_curves", draw.FOLD_CURVE, "fold of cycles")):
        for curve in result[kind]:
            ax.plot(curve["V"], numpy.asarray(curve["yfp"]) / eps, label=label, **style)
            label = None
    for lo, hi, name in ((0.0, window["a"], "R1"), (window["b"], window["c"], "R2")):
        ax.fill_between([0, yfp_runs.V_LIMIT], lo / eps, hi / eps, color=draw.palette.ALLOWED,
                        alpha=0.35)
        ax.text(60, 0.5 * (lo + hi) / eps, name, ha="center", va="center")
    for name in "abc":
        V, y = window[f"V_{name}"], window[name] / eps
        ax.plot(V, y, "o", color=draw.NEUTRAL, ms=4)
        ax.annotate(name, (V, y), textcoords="offset points", xytext=(4, 4))
    ax.axvline(yfp_runs.V_LIMIT, color=draw.palette.GUIDE, ls=":", lw=1)
    ax.set(xlim=(0, yfp_runs.V_MAX), ylim=(0, 6), xlabel="V [m/s]", ylabel=r"$y_{fp}/\epsilon$")
    draw.figure_title(ax, r"Fig. 17: bifurcation curves in (V, $y_{fp}/\epsilon$), $F^*$ = 1, "
                          r"$\epsilon$ = 0.1 mm")
    ax.legend(fontsize=8, loc="upper right")
    draw.save(fig, "fig17")


if __name__ == "__main__":
    jobs.run_figure("fig17", compute, plot)
