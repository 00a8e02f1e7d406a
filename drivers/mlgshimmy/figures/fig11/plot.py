"""Fig. 11 drawn from its cached result: the regions by what the gear
settles on, the curves that bound them, a short legend in the reader's
words, and the rest (the reference curves, where each curve ends and why)
in a caption written beside the PNG, $MLG_RUN_ROOT/figures/fig11_caption.txt,
which the report shows under the figure."""
import os
from typing import Any, Dict, List, Sequence, Tuple

import numpy

from mlgshimmy.figures.fig11.ends import JOIN_LABELS, SWITCH_WIDTHS
from mlgshimmy.figures.fig11.plane import F_MAX, SLICES, V_MAX
from mlgshimmy.figures.fig11.regions import (PATTERNS, REGION_ALPHA, WORDS, fill_words,
                                             shade)
from mlgshimmy.shared import jobs
from mlgshimmy.shared import paper
from mlgshimmy.shared import paths
from mlgshimmy.shared.jobs.atomic import write_text

CAPTION = "fig11_caption.txt"
# the curves of the legend: (result["curves"] key, legend text, line style)
CURVES = (("hopf", "Hopf curve: straight rolling's stability changes", "-"),
          ("fold", "fold of shimmy orbits (S in Fig. 10)", "--"),
          ("torus", "torus curve: quasi-periodic shimmy beyond", "-"),
          ("tongue", "tongue edge: large shimmy unstable inside", "--"))
# where a curve ends inside the plane: (result key, join kind or None, why)
ENDS = (("mx_joins", "hopf", JOIN_LABELS["hopf"]),
        ("mx_joins", "hopf_elsewhere", JOIN_LABELS["hopf_elsewhere"]),
        ("mx_joins", "tongue", JOIN_LABELS["tongue"]),
        ("stage_switch_ends", None, "the curve stops inside the oleo's stage switch"),
        ("generalised_hopf_ends", None, "a fold curve ends on the Hopf curve (a generalised "
                                        "Hopf point: its orbits shrink to straight rolling)"),
        ("on_fold_ends", None, "a torus curve ends on a fold curve (its Floquet pair meets "
                               "the fold's multiplier 1)"),
        ("liftoff_ends", None, "the curve ends at the lift-off edge (a wheel lifts off beyond)"),
        ("orbit_switch_ends", None, "the curve stops where its orbit grazes the oleo's stage "
                                    "switch (its largest or smallest compression within "
                                    f"{SWITCH_WIDTHS:g} switch widths of it)"),
        ("mx_stops", None, "AUTO stopped the continuation (MX) for no reason found"))


def curve_colours(palette: Any) -> Dict[str, str]:
    """The colour of each curve kind of CURVES."""
    return {"hopf": palette.HOPF, "fold": palette.FOLD, "torus": palette.TORUS,
            "tongue": palette.TORUS}


def ends_found(result: Dict[str, Any]) -> List[Tuple[float, float, str]]:
    """[(V, F*, why)] of every curve end inside the plane that the result
    records, in ENDS' order."""
    out = []
    for key, kind, why in ENDS:
        for point in result.get(key, []):
            if kind is None or point["kind"] == kind:
                out.append((float(point["V"]), float(point["Fstar"]), why))
    return out


def caption(result: Dict[str, Any], ends: Sequence[Tuple[float, float, str]],
            marked: Sequence[str] = ()) -> str:
    """The caption: what the figure holds beyond its legend (marked: the
    legend texts of the special points named on the plot, draw.point_handles)."""
    lines = ["Fig. 11: the (V, F*) plane with ±1 mm of torque-link freeplay (y_fp = 1 mm, "
             "eps = 0.1 mm). Each region is labelled by what the gear settles on there, "
             f"found on diagrams in V at the loads F* = {SLICES[0]:g}, {SLICES[1]:g}, ..., "
             f"{SLICES[-1]:g}; where two attractors are named, a disturbance decides "
             "between them.", ""]
    if result["curves"].get("zero"):
        lines.append("- Grey dotted: the Hopf curve without freeplay (Fig. 9), for reference.")
    if result["pitchfork"][1] or result.get("stationary_folds"):
        lines.append("- Hatched, between the dash-dotted lines: stable yawed (off-centre) "
                     "rolling; the lines are the pitchforks where it begins and ends (with "
                     "side-stay angles, the folds of the yawed states).")
    if result["torus_points"]:
        lines.append("- Small open circles: torus points of the large shimmy found on the "
                     "diagrams in V that no continued tongue edge passes through.")
    if result.get("liftoff"):
        lines.append(f"- Lift-off edge: beyond it a wheel lifts off within "
                     f"{result['liftoff']['t_end']:g} s of a disturbed straight rolling "
                     "(simulated, bisected in V and on V = 600 m/s in F*).")
    if result.get("stage_switch_ends"):
        lines.append(f"- Thin grey lines: the oleo's stage switch, where straight rolling's "
                     f"strut compression is within {SWITCH_WIDTHS:g}/k_stage of the switch.")
    if marked:
        lines.append("- Special points, named on the plot: " + "; ".join(marked) + ".")
    if ends:
        lines += ["", "Where a curve ends inside the plane (the open diamonds), and why:"]
        lines += [f"- V = {V:.4g} m/s, F* = {F:.4g}: {why}" for V, F, why in ends]
    return "\n".join(lines) + "\n"


