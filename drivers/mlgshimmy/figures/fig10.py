"""Fig. 10: F* = 1 with +-1 mm of torque-link freeplay (epsilon = 0.1 y_fp),
V in [0, 600]: straight rolling and its Hopf points, the low-frequency
orbits between the two low-speed Hopf points, the high-frequency orbits from
the third with their fold S, and the zero-freeplay orbits for reference.
Panels: torsional amplitude (with a zoom on small amplitudes) and frequency."""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D

from mlgshimmy.shared import runerror
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
    "fig10": {
        "help": "Fig. 10: y_fp = 1 mm, F* = 1: three Hopf points, orbits, fold",
        "time": "40 s",
        "regress": True,
        "report": ("F* = 1 with +-1 mm of freeplay: Hopf points at 1.5, 28.1 and 142.5 m/s, "
                   "low-frequency orbits between the first two, high-frequency orbits with a "
                   "fold S at 41.5 m/s; bistability for V in (41.5, 142.5) (IV.B)."),
        "paper": {"H1 [m/s]": 1.5, "H2 [m/s]": 28.1, "H3 [m/s]": 142.5, "S1 [m/s]": 41.5},
    },
}

DEG = draw.DEG
V_MAX = ct.V_MAX
COLUMNS = ("V", "psi_amp", "freq")
FREEPLAY = {"Fstar": 1.0, "yfp": 1.0, "eps_rel": 0.1}   # the figure's conditions
HIGH_HZ = naming.HIGH_HZ   # Hz: the high-frequency orbits
# the table's words for the ends of a branch (domain.stop_reason)
ENDS = {domain.LIFT_OFF: "wheel lift-off",
        domain.SADDLES: "a saddle connection (period unbounded)"}


def numbers(diagram: Any, points: Sequence[Mapping[str, Any]]) -> Dict[str, Optional[float]]:
    """The special points of Fig. 10 as {quantity: value}: the Hopf points
    by name (points: the diagram's named points), the folds S1, S2, ... of the
    high-frequency orbits (>= HIGH_HZ; S1 is the paper's S), the folds of
    the low-frequency ones, and where a branch ends at a wheel's lift-off or
    a connection of saddles, or stopped with no convergence (an orbit branch that shrinks onto straight
    rolling at a Hopf point ends there: no row)."""
    out = {f"{p['name']} [m/s]": p["V"] for p in points}
    out.update({f"{name} [m/s]": V for name, V in naming.fold_names(
        [(V, run(lab)["freq"]) for run, lab, V, _ in diagram.folds()])})
    for name, (_, run) in zip(diagram.names, diagram.parts):   # runs kept up to an MX
        stops = [p for p in run("MX") if p["psi_amp"] > ct.COLLAPSED]   # not a Hopf bubble
        for k, point in enumerate(stops):
            why = domain.stop_reason(point)
            out[(f"{name}: ends at {ENDS[why]} at V [m/s]" if why in ENDS else
                 f"{name}: stops (MX, {why}) at V [m/s]") + (f" {k + 1}" if k else "")] = point["V"]
    return out


def stored(eq: Any, diagram: Any) -> Dict[str, Any]:
    """A diagram's branches for the cache: the orbit runs with their Hopf
    point (V, frequency 1/T)."""
    return {"eq": jobs.stored(eq, COLUMNS),
            "parts": [{"hopf": (point["V"], 1 / point["T"]), "orbits": jobs.stored(run, COLUMNS)}
                      for point, run in diagram.parts],
            "hopf": diagram.hopf}


def compute() -> Dict[str, Any]:
    """The figure (`figures` set, and zero freeplay for reference) and the
    numbers of the `table` set (its failure leaves that column empty)."""
    at = gear.parameters()    # the gear's changes ({} at the paper's)
    print("fig10: F* = 1, y_fp = 1 mm, eps = 0.1 mm (figures set)" + gear.suffix())
    eq, freeplay = ct.diagram_from_rest(paths.rundir("fig10"), "figures", **FREEPLAY, **at)
    print("fig10: zero freeplay, for reference")
    zero_eq, zero = ct.diagram_from_rest(paths.rundir("fig10/zero"), "figures", Fstar=1.0,
                                         yfp=0.0, **at)
    print("fig10: the same with the `table` set, for its numbers")
    try:
        diagram = ct.diagram_from_rest(paths.rundir("fig10/table"), "table", allow_failed=True,
                                       **FREEPLAY, **at)[1]
        table = numbers(diagram, diagram.named)
    except (runerror.RunError, RuntimeError) as exc:
        print(f"fig10: the `table` set stops, its column stays empty: {getattr(exc, 'brief', exc)}")
        table = {}
    points = freeplay.named
    # V_crit: where zero freeplay loses stability (the paper's 346.1 m/s, Fig. 7)
    crit = {"V_crit (zero freeplay) [m/s]": zero.hopf[0][0]} if zero.hopf else {}
    return {"freeplay": stored(eq, freeplay), "zero": stored(zero_eq, zero),
            "numbers": {**numbers(freeplay, points), **crit}, "numbers_table": table,
            "hopf_points": points, "zero_hopf_points": zero.named[:1]}


