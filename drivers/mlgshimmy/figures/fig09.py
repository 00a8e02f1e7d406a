"""Fig. 9: the zero-freeplay Hopf curve in the (V, F*) plane, F* in [0, 3.5],
continued from the Hopf point of straight rolling at F* = 1."""
import matplotlib.pyplot as plt

from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import draw
from mlgshimmy.shared import geometry
from mlgshimmy.shared import jobs
from mlgshimmy.shared import paths

FSTAR_RANGE = (0.1, 3.5)   # below F* ~ 0.1 the curve leaves V <= 600 m/s steeply


def compute(parameter_set="figures", where="fig09"):
    """{"curves": stored Hopf-curve branches, "ends": [(F*, V)] of their UZ ends}."""
    rundir = paths.rundir(where)
    start = ct.Start(parameter_set, Fstar=1.0, V=geometry.start_speed(), **geometry.parameters())
    eq = ct.equilibria(rundir, "eq", start, stop={"V": 600.0}, expect=["HB"])
    curves = []
    for direction, ds in (("up", 0.01), ("down", -0.01)):
        curves.append(ct.hopf_curve(rundir, f"hopf_{direction}", eq("HB1"), DS=ds,
                                    stop={"Fstar": list(FSTAR_RANGE)},
                                    expect=["UZ"]))
    return {"curves": [jobs.stored(c, ("V", "Fstar")) for c in curves],
            "ends": [(p["Fstar"], p["V"]) for c in curves for p in c("UZ")]}


def plot(result):
    for Fstar, V in result["ends"]:
        print(f"fig09: Hopf curve end F* = {Fstar:.3f} at V = {V:.2f} m/s")
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for curve in result["curves"]:
        for branch in jobs.loaded(curve):
            ax.plot(branch["V"], branch["Fstar"], color="tab:blue", lw=1.6)
    ax.text(495, 2.2, "H", color="tab:blue")
    ax.axvline(80.0, color="k", ls="--", lw=1)
    ax.text(40, 3.3, "operating\nregion", ha="center", fontsize=8)
    ax.text(450, 0.4, "torsional shimmy", ha="center", fontsize=8)
    ax.text(230, 1.6, "stable straight rolling", ha="center", fontsize=8)
    ax.set_xlim(0, 600)
    ax.set_ylim(0, 3.5)
    ax.set_xlabel("V [m/s]")
    ax.set_ylabel("$F_z^*$")
    ax.set_title("Fig. 9: Hopf curve, zero freeplay")
    draw.save(fig, "fig09")


if __name__ == "__main__":
    jobs.run_figure("fig09", compute, plot)
