"""Fig. 12: V = 50 m/s, +-1 mm of freeplay (epsilon = 0.1 y_fp), F* in
[0, 3.5]: straight rolling with its two pitchforks, the stationary non-zero
yaw branches between them, the Hopf point and the periodic orbits born
there; panels torsional amplitude (with the freeplay boundary
psi_fp = y_fp / r_tlk(eta*) in grey) and frequency.  Also a_12 and b_12: the
loads at V = 50 between which stable straight rolling coexists with stable
torsional shimmy, separated by the unstable orbits.
`fig12.py --strut-variant 1` does the same with the printed strut spring
(build/fig12_v1/, build/figures/fig12_v1.*)."""
from __future__ import annotations

from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D
import numpy
from numpy.typing import ArrayLike

from mlgshimmy.shared import runerror
from mlgshimmy.shared import branches
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import doubling
from mlgshimmy.shared import draw
from mlgshimmy.shared import gear
from mlgshimmy.shared import jobs
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import naming
from mlgshimmy.shared import paper
from mlgshimmy.shared import paths
from mlgshimmy.shared import stationary

# What make, make help, make submit and the report know of this figure
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "fig12": {
        "help": "Fig. 12: V = 50 m/s: pitchforks, yawed states, orbits in F*",
        "time": "20 s",
        "regress": True,
        "report": ("V = 50 m/s, diagram in F*: two pitchforks with stationary yawed states "
                   "between them, a Hopf point, orbits with stable low- and high-frequency "
                   "segments; bistability for F* in (a_12, b_12), values the paper withholds "
                   "(IV.C)."),
        # values the paper replaces by symbols: our quantity -> its symbol
        "held_out": {"a_12": "a_12", "b_12": "b_12"},
    },
    "fig12_v1": {
        "help": "Fig. 12 with the printed strut stage order",
        "time": "20 s",
        "options": "--strut-variant 1",
        "report": ("Fig. 12 with the strut spring's stage order as printed (strut variant 1; "
                   "docs/model.md)."),
    },
}

DEG = draw.DEG
COLUMNS = ("Fstar", "psi_amp", "psi_mean", "freq")
F_MIN, F_MAX = 0.02, 3.5
VALUES = dict(V=50.0, yfp=1.0, eps_rel=0.1)


def runs(parameter_set: str = "figures", where: str = "fig12",
         variant: int = 0) -> Tuple[Any, List[Dict[str, Any]], List[Any], List[Tuple[Any, Any]]]:
    """(stationary states, Hopf points named by their mode (shared.naming),
    orbit runs, [(PD point, run)] of the period-doubled orbits from them)."""
    rundir = paths.rundir(where)
    values = {**VALUES, "strut_variant": float(variant), **gear.parameters()}
    # The printed strut (variant 1) folds straight rolling twice in F* while
    # eta crosses its 1e-5 m stage switch (F* 0.63-0.70): steps must shrink
    # below AUTO's default DSMIN of 1e-5 there (constants/runs/c.stage_switch).
    steps = {"overlay": "stage_switch"} if variant else {}
    found = stationary.states(rundir, parameter_set, (F_MIN, F_MAX), steps, **values)
    if stationary.symmetric(values) and not found.pitchforks:
        raise runerror.RunError(f"{where}: straight rolling of the symmetric gear has no "
                                f"pitchfork (BP) in F* = {F_MIN}-{F_MAX}")
    state = rolling_states(found)
    # the orbits from each Hopf point, across the others (continuation.follow_orbits;
    # gap in F*: at rho = mu = 10 deg those from H1 collapse at H2, 0.055 above,
    # and 0.01 before it they have not yet shrunk to SHRUNK of their largest)
    diagram = ct.speed_diagram(rundir, parameter_set, values, numpy.linspace(F_MIN, F_MAX, 1000),
                               parameter="Fstar", gap=1e-3, figure=where, state=state, DS=0.002,
                               DSMAX=0.02, NMX=3000, **steps)
    orbits = diagram.branches
    doubled = doubling.follow(rundir, "pd", orbits, "Fstar", (F_MIN, F_MAX), DS=0.002,
                              DSMAX=0.02, NMX=3000, **steps)
    return found, diagram.named, orbits, doubled


