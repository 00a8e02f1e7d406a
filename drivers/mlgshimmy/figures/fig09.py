"""Fig. 9: the zero-freeplay Hopf curve in the (V, F*) plane, F* in [0, 3.5],
continued from the Hopf point of straight rolling at F* = 1; l1 along it,
its codimension-two points (shared.codim2) and the criticality of its
ends checked (shared.naming)."""
from __future__ import annotations

from typing import Any, Dict, List, Mapping

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from mlgshimmy.shared import codim2
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import draw
from mlgshimmy.shared import gear
from mlgshimmy.shared import jobs
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import naming
from mlgshimmy.shared import paper
from mlgshimmy.shared import paths

# What make, make help, make submit and the report know of this figure
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "fig09": {
        "help": "Fig. 9: zero-freeplay Hopf curve in (V, F*)",
        "time": "5 s",
        "regress": "quick",
        "report": ("The zero-freeplay Hopf curve in (V, F*): it bounds stable straight rolling "
                   "and lies outside the operating region (IV.A)."),
    },
}

FSTAR_RANGE = (0.1, 3.5)   # below F* ~ 0.1 the curve leaves V <= 600 m/s steeply


def compute(parameter_set: str = "figures", where: str = "fig09") -> Dict[str, Any]:
    """{"curves": stored Hopf-curve branches, "ends": [(F*, V)] of their UZ
    ends, "tests": codim2.along_hopf_curve of each branch, "named": the ends
    as Hopf points in V, named with their criticality checked}."""
    rundir = paths.rundir(where)
    start = ct.Start(parameter_set, Fstar=1.0, V=gear.start_speed(), **gear.parameters())
    eq = ct.equilibria(rundir, "eq", start, stop={"V": 600.0}, expect=["HB"])
    curves = []
    for direction, ds in (("up", 0.01), ("down", -0.01)):
        # it ends where it leaves the plane: F* at either end, or V (a
        # stiffer gear's curve passes V = 600 m/s below F* = 3.5)
        curves.append(ct.hopf_curve(rundir, f"hopf_{direction}", eq("HB1"), DS=ds,
                                    stop={"Fstar": list(FSTAR_RANGE),
                                          "V": [ct.V_MIN, ct.V_MAX]},
                                    expect=["UZ"]))
    ends = [(p["Fstar"], p["V"]) for c in curves for p in c("UZ")]

    def at(V, Fstar):
        model = mlgmodel.Model(parameter_set, V=V, Fstar=Fstar, **gear.parameters())
        return model, model.equilibrium()
    tests = [codim2.along_hopf_curve(list(zip(b["V"], b["Fstar"])), at)
             for c in curves for b in c]
    kinks = [codim2.kink(*at(V, F)) for c in curves for b in c for V, F in zip(b["V"], b["Fstar"])]
    named = [naming.named_points([(V, None)], [], parameter_set, "V", Fstar=Fstar,
                                 **gear.parameters())[0] for Fstar, V in ends]
    return {"curves": [jobs.stored(c, ("V", "Fstar")) for c in curves], "ends": ends,
            "tests": tests, "named": named, "kinks": kinks}


def about(result: Mapping[str, Any]) -> List[str]:
    """The table's lines: l1 along the curve, its codimension-two points,
    the ends' criticality checked."""
    l1 = [v for t in result["tests"] for v in t["l1"]]
    found = [p for t in result["tests"] for p in t["points"]]
    sign = ("negative throughout: supercritical" if max(l1) < 0 else
            "positive throughout: subcritical" if min(l1) > 0 else "changes sign")
    lines = [f"l1 along the Hopf curve ({len(l1)} points): {min(l1):+.4g} to {max(l1):+.4g}, "
             f"{sign}",
             "codimension-two points on it (codim2): " + (", ".join(
                 f"{p['type']} at V = {p['a']:.6g} m/s, F* = {p['b']:.6g} (omega "
                 f"{p['omega']:.4g} rad/s, l1 {p['l1']:+.4g}"
                 + (f", l2 {p['l2']:+.4g}" if p["type"] == "GH" else "") + ")" for p in found)
                 or "none")]
    decided = [a2 for a2, psi in result["kinks"] if psi > naming.SEEN]
    if decided:
        lines.append(f"the oleo's kink decides at {len(decided)} of {len(result['kinks'])} points "
                     f"(Re a2 {min(decided):+.3g} to {max(decided):+.3g}; "
                     f"{'supercritical' if max(decided) < 0 else 'mixed'} there): "
                     "the mode moves eta', l1, l2 and its GH points are those of the one-sided "
                     "expansion, above the kink's amplitude")
    lines += [f"end at F* = {Fstar:.3g}: {p['about']}"
              for (Fstar, _), p in zip(result["ends"], result["named"])]
    return lines + [naming.agreement(result["named"])]


def plot(result: Mapping[str, Any]) -> None:
    paper.report("fig09", {f"Hopf curve at F* = {Fstar:.3g}: V [m/s]": V
                           for Fstar, V in result["ends"]}, notes=about(result))
    fig, ax = plt.subplots(figsize=(6, 4.5))
    span = (600.0, 3.5)
    for curve in result["curves"]:
        for branch in jobs.loaded(curve):
            # AUTO steps in F* only (V is left out of the arclength), so
            # below F* ~ 0.3, where V changes fast, its points are far apart:
            # drawn smoothly through them (draw.smooth), the points unchanged
            ax.plot(*draw.smooth(branch["V"], branch["Fstar"], span), lw=1.6,
                    color=draw.HOPF_CURVE["color"])
    ax.text(495, 2.2, "H", color=draw.HOPF_CURVE["color"])
    for point in (p for t in result["tests"] for p in t["points"]):
        draw.mark(ax, point["a"], point["b"], point["type"])
    ax.axvspan(0, 80.0, color=draw.palette.SHADE, zorder=0)
    ax.text(450, 0.4, "torsional shimmy", ha="center", fontsize=8)
    ax.text(230, 1.6, "stable straight rolling", ha="center", fontsize=8)
    ax.set_xlim(0, span[0])
    ax.set_ylim(0, span[1])
    ax.set_xlabel("V [m/s]")
    ax.set_ylabel("$F_z^*$")
    handles = [Line2D([], [], color=draw.HOPF_CURVE["color"], lw=1.6,
                      label="H: Hopf curve of straight rolling"),
               Patch(color=draw.palette.SHADE, label="operating region, V ≤ 80 m/s")]
    draw.legend(ax, extra=handles, stability=False, loc="upper right")
    draw.figure_title(ax, "Fig. 9: Hopf curve, zero freeplay")
    draw.save(fig, "fig09")


if __name__ == "__main__":
    jobs.run_figure("fig09", compute, plot)
