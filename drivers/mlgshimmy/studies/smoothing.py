"""The smoothing error: how far the smoothed freeplay law (eq. 15, or the
gear's law, FREEPLAY=) puts the answers from those of the non-smooth eq.
(14), against eps / y_fp, with the fitted order of convergence set against
the predicted one (docs/model.md 9.3).  Fig. 10's case, F* = 1, y_fp = 1 mm.

- H1, H2, H3 of straight rolling: eigenvalue scans in V (no AUTO); in the
  limit straight rolling lies inside the gap, where eq. (14) is smooth.
  Predicted by the law's stiffness at y = 0 (PREDICTED): order 3 for eq.
  (15), (4 / 3 pi) (eps / y_fp)^3 k_tlk; exponentially small for tanh;
  none at all for cubic and hertz, zero inside |y| < y_fp - eps.
- The stable high-frequency orbit at SPEEDS: psi amplitude and frequency
  by time simulation, eq. (14) with every switch located (mlg_simulate).
  Predicted order 2 where the force error (at most ~k_tlk eps) is confined
  to a band of width ~eps that the orbit crosses transversally; 1 for
  hertz, whose ramp shifts the whole contact line by k_tlk eps / 3.
- The fold S of those orbits, by simulation (simulator.fold_speed: whether
  the orbit survives 80 s, bisected in V to 1e-3 m/s; low by about 1e-3
  m/s, the slow passage past the fold).  The orbit there still crosses the
  corners transversally: the same orders as the orbits.

    make smoothing          # compute (about 6 min) and write the table
    make smoothing-plot     # redraw from the cache
"""
from typing import Dict, Optional

from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import convergence, freeplay, gear, jobs, mlgmodel, naming, paths
from mlgshimmy.shared import simulator

DECLARED = {
    "smoothing": {
        "help": "eq. (15) (or FREEPLAY=) against eq. (14): H1-H3, orbits, S, fitted orders",
        "time": "5 min",
        "report": {
            "command": "make smoothing",
            "text": ("The smoothing error of eq. (15) against the non-smooth eq. (14) by "
                     "eps / y_fp: H1-H3, the stable orbit's amplitude and frequency and "
                     "the fold S, with fitted orders."),
            "tables": ["tables/smoothing.txt"],
            "figures": ["figures/smoothing.png"],
        },
    },
}
FIGURE = "smoothing"
RATIOS = (1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01)      # eps / y_fp
ASYMPTOTIC = 0.2                                       # the fit uses eps / y_fp <= this
CASE = {"Fstar": 1.0, "yfp": freeplay.NOMINAL["yfp"], "eps_abs": 0.0}
SPEEDS = (60.0, 100.0, 140.0)      # m/s, between S and H3: the stable high-frequency orbit
# 16 s from psi = 0.01 rad; the settled orbit sampled every 10 us over the last
# second (the amplitude's sampling error below 3e-7), at CVODE rtol 1e-10
SIMULATION = ("--t-end", 16, "--dt-out", 1e-5, "--psi0", 0.01, "--rtol", 1e-10,
              "--atol", 1e-12)
# below these relative errors a difference is noise (round-off; the sampling)
FLOOR = {"hopf": 1e-10, "orbit": 1e-6, "fold": 1e-4}
PREDICTED = {"atan": {"hopf": "3", "orbit": "2", "fold": "2"},
             "tanh": {"hopf": "exp.", "orbit": "2", "fold": "2"},
             "cubic": {"hopf": "exact", "orbit": "2", "fold": "2"},
             "hertz": {"hopf": "exact", "orbit": "1", "fold": "1"}}
FOLD_BRACKET, FOLD_TOL = (30.0, 45.0), 1e-3     # m/s: S of Fig. 10 is 41.5


def law() -> int:
    """The gear's freeplay law, which must be a smoothed one."""
    chosen = gear.current().law()
    if chosen == mlgmodel.LAWS.index("nonsmooth"):
        raise ValueError("smoothing: FREEPLAY=nonsmooth is the limit itself: choose a "
                         "smoothed law")
    return chosen


def values(ratio: Optional[float]) -> Dict[str, float]:
    """The model at eps = ratio y_fp, or eq. (14) for None."""
    law14 = mlgmodel.LAWS.index("nonsmooth")
    return {**gear.parameters(), **CASE, "eps_rel": ratio if ratio else 0.0,
            "freeplay_law": law14 if ratio is None else law()}