def plot(result: Dict[str, Any]) -> None:
    # matplotlib is loaded here only: each of the ~40 part jobs would spend
    # 0.5 s loading it
    import matplotlib.pyplot as plt
    from matplotlib.legend_handler import HandlerTuple
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    from mlgshimmy.shared import draw
    palette = draw.palette
    fig, ax = plt.subplots(figsize=(8, 6.5))
    fills, patterned = shade(ax, numpy.asarray(result["region_map"]["code"]))
    colours = curve_colours(palette)
    # a region beyond a curve that bounds it is named by the curve's entry
    # (its fill under the line): quasi-periodic shimmy beyond the torus curve,
    # lift-off beyond the lift-off edge
    beyond = {"torus": ("quasi",), "liftoff": ("liftoff",)}

    def entry(kind, line, text):
        fill = fills.pop(beyond.get(kind), None)
        if fill is None:
            return line, text
        return (Patch(facecolor=fill, alpha=REGION_ALPHA), line), f"{text} (shaded)"
    entries = []
    for kind, text, style in CURVES:
        diagrams = result["curves"].get(kind, [])
        for diagram in diagrams:
            for branch in jobs.loaded(diagram):
                ax.plot(branch["V"], branch["Fstar"], color=colours[kind], ls=style, lw=1.4)
        if diagrams:
            entries.append(entry(kind, Line2D([], [], color=colours[kind], ls=style, lw=1.4),
                                 text))
    for diagram in result["curves"].get("zero", []):
        for branch in jobs.loaded(diagram):
            ax.plot(branch["V"], branch["Fstar"], color=palette.GUIDE, ls=":", lw=1.2)
    for point in result["torus_points"]:
        ax.plot(point["V"], point["Fstar"], "o", mfc="none", mec=palette.TORUS, ms=4)
    if result.get("liftoff"):
        lift = [c for c in result["edge_curves"] if c["kind"] == "liftoff"]
        V, F = numpy.array(result["liftoff"]["points"]).T
        ax.plot(lift[0]["V"], lift[0]["Fstar"], color=palette.LIFTOFF, lw=1.6)
        ax.plot(V, F, "o", color=palette.LIFTOFF, ms=2.5)
        entries.append(entry("liftoff", Line2D([], [], color=palette.LIFTOFF, lw=1.6),
                             "lift-off edge: a wheel lifts off beyond"))
    yawed = list(result["pitchfork"][1]) + list(result.get("stationary_folds", []))
    for f in yawed:
        ax.axhline(f, color=palette.PITCHFORK, lw=1.0, ls="-.")
    if result.get("stage_switch_ends"):
        for f in result["stage_switch"]:
            ax.axhline(f, color=palette.GUIDE, lw=0.6)
    ends = ends_found(result)
    for V, F, _ in ends:
        ax.plot(V, F, "D", mfc=palette.OPEN, mec=palette.NEUTRAL, ms=4.5, zorder=6)
    # special points marked with draw.mark (e.g. codimension-two points on
    # the curves) are named on the plot, and what the names mean in the caption
    for point in result["codim2"]:
        draw.mark(ax, point["V"], point["Fstar"], point["type"])
    marked = [h.get_label() for h in draw.point_handles(draw.marked_kinds(ax))]
    ax.set_xlim(0, V_MAX)
    ax.set_ylim(0, F_MAX)
    ax.set_xlabel("V [m/s]")
    ax.set_ylabel(r"$F_z^*$")
    # the unfilled region (no shimmy: straight or yawed rolling, by its
    # pattern) is said in the regions' title, which keeps the legends to 10
    regions = [(Patch(facecolor=colour, edgecolor=palette.GUIDE, alpha=REGION_ALPHA),
                fill_words(kinds)) for kinds, colour in fills.items() if kinds]
    settles = "the gear settles on" + (f"\n(white: {fill_words(())})" if () in fills else "")
    regions += [(Patch(facecolor="none", edgecolor=palette.NEUTRAL, hatch=PATTERNS[kind]),
                 f"{'dotted' if kind == 'straight' else 'hatched'}: {WORDS[kind]} too")
                for kind in patterned]
    # figure legends, which the saved figure's bounds take in, beside the axes
    for items, title, corner, y in (
            (entries, "curves", "upper left", 1.0),
            (regions, settles, "lower left", 0.0)):
        fig.legend(*zip(*items), title=title, loc=corner, bbox_to_anchor=(1.02, y),
                   bbox_transform=ax.transAxes, handler_map={tuple: HandlerTuple(ndivide=1)})
    draw.figure_title(ax, r"Fig. 11: $y_{fp}$ = 1 mm, $\epsilon$ = 0.1 mm: what the gear "
                          "settles on, and the curves that bound it")
    write_text(os.path.join(paths.figures_dir(), CAPTION), caption(result, ends, marked))
    draw.save(fig, "fig11")
    paper.report("fig11", result["numbers"], notes=result["codim2_notes"])