def closure(orbits: Sequence[Any], hopf: Sequence[Tuple[float, float]], column: str,
            scale: float = 1.0) -> Optional[Tuple[List[float], List[float]]]:
    """The line from the last stored orbit of a branch to the Hopf point it
    collapses onto, as ([V, V_H], [y, y_H]), or None: the driver stops a
    branch 0.01 m/s (continuation.speed_diagram's gap) before the next
    Hopf point, where the amplitude still is sqrt(0.01 m/s) away from 0."""
    end = orbits[-1]
    V, amp = end["V"][-1], end["psi_amp"][-1]
    for v, f in hopf:
        if 0 < abs(v - V) < 0.05 and amp < 1e-3:
            return [V, v], [end[column][-1] * scale, (0.0 if column == "psi_amp" else f)]
    return None


def fold_name(numbers: Mapping[str, Optional[float]], V: float) -> Optional[str]:
    """The table's name of the fold at speed V ("S2", "L1" for the
    low-frequency fold 1), so that the figure and its table agree; None if
    the table has none there."""
    for quantity, value in numbers.items():
        if value is not None and abs(value - V) <= 1e-9 * max(1.0, abs(V)):
            if quantity.startswith("S"):
                return quantity.split()[0]
            if quantity.startswith("low-frequency fold"):
                return "L" + quantity.split()[2]
    return None


def plot(result: Mapping[str, Any]) -> None:
    points = result["hopf_points"]
    crit = result.get("zero_hopf_points", [])
    paper.report("fig10", result["numbers"], result["numbers_table"],
                 notes=[f"{p['name']}: {p['about']}" for p in points]
                 + [f"V_crit (zero freeplay): {p['about']}" for p in crit]
                 + ([naming.agreement(points + crit)] if points + crit else []))
    freeplay, zero = result["freeplay"], result["zero"]
    parts = [(point, jobs.loaded(part["orbits"])) for part in freeplay["parts"]
             for point in [part["hopf"]]]
    zero_orbits = [jobs.loaded(part["orbits"]) for part in zero["parts"]]
    hopf_names = [p["name"] for p in points]
    fig = plt.figure(figsize=(10, 7.4))
    grid = fig.add_gridspec(2, 2, width_ratios=(1.6, 1))
    amp, zoom, freq = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1]), \
        fig.add_subplot(grid[1, :])
    closing = []
    for ax, column, scale in ((amp, "psi_amp", DEG), (zoom, "psi_amp", DEG), (freq, "freq", 1.0)):
        for orbits in zero_orbits:
            draw.plot_branch(ax, orbits, "V", column, scale=scale, color=draw.palette.GUIDE)
        if column == "psi_amp":
            draw.plot_branch(ax, jobs.loaded(freeplay["eq"]), "V", column, scale=DEG)
        names = iter(f"S{k + 1}" for k in range(100))
        for _, orbits in parts:
            draw.plot_branch(ax, orbits, "V", column, scale=scale)
            for branch in orbits:
                for index, _, _ in branches.labelled_points(branch, "LP"):
                    V = branch["V"][index]
                    if any(abs(V - h) <= 1e-3 * abs(h) for h, _ in freeplay["hopf"]):
                        continue    # AUTO's spurious LP next to a Hopf point (Diagram.folds)
                    draw.mark(ax, V, branch[column][index] * scale, "LP",
                              name=fold_name(result["numbers"], V) or next(names))
            draw.mark_specials(ax, orbits, "V", column, scale=scale, kinds=("TR",))
            line = closure(orbits, freeplay["hopf"], column, scale)
            if line:
                ax.plot(*line, color=draw.STABLE, ls=":", lw=1.2)
                closing.append(ax)
        for (v, f), name in zip(freeplay["hopf"], hopf_names):
            draw.mark(ax, v, 0.0 if column == "psi_amp" else f, "HB", name=name)
        ax.set_xlabel("V [m/s]")
    for ax in (amp, zoom):
        ax.set_ylabel(r"$\psi$ amplitude [deg]")
    amp.set_xlim(0, V_MAX)
    amp.set_title("(a1) torsional amplitude")
    zoom.set_xlim(0, 160)
    zoom.set_ylim(-0.01, 0.3)
    zoom.set_title("(a2) zoom of (a1): small amplitudes")
    freq.set_xlim(0, V_MAX)
    freq.set_ylabel("frequency [Hz]")
    freq.set_title("(b) frequency")
    extra = [Line2D([], [], color=draw.palette.GUIDE,
                    label="zero freeplay (stable solid, unstable dashed)")]
    if closing:
        extra.append(Line2D([], [], color=draw.STABLE, ls=":", lw=1.2,
                            label="to its Hopf point (the run stops 0.01 m/s before it)"))
    draw.legend(freq, extra=extra, axes=(amp, zoom, freq), loc="lower right", ncol=2)
    draw.figure_title(fig, r"Fig. 10: $F_z^*$ = 1, $y_{fp}$ = 1 mm, $\epsilon$ = 0.1 mm")
    fig.tight_layout()
    draw.save(fig, "fig10")


if __name__ == "__main__":
    jobs.run_figure("fig10", compute, plot)