def rolling_states(found: Any) -> Any:
    """None at the symmetric gear (Newton from psi = 0 finds straight
    rolling), else the states of its branch (stationary.rolling_state):
    with side-stay angles Newton from psi = 0 stalls or lands on the
    other branch at light load."""
    return None if stationary.symmetric(found.values) else found.rolling_state


def stable_from(found: Any, hopf: Sequence[float]) -> float:
    """The load from which straight rolling is stable up to the first Hopf
    point: its last pitchfork (symmetric gear) or fold below it, else the
    lowest load (with side-stay angles the branch from light load is the
    smooth side of the imperfect pitchforks and stays stable)."""
    below = [F for F, _, d in found.folds() if d is found.straight and F < hopf[0]]
    return max(found.pitchforks + below, default=F_MIN)


def bistable_interval(lower: float, hopf: Sequence[float],
                      orbits: Sequence[Any]) -> Tuple[Optional[float], Optional[float]]:
    """(a_12, b_12): the loads where straight rolling is stable (from
    `lower` to the Hopf point) and a stable orbit coexists with it,
    separated from it by unstable orbits.  The orbit branch leaves the Hopf
    point stable (low frequency); the stable orbits that coexist with stable
    straight rolling are on its later stable segments."""
    upper = hopf[0]
    pieces = [piece for diagram in orbits for branch in diagram
              for piece in branches.segments(branch, "Fstar", "psi_amp")]
    coexisting = [min(xs) for xs, _, stable in pieces[1:] if stable]
    separating = [max(xs) for xs, _, stable in pieces if not stable]
    if not coexisting or not separating:
        return None, None
    return max(lower, min(coexisting)), min(upper, max(separating))


def loads_of(named: Sequence[Mapping[str, Any]]) -> List[float]:
    """The loads of the named Hopf points, in order."""
    return [p["Fstar"] for p in named]


def numbers(found: Any, named: Sequence[Mapping[str, Any]],
            orbits: Sequence[Any]) -> Dict[str, Optional[float]]:
    hopf = loads_of(named)
    out = {f"pitchfork {k + 1} F*": f for k, f in enumerate(found.pitchforks)}
    if not gear.current().symmetric:
        # the baseline's pitchforks (its column) beside the folds they became
        out.update({f"pitchfork {k + 1} F*": None for k in range(2)})
        out.update({f"stationary fold F{k + 1} F*": F for k, (F, _, _) in enumerate(found.folds())})
    out.update({f"{p['name']} F*": p["Fstar"] for p in named})
    folds = [p["Fstar"] for diagram in orbits for p in diagram("LP")]
    out.update({f"fold {k + 1} F*": f for k, f in enumerate(folds)})
    if orbits:
        out["orbits: lowest F* (turning point)"] = min(min(b["Fstar"]) for d in orbits
                                                       for b in d)
    a12, b12 = bistable_interval(stable_from(found, hopf), hopf, orbits)
    out.update({"a_12": a12, "b_12": b12})
    return out