def answers(ratio: Optional[float]) -> Dict[str, Optional[float]]:
    """{quantity: value} at one smoothing (None: the limit)."""
    model = values(ratio)
    hopf = naming.scanned("figures", "V", ct.SPEED_SCAN, **model)
    out = {f"{name} [m/s]": hopf.get(name) for name in ("H1", "H2", "H3")}
    for speed in SPEEDS:
        orbit = simulator.simulate(None, "--V", speed, *SIMULATION, params=model)
        out[f"psi amplitude at {speed:g} m/s [rad]"] = orbit["psi_amplitude_rad"]
        out[f"frequency at {speed:g} m/s [Hz]"] = orbit["frequency_hz"]
        print(f"smoothing: eps/y_fp = {ratio if ratio else 0:g}, V = {speed:g} m/s: "
              f"psi amplitude {orbit['psi_amplitude_rad']:.10e} rad, "
              f"{orbit['frequency_hz']:.8f} Hz")
    out["S [m/s]"] = simulator.fold_speed(*FOLD_BRACKET, FOLD_TOL, model)
    print(f"smoothing: eps/y_fp = {ratio if ratio else 0:g}: S = {out['S [m/s]']} m/s")
    return out


def kind(quantity: str) -> str:
    return "hopf" if quantity.startswith("H") else "fold" if quantity.startswith("S ") \
        else "orbit"


def compute():
    law()
    limit = answers(None)
    smoothed = [answers(r) for r in RATIOS]
    table = {}
    for q, x0 in limit.items():
        errors = [None if s[q] is None or x0 is None else s[q] - x0 for s in smoothed]
        fit = None
        if x0 is not None:
            near = [(r, e) for r, e in zip(RATIOS, errors) if r <= ASYMPTOTIC and e is not None]
            fit = convergence.fitted_order([r for r, _ in near], [e for _, e in near],
                                           FLOOR[kind(q)] * abs(x0))
        table[q] = {"limit": x0, "errors": errors, "fit": fit}
    return {"law": mlgmodel.LAWS[law()], "ratios": list(RATIOS), "speeds": list(SPEEDS),
            "asymptotic": ASYMPTOTIC, "table": table}


def text(result) -> str:
    ratios = result["ratios"]
    head = ["quantity", "eq. (14)"] + [f"{r:g}" for r in ratios] + ["p fitted", "p predicted"]
    lines = [head]
    predicted = PREDICTED.get(result["law"], {})
    for q, row in result["table"].items():
        fit = row["fit"]
        lines.append([q, "vanished" if row["limit"] is None else f"{row['limit']:.10g}"]
                     + ["-" if e is None else f"{e:+.3e}" for e in row["errors"]]
                     + [f"{fit['p']:.2f}" if fit else "exact", predicted.get(kind(q), "?")])
    widths = [max(len(line[k]) for line in lines) for k in range(len(head))]
    body = "\n".join("  ".join(c.ljust(w) for c, w in zip(line, widths)).rstrip()
                     for line in lines)
    return (f"smoothing: X(eps) - X(0) of the {result['law']} law against eq. (14), F* = 1, "
            f"y_fp = 1 mm, by eps / y_fp (columns); p fitted over eps / y_fp <= "
            f"{result['asymptotic']:g} (\"exact\": no difference above round-off)\n{body}\n")


def plot(result):
    import matplotlib.pyplot as plt
    import numpy
    from mlgshimmy.shared import draw

    table = text(result)
    jobs.write_text(f"{paths.tables_dir()}/{FIGURE}.txt", table)
    print(table, end="")
    ratios = numpy.array(result["ratios"])
    fig, ax = plt.subplots(figsize=(7, 5))
    rows = list(result["table"].items())
    for (q, row), colour in zip(rows, draw.sequence(len(rows))):
        if row["limit"] is None:
            continue
        pairs = [(r, abs(e / row["limit"])) for r, e in zip(ratios, row["errors"])
                 if e is not None and e != 0]
        if pairs:
            ax.loglog(*zip(*pairs), "o-" if kind(q) == "hopf" else "s--", color=colour,
                      lw=1.1, ms=4, label=q)
    for p, style in ((3, ":"), (2, "-.")):
        ax.loglog(ratios, 0.3 * ratios ** p, "k" + style, lw=0.8, label=f"slope {p}")
    ax.set(xlabel=r"$\epsilon / y_{fp}$", ylabel=r"$|X(\epsilon) - X(0)| / |X(0)|$",
           title=f"the {result['law']} law against eq. (14), F* = 1, y_fp = 1 mm")
    ax.legend(fontsize=7)
    draw.figure_title(fig, "Smoothing error against eq. (14)")
    fig.tight_layout()
    draw.save(fig, FIGURE)


if __name__ == "__main__":
    jobs.run_figure(FIGURE, compute, plot, module="mlgshimmy.studies.smoothing")
