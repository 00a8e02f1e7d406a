"""Fig. 11 drawn from its cached result."""
import numpy

from mlgshimmy.figures.fig11.ends import JOIN_LABELS, SWITCH_WIDTHS
from mlgshimmy.figures.fig11.plane import F_MAX, SLICES, V_MAX
from mlgshimmy.figures.fig11.regions import shade
from mlgshimmy.shared import jobs
from mlgshimmy.shared import paper

STYLES = {"hopf": ("k-", "Hopf (y_fp = 1 mm)"), "fold": ("b--", "fold of periodic orbits"),
          "zero": ("k:", "Hopf, zero freeplay")}


def plot(result):
    # matplotlib is loaded here only: each of the ~40 part jobs would spend
    # 0.5 s loading it
    import matplotlib.pyplot as plt
    from mlgshimmy.shared import draw
    region = result["region_map"]
    found = numpy.asarray(region["code"])
    fig, ax = plt.subplots(figsize=(8, 6.5))
    handles = []
    for kind, (style, label) in STYLES.items():
        for diagram in result["curves"][kind]:
            for branch in jobs.loaded(diagram):
                ax.plot(branch["V"], branch["Fstar"], style, lw=1.4)
        handles.append(plt.Line2D([], [], color=style[0], ls=style[1:], label=label))
    for f in result["pitchfork"][1]:
        ax.axhline(f, color="g", lw=1.4, ls="-.")
    if result["pitchfork"][1]:
        handles.append(plt.Line2D([], [], color="g", ls="-.", label="pitchfork"))
    for f in result.get("stationary_folds", []):
        ax.axhline(f, color="g", lw=1.4, ls=":")
    if result.get("stationary_folds"):
        handles.append(plt.Line2D([], [], color="g", ls=":", label=(
            "fold of yawed equilibria (the imperfect\npitchforks of the gear with side-stay angles)")))
    for diagram in result["curves"]["torus"]:
        for branch in jobs.loaded(diagram):
            ax.plot(branch["V"], branch["Fstar"], color="m", lw=1.4)
    handles.append(plt.Line2D([], [], color="m", label="torus (Neimark-Sacker) curve:\n"
                              "large orbit loses stability, quasi-periodic\nshimmy beyond "
                              "(AUTO, ISW = 2)"))
    for diagram in result["curves"].get("tongue", []):
        for branch in jobs.loaded(diagram):
            ax.plot(branch["V"], branch["Fstar"], color="m", lw=1.2, ls="--")
    if result["curves"].get("tongue"):
        handles.append(plt.Line2D([], [], color="m", ls="--", label=(
            "torus curve of another Floquet pair: edge of a\n"
            "tongue where the large orbit is unstable (AUTO)")))
    for point in result["torus_points"]:
        ax.plot(point["V"], point["Fstar"], "o", mfc="none", mec="m", ms=5)
    if result["torus_points"]:
        handles.append(plt.Line2D([], [], color="m", marker="o", mfc="none", ls="",
                                  label="tongue torus points on no continued\n"
                                        "curve (located on diagrams in V)"))
    lift = [c for c in result["edge_curves"] if c["kind"] == "liftoff"]
    if lift:
        V, F = numpy.array(result["liftoff"]["points"]).T
        ax.plot(lift[0]["V"], lift[0]["Fstar"], color="navy", lw=1.4)
        ax.plot(V, F, "o", color="navy", ms=3)
        handles.append(plt.Line2D([], [], color="navy", marker="o", ms=3, label=(
            f"wheel lift-off within {result['liftoff']['t_end']:g} s from straight\n"
            "rolling (bisection in V and on V = 600 in F*)")))
    for kind, colour in (("hopf", "k"), ("hopf_elsewhere", "0.5"), ("tongue", "m")):
        joins = [j for j in result["mx_joins"] if j["kind"] == kind]
        for join in joins:
            ax.plot(join["V"], join["Fstar"], "o", color=colour, ms=4)
        if joins:
            handles.append(plt.Line2D([], [], color=colour, marker="o", ms=4, ls="",
                                      label=JOIN_LABELS[kind]))
    switch_ends = result.get("stage_switch_ends", [])
    if switch_ends:
        for f in result["stage_switch"]:
            ax.axhline(f, color="0.45", lw=0.7)
        for stop in switch_ends:
            ax.plot(stop["V"], stop["Fstar"], "D", mfc="none", mec="k", ms=5)
        handles.append(plt.Line2D([], [], color="0.45", lw=0.7, marker="D", mfc="none",
                                  mec="k", ms=5, label=(
            f"oleo stage switch (|eta* - eta_s| < {SWITCH_WIDTHS:g}/k_stage)\n"
            "and where AUTO stops a curve inside it")))
    for stop in result.get("generalised_hopf_ends", []):
        ax.plot(stop["V"], stop["Fstar"], "*", color="b", ms=8)
    if result.get("generalised_hopf_ends"):
        handles.append(plt.Line2D([], [], color="b", marker="*", ls="", ms=8,
                                  label="a fold curve ends on the Hopf locus (generalised\n"
                                        "Hopf point: its orbits shrink to straight rolling)"))
    for stop in result.get("on_fold_ends", []):
        ax.plot(stop["V"], stop["Fstar"], "^", mfc="none", mec="m", ms=6)
    if result.get("on_fold_ends"):
        handles.append(plt.Line2D([], [], color="m", marker="^", mfc="none", ls="", ms=6,
                                  label="a torus curve ends on a fold curve (its Floquet\n"
                                        "pair meets the fold's multiplier 1)"))
    for stop in result.get("liftoff_ends", []):
        ax.plot(stop["V"], stop["Fstar"], "s", mfc="none", mec="navy", ms=5)
    if result.get("liftoff_ends"):
        handles.append(plt.Line2D([], [], color="navy", marker="s", mfc="none", ls="", ms=5,
                                  label="a curve ends at the lift-off edge\n"
                                        "(AUTO stops; the wheel lifts off beyond)"))
    for stop in result["mx_stops"]:
        ax.plot(stop["V"], stop["Fstar"], "rx", ms=8)
    if result["mx_stops"]:
        handles.append(plt.Line2D([], [], color="r", marker="x", ls="",
                                  label="continuation stopped (MX)"))
    patches = shade(ax, found)
    ax.legend(handles=handles + patches, fontsize=7, loc="upper left",
              bbox_to_anchor=(1.01, 1.0), framealpha=0.9)
    ax.set_xlim(0, V_MAX)
    ax.set_ylim(0, F_MAX)
    ax.set_xlabel("V [m/s]")
    ax.set_ylabel(r"$F_z^*$")
    draw.figure_title(ax, r"Fig. 11: $y_{fp}$ = 1 mm, $\epsilon$ = 0.1 mm; regions bounded by the "
                          "curves, labelled from diagrams in V at "
                          f"F* = {SLICES[0]:g}, {SLICES[1]:g}, ..., {SLICES[-1]:g}", fontsize=8)
    draw.save(fig, "fig11")
    paper.report("fig11", result["numbers"])