def bounds_meaning(found: Any, hopf: Sequence[float],
                   numbers: Mapping[str, Optional[float]]) -> List[str]:
    """What a_12 and b_12 are at this gear, as lines under the table: at the
    paper's gear a pitchfork of straight rolling and the Hopf point; at a
    side-stay geometry the pitchfork has become a fold of the stationary
    states, or the stable orbits begin at their own turning point."""
    a12, b12 = numbers["a_12"], numbers["b_12"]
    if a12 is None:
        return ["a_12, b_12: no stable orbit coexists with stable straight rolling here"]
    lower = stable_from(found, hopf)
    same = abs(a12 - lower) <= 1e-12 * max(1.0, lower)
    if same and lower in found.pitchforks:
        a_is = "the last pitchfork of straight rolling (as in the paper)"
    elif same and lower != F_MIN:
        a_is = "a fold of the stationary states (the pitchfork at the paper's gear)"
    elif same:
        a_is = "the lightest load computed (straight rolling is stable from there)"
    else:
        a_is = "the turning point of the orbits, where the stable shimmy begins"
    b_is = "the Hopf point of straight rolling" if abs(b12 - hopf[0]) <= 1e-12 * hopf[0] \
        else "where the unstable orbits that separate the two attractors end"
    return [f"a_12 = {a12:.4g}: {a_is}", f"b_12 = {b12:.4g}: {b_is}"]


def freeplay_boundary(parameter_set: str, loads: ArrayLike, variant: int = 0,
                      state: Optional[Callable[[float], Any]] = None) -> numpy.ndarray:
    """psi_fp = y_fp / r_tlk(eta*) [rad] along straight rolling (state(F*):
    its state, as for runs)."""
    out = []
    for F in loads:
        model = mlgmodel.Model(parameter_set, Fstar=F, strut_variant=variant, **VALUES,
                               **gear.parameters())
        u = state(F) if state else model.equilibrium()
        out.append(1e-3 * VALUES["yfp"] / model.r_tlk(u["eta"]))
    return numpy.array(out)


def compute(name: str = "fig12", variant: int = 0,
            parameter_set: str = "figures") -> Dict[str, Any]:
    found, hopf, orbits, doubled = runs(parameter_set, name, variant)
    loads = numpy.linspace(F_MIN, F_MAX, 200)
    out = numbers(found, hopf, orbits)
    return {"name": name, "variant": variant, "numbers": out,
            "about": ([f"{p['name']}: {p['about']}" for p in hopf]
                      + ([naming.agreement(hopf)] if hopf else [])
                      + (doubling.describe("Fstar", doubled) if orbits else [])
                      + (bounds_meaning(found, loads_of(hopf), out) if hopf else [])),
            "hopf_names": [p["name"] for p in hopf],
            "eq": jobs.stored(found.straight, COLUMNS),
            "pitchforks": found.pitchforks, "hopf": loads_of(hopf),
            "folds": [(F, psi) for F, psi, _ in found.folds()],
            "yaw": [jobs.stored(d, COLUMNS) for d in found.yawed],
            "orbits": [jobs.stored(d, COLUMNS) for d in orbits],
            "doubled": [jobs.stored(run, COLUMNS) for _, run in doubled],
            "boundary": (loads, freeplay_boundary(parameter_set, loads, variant,
                                                  rolling_states(found)))}


