"""Fig. 7: zero-freeplay diagrams in V for F* = 0.2 and F* = 1: straight
rolling, its Hopf point H and the periodic orbits born there; torsional and
lateral amplitudes."""
from __future__ import annotations

from typing import Any, Dict, List, Mapping

import matplotlib.pyplot as plt
from matplotlib.patches import Patch

from mlgshimmy.shared import branches
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import domain
from mlgshimmy.shared import draw
from mlgshimmy.shared import gear
from mlgshimmy.shared import jobs
from mlgshimmy.shared import naming
from mlgshimmy.shared import paper
from mlgshimmy.shared import paths

# What make, make help, make submit and the report know of this figure
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "fig07": {
        "help": "Fig. 7: zero freeplay, diagrams in V at F* = 0.2, 1",
        "time": "10 s",
        "regress": "quick",
        "report": ("Zero freeplay, diagrams in V at F* = 0.2 and 1: stable straight rolling up "
                   "to a supercritical Hopf point H, torsional shimmy beyond it, far above the "
                   "80 m/s operating region; H at F* = 1 is 346.1 m/s (IV.A, IV.B)."),
        # the result values the paper prints (the calibration: model.md section 5)
        "paper": {"H, F* = 1 [m/s]": 346.1},
        "calibrated": ["H, F* = 1 [m/s]"],
    },
}

LOADS = (0.2, 1.0)
COLUMNS = ("V", "psi_amp", "delta_amp")


def compute(parameter_set: str = "figures", where: str = "fig07") -> Dict[str, Any]:
    """{"F<F*>": {"eq", "po": stored branches, "hopf_V", "end_V", "end_psi_amp",
    "hopf": the Hopf point named by its mode, criticality checked (shared.naming)}}."""
    rundir = paths.rundir(where)
    result = {}
    for Fstar in LOADS:
        tag = f"F{Fstar:g}"
        start = ct.Start(parameter_set, Fstar=Fstar, V=gear.start_speed(),
                         **gear.parameters())
        eq = ct.equilibria(rundir, f"eq_{tag}", start, stop={"V": 600.0})
        hopf = eq("HB1") if eq("HB") else first_hopf(rundir, tag, parameter_set, Fstar)
        if hopf is None:
            print(f"fig07: F* = {Fstar:g}: straight rolling is stable up to 600 m/s "
                  "(no Hopf point: it vanished)")
            result[tag] = {"eq": jobs.stored(eq, COLUMNS), "po": [], "hopf_V": None}
            continue
        # the orbits may reach wheel lift-off below 600 m/s: the run is
        # kept up to there (MX) and its reason stored; with side-stay angles
        # any MX is kept, as the reference runs at a geometry were made
        po = ct.periodic_from(rundir, f"po_{tag}", hopf, stop={"V": 600.0},
                              allow_mx=ct.EDGE if gear.current().geometry.baseline else True)
        named, = naming.named_points([(hopf["V"], None)], [po], parameter_set, "V",
                                     Fstar=Fstar, **gear.parameters())
        result[tag] = {"eq": jobs.stored(eq, COLUMNS), "po": jobs.stored(po, COLUMNS),
                       "hopf_V": hopf["V"], "end_V": po[0]["V"][-1],
                       "end_psi_amp": po[0]["psi_amp"][-1], "hopf": named}
        for point in po("MX"):
            result[tag]["stop"] = domain.stop_reason(point)
            print(f"fig07: F* = {Fstar:g}: the orbits stop at V = {point['V']:.2f} m/s: "
                  f"{result[tag]['stop']}")
    return result


def first_hopf(rundir: str, tag: str, parameter_set: str, Fstar: float) -> Any:
    """The first Hopf point of straight rolling in V, where AUTO's own test
    missed it (it follows the pair nearest the axis: continuation.hopf_points
    scans the spectrum), or None: stable up to V_MAX."""
    found = ct.hopf_points(rundir, f"hb_{tag}", parameter_set, "V", ct.SPEED_SCAN, limit=1,
                           Fstar=Fstar, **gear.parameters())
    return found[0] if found else None


def numbers(result: Mapping[str, Any]) -> Dict[str, float]:
    """{quantity: value} of the figure (psi in degrees, as plotted); a Hopf
    point that does not exist is left out (reported as vanished)."""
    out = {f"H, F* = {Fstar:g} [m/s]": result[f"F{Fstar:g}"]["hopf_V"] for Fstar in (1.0, 0.2)
           if result[f"F{Fstar:g}"]["hopf_V"] is not None}
    for Fstar in LOADS:
        load = result[f"F{Fstar:g}"]
        if load["hopf_V"] is not None:
            out[f"F* = {Fstar:g}: orbit at V = {load['end_V']:g}: psi amplitude [deg]"] = \
                load["end_psi_amp"] * draw.DEG
    return out


def about(result: Mapping[str, Any]) -> List[str]:
    """The table's lines on the Hopf points: mode and criticality, checked."""
    named = [(Fstar, result[f"F{Fstar:g}"].get("hopf")) for Fstar in LOADS]
    named = [(Fstar, p) for Fstar, p in named if p]
    return ([f"H, F* = {Fstar:g}: {p['about']}" for Fstar, p in named]
            + ([naming.agreement([p for _, p in named])] if named else []))


def plot(result: Mapping[str, Any]) -> None:
    paper.report("fig07", numbers(result), notes=about(result))
    fig, axes = plt.subplots(2, 2, figsize=(9, 6.4), sharex=True)
    for col, Fstar in enumerate(LOADS):
        load = result[f"F{Fstar:g}"]
        if load["hopf_V"] is not None:
            print(f"fig07: F* = {Fstar:g}: Hopf at V = {load['hopf_V']:.3f} m/s; orbit at "
                  f"V = {load['end_V']:.1f}: psi amplitude "
                  f"{load['end_psi_amp'] * draw.DEG:.4f} deg")
        eq, po = jobs.loaded(load["eq"]), jobs.loaded(load["po"])
        for row, (measure, name) in enumerate((("psi_amp", r"$\psi$"), ("delta_amp", r"$\delta$"))):
            ax = axes[row][col]
            draw.plot_branch(ax, eq, "V", measure, scale=draw.DEG)
            draw.plot_branch(ax, po, "V", measure, scale=draw.DEG)
            draw.mark_points(ax, eq, "HB", "V", measure, scale=draw.DEG)
            if load["hopf_V"] is not None and not any(
                    branches.labelled_points(b, "HB") for b in eq):   # located by a scan
                draw.mark(ax, load["hopf_V"], 0.0, "HB")
            draw.mark_specials(ax, po, "V", measure, scale=draw.DEG)
            ax.set_title(f"({'ab'[col]}{row + 1}) $F_z^*$ = {Fstar:g}")
            ax.set_ylabel(f"{name} amplitude [deg]")
            ax.set_xlim(0, 600)
            ax.axvspan(0, 80, color=draw.palette.SHADE, zorder=0)
        axes[1][col].set_xlabel("V [m/s]")
    operating = Patch(color=draw.palette.SHADE, label="operating region, V ≤ 80 m/s")
    draw.legend(axes[0][0], extra=[operating], axes=axes.ravel(), loc="upper left")
    draw.figure_title(fig, "Fig. 7: zero freeplay, diagrams in V")
    fig.tight_layout()
    draw.save(fig, "fig07")


if __name__ == "__main__":
    jobs.run_figure("fig07", compute, plot)
