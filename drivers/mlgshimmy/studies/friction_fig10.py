"""Fig. 10 with oleo seal friction (docs/friction.md): the paper's diagram in V
(F* = 1, y_fp = 1 mm, eps = 0.1 y_fp) at LEVELS of the friction moment
M_fric, regularised with v_fric = V_FRIC (the model's default), each by
Fig. 10's recipe (continuation.diagram_from_rest): straight rolling, its
Hopf points, and the orbits born there.  The friction is felt by straight
rolling as the damper M_fric r_seal / v_fric (docs/model.md 10), so these
levels lie below the linear threshold (8.85 N m at 1 mm/s, make friction),
where H1 and H2 still exist; above it the low-frequency orbits are an
isolated family (the fold curves of make friction).

    make friction_fig10        # build/figures/friction_fig10.png
"""
from __future__ import annotations

from typing import Any, Dict, Mapping

import matplotlib.pyplot as plt

from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import draw
from mlgshimmy.shared import gear
from mlgshimmy.shared import jobs
from mlgshimmy.shared import naming
from mlgshimmy.shared import paper
from mlgshimmy.shared import paths

DECLARED = {
    "friction_fig10": {
        "help": "Fig. 10 with oleo seal friction at three levels of M_fric",
        "time": "6 min",
        "report": {
            "command": "make friction_fig10",
            "text": ("Beyond the paper: Fig. 10's diagram with the oleo seal friction moment "
                     "M_fric at 0, 2 and 5 N m (regularised, v_fric = 1 mm/s): the low-speed "
                     "shimmy shrinks and its Hopf points turn subcritical (docs/friction.md)."),
            "tables": ["tables/friction_fig10.txt"],
            "figures": ["figures/friction_fig10.png"],
        },
    },
}

CONDITIONS = {"Fstar": 1.0, "yfp": 1.0, "eps_rel": 0.1}   # Fig. 10's
LEVELS = (0.0, 2.0, 5.0)   # N m
V_FRIC = 1e-3              # m/s
COLUMNS = ("V", "psi_amp", "freq")
V_LOW = 50.0               # m/s: the panels' range, the low-speed shimmy and S


def level(moment: float) -> Dict[str, Any]:
    """Fig. 10's diagram at M_fric = moment: its branches, Hopf points by
    name and folds of orbits (V, Hz)."""
    values = {**CONDITIONS, "M_fric": moment, "v_fric": V_FRIC, **gear.parameters()}
    rundir = paths.rundir(f"friction_fig10/m{moment:g}")
    eq, diagram = ct.diagram_from_rest(rundir, "figures", figure="friction_fig10", **values)
    folds = sorted((V, run(lab)["freq"], amp) for run, lab, V, amp in diagram.folds())
    return {"M_fric": moment, "eq": jobs.stored(eq, COLUMNS),
            "orbits": [jobs.stored(run, COLUMNS) for run in diagram.branches],
            "hopf": [{"name": p["name"], "V": p["V"], "criticality": p["criticality"]}
                     for p in diagram.named],
            "folds": folds}


def compute() -> Dict[str, Any]:
    print("friction_fig10: Fig. 10 at seal friction levels " + ", ".join(map(str, LEVELS))
          + " N m" + gear.suffix())
    return {"levels": [level(m) for m in LEVELS]}


def numbers(result: Mapping[str, Any]) -> Dict[str, float]:
    """{quantity: value}: each level's Hopf points (with their criticality)
    and folds of orbits."""
    out = {}
    for lv in result["levels"]:
        at = f"M_fric = {lv['M_fric']:g} N m"
        out.update({f"{p['name']} ({p['criticality']}) [m/s], {at}": p["V"]
                    for p in lv["hopf"]})
        for name, V in naming.fold_names([(V, hz) for V, hz, _ in lv["folds"]]):
            out[f"{name} [m/s], {at}"] = V
    return out


def plot(result: Mapping[str, Any]) -> None:
    paper.report("friction_fig10", numbers(result))
    levels = result["levels"]
    fig, axes = plt.subplots(1, len(levels), figsize=(4.2 * len(levels), 4.4), sharey=True)
    for ax, lv in zip(axes, levels):
        draw.plot_branch(ax, jobs.loaded(lv["eq"]), "V", "psi_amp", scale=draw.DEG)
        for orbits in lv["orbits"]:
            draw.plot_branch(ax, jobs.loaded(orbits), "V", "psi_amp", scale=draw.DEG)
        for V, _, amp in lv["folds"]:
            if V < V_LOW:
                draw.mark(ax, V, amp * draw.DEG, "LP")
        for p in lv["hopf"]:
            if p["V"] < V_LOW:
                draw.mark(ax, p["V"], 0.0, "HB", name=p["name"])
        ax.set_xlim(0.0, V_LOW)
        ax.set_xlabel("V [m/s]")
        ax.set_title(rf"$M_f$ = {lv['M_fric']:g} N m")
    # the low-speed shimmy's scale: the large high-frequency orbits beyond V_LOW hide it
    top = max(amp for lv in levels for orbits in lv["orbits"] for b in jobs.loaded(orbits)
              for V, amp in zip(b["V"], b["psi_amp"]) if V <= V_LOW)
    axes[0].set_ylim(-0.05 * top * draw.DEG, 1.3 * top * draw.DEG)
    axes[0].set_ylabel(r"torsional amplitude $\psi$ [deg]")
    draw.legend(fig)
    draw.figure_title(fig, r"Fig. 10 with seal friction ($v_\varepsilon$ = 1 mm/s): $F^*$ = 1, "
                      r"$y_{fp}$ = 1 mm")   # draw.save adds the gear
    fig.tight_layout()
    draw.save(fig, "friction_fig10")


if __name__ == "__main__":
    jobs.run_figure("friction_fig10", compute, plot, module="mlgshimmy.studies.friction_fig10")