def plot(result: Mapping[str, Any]) -> None:
    paper.report(result["name"], result["numbers"], notes=result["about"])
    eq, pitchforks, hopf = jobs.loaded(result["eq"]), result["pitchforks"], result["hopf"]
    yaw = [jobs.loaded(d) for d in result["yaw"]]
    orbits = [jobs.loaded(d) for d in result["orbits"]]
    doubled = [jobs.loaded(d) for d in result.get("doubled", [])]
    fig, (amp, freq) = plt.subplots(2, 1, figsize=(8, 8.4), sharex=True)
    loads, boundary = (numpy.asarray(a) for a in result["boundary"])
    boundary = boundary * DEG
    amp.plot(loads, boundary, color=draw.palette.GUIDE, lw=3, zorder=1)
    amp.plot(loads, -boundary, color=draw.palette.GUIDE, lw=3, zorder=1)
    draw.plot_branch(amp, eq, "Fstar", "psi_amp", scale=DEG)
    shown = [boundary, -boundary]
    # with side-stay angles straight rolling is yawed too: drawn as a stationary state
    for diagram in yaw + ([] if gear.current().symmetric else [eq]):
        for branch in diagram:
            for xs, ys, stable in branches.segments(branch, "Fstar", "psi_mean"):
                amp.plot(xs, ys * DEG, **{**draw.style_of(stable), "linestyle": YAW[stable]})
                shown.append(ys * DEG)
    names = {ax: iter(f"S{k + 1}" for k in range(100)) for ax in (amp, freq)}
    for diagram in orbits:
        draw.plot_branch(amp, diagram, "Fstar", "psi_amp", scale=DEG)
        draw.plot_branch(freq, diagram, "Fstar", "freq")
        for ax, column, scale in ((amp, "psi_amp", DEG), (freq, "freq", 1.0)):
            for branch in diagram:
                for index, _, _ in branches.labelled_points(branch, "LP"):
                    draw.mark(ax, branch["Fstar"][index], branch[column][index] * scale, "LP",
                              name=next(names[ax]))
            draw.mark_specials(ax, diagram, "Fstar", column, scale=scale, kinds=("TR", "PD"))
        shown += [branch["psi_amp"] * DEG for branch in diagram]
    for diagram in doubled:   # twice the period: half the frequency of the orbits they leave
        draw.plot_branch(amp, diagram, "Fstar", "psi_amp", scale=DEG, color=DOUBLED)
        draw.plot_branch(freq, diagram, "Fstar", "freq", color=DOUBLED)
        for ax, column, scale in ((amp, "psi_amp", DEG), (freq, "freq", 1.0)):
            draw.mark_specials(ax, diagram, "Fstar", column, scale=scale, kinds=("TR", "PD"))
        shown += [branch["psi_amp"] * DEG for branch in diagram]
    for k, f in enumerate(pitchforks):
        draw.mark(amp, f, 0, "BP", name=f"P{k + 1}")
    for k, (f, psi) in enumerate(result.get("folds", [])):
        draw.mark(amp, f, psi * DEG, "LPeq", name=f"F{k + 1}")
    for f, name in zip(hopf, result["hopf_names"]):
        draw.mark(amp, f, 0, "HB", name=name)
        for diagram in orbits:   # the orbit branch born there starts at its frequency
            start = diagram[0]
            if abs(start["Fstar"][0] - f) < 1e-6 * max(1.0, abs(f)):
                draw.mark(freq, f, start["freq"][0], "HB", name=name)
    # the data set the range: the orbits, the yawed states and the boundary
    low = min(numpy.nanmin(y) for y in shown)
    high = max(numpy.nanmax(y) for y in shown)
    pad = 0.06 * (high - low)
    amp.set_ylim(low - pad, high + pad)
    amp.set_ylabel(r"$\psi$ amplitude; yaw of stationary states [deg]")
    amp.set_title("(a) torsional amplitude")
    extra = [Line2D([], [], color=draw.STABLE, ls=YAW[True], label="stationary yaw, stable"),
             Line2D([], [], color=draw.UNSTABLE, ls=YAW[False], label="stationary yaw, unstable"),
             Line2D([], [], color=draw.palette.GUIDE, lw=3,
                    label=r"freeplay boundary $\pm\psi_{fp}$")]
    if doubled:
        extra.append(Line2D([], [], color=DOUBLED, label="orbits of twice the period, from PD"))
    freq.set_ylabel("frequency [Hz]")
    freq.set_xlabel(r"$F_z^*$")
    freq.set_title("(b) frequency")
    freq.set_xlim(0, F_MAX)
    draw.figure_title(fig, r"Fig. 12: V = 50 m/s, $y_{fp}$ = 1 mm, $\epsilon$ = 0.1 mm; "
                           + draw.STRUT_ORDER[result["variant"]])
    fig.tight_layout()
    draw.legend(fig, extra=extra)   # below the panels
    draw.save(fig, result["name"])


YAW = {True: "-.", False: ":"}   # line styles of the stationary yawed states
DOUBLED = draw.palette.DOUBLED       # the period-doubled orbits: neither stability colour


if __name__ == "__main__":
    jobs.run_variant_figure("fig12", __doc__.splitlines()[0], compute, plot)
