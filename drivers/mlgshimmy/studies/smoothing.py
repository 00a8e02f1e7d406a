"""The smoothing error: how far the smoothed freeplay law (eq. 15, or the
gear's law, FREEPLAY=) puts the answers from those of the non-smooth eq.
(14), against eps / y_fp, with the fitted order of convergence set against
the predicted one (docs/model.md 9.3).  Fig. 10's case, F* = 1, y_fp = 1 mm.

- Straight rolling inside the gap (eigenvalue scans, no AUTO; eq. (14) is
  smooth there): H1, H2, H3 in V, and Fig. 12's a_12, b_12 in F* at 50 m/s
  (spectrum.stable_before_hopf).  Predicted by the law's stiffness at y = 0
  (PREDICTED): order 3 for eq. (15), (4 / 3 pi) (eps / y_fp)^3 k_tlk;
  exponentially small for tanh; none at all for cubic and hertz, zero
  inside |y| < y_fp - eps.
- The stable high-frequency orbit at SPEEDS: psi amplitude and frequency
  by time simulation, eq. (14) with every switch located (mlg_simulate).
  Predicted order 2 where the force error (at most ~k_tlk eps) is confined
  to a band of width ~eps that the orbit crosses transversally; 1 for
  hertz, whose ramp shifts the whole contact line by k_tlk eps / 3.
- The fold S of those orbits, by simulation (simulator.fold_speed: whether
  the orbit survives 80 s, bisected in V to 1e-3 m/s; low by about 1e-3
  m/s, the slow passage past the fold).  The orbit there still crosses the
  corners transversally: the same orders as the orbits.
- The torus points TR1-TR4 of Fig. 10's large orbits (AUTO, Fig. 10's
  diagram on the mesh TORUS_MESH; torus.speeds).  No computed limit:
  X(0), C and p are fitted together (convergence.extrapolated), where the
  points spread by more than the mesh moves them (TORUS_RESOLUTION).
- Eq. (17)'s kappa* (kappa_criterion.criterion, eps = eps / y_fp x 1 mm) and the
  freeplay it allows, kappa* eps.  Eq. (14) allows none (kappa* = 0); a law
  of one shape has the same kappa* at every eps at the paper's gear
  (docs/model.md 9.4), so kappa* has no limit (order 0) and the allowed
  freeplay goes to zero at order 1.

The Fig. 10 diagrams at OVERLAY ratios and eq. (14)'s simulated orbits at
OVERLAY_SPEEDS are kept for the overlay figure (smoothing_fig10.png).

    make smoothing          # compute (about 25 min) and write the table
    make smoothing-plot     # redraw from the cache
"""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import runerror
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import convergence, freeplay, gear, jobs, mlgmodel, naming, paths
from mlgshimmy.shared import kappa_criterion
from mlgshimmy.shared import rolling_state
from mlgshimmy.shared import yfp_stored
from mlgshimmy.shared import simulator, spectrum, torus

DECLARED = {
    "smoothing": {
        "help": "eq. (15) (or FREEPLAY=) against eq. (14): the eps table, fitted orders, Fig. 10",
        "time": "25 min",
        "report": {
            "command": "make smoothing",
            "text": ("The smoothing error of eq. (15) against the non-smooth eq. (14) by "
                     "eps / y_fp: H1-H3, Fig. 12's a_12 and b_12, the stable orbit's "
                     "amplitude and frequency, the fold S, Fig. 10's torus points and "
                     "eq. (17)'s kappa*, with fitted orders; Fig. 10's diagram at several "
                     "eps with eq. (14)'s simulated orbits (docs/model.md 9.3)."),
            "tables": ["tables/smoothing.txt"],
            "figures": ["figures/smoothing.png", "figures/smoothing_fig10.png"],
        },
    },
}
FIGURE = "smoothing"
RATIOS = freeplay.TABLE_RATIOS                        # eps / y_fp
ASYMPTOTIC = 0.2                                       # the fit uses eps / y_fp <= this
CASE = {"Fstar": 1.0, "yfp": freeplay.NOMINAL["yfp"], "eps_abs": 0.0}
SPEEDS = (60.0, 100.0, 140.0)      # m/s, between S and H3: the stable high-frequency orbit
# 16 s from psi = 0.01 rad; the settled orbit sampled every 10 us over the last
# second (the amplitude's sampling error below 3e-7), at CVODE rtol 1e-10
SIMULATION = ("--t-end", 16, "--dt-out", 1e-5, "--psi0", 0.01, "--rtol", 1e-10,
              "--atol", 1e-12)
A12_SPEED = 50.0                                  # m/s: Fig. 12
A12_GRID = numpy.linspace(0.02, 3.5, 175)         # F*: Fig. 12's range
# Fig. 10's orbits on twice the default mesh: on NTST 80 the torus points
# move by 0.05 m/s at eps = 0.1 y_fp and by 0.2 m/s at 0.01 y_fp; on NTST 160
# they jump by up to 0.06 m/s between neighbouring eps, without a trend
TORUS_MESH = 160
TORUS_RESOLUTION = 0.1      # m/s: torus points closer than this are not told apart
# below these errors relative to X(0) a difference is noise (round-off; the
# sampling); kappa* and the freeplay it allows have X(0) = 0: absolute floors
FLOOR = {"rolling": 1e-10, "orbit": 1e-6, "fold": 1e-4}
ABSOLUTE = {"kappa": 1e-6, "allowed": 1e-9}
PREDICTED = {"atan": {"rolling": "3", "orbit": "2", "fold": "2", "torus": "2",
                      "kappa": "0", "allowed": "1"},
             "tanh": {"rolling": "exp.", "orbit": "2", "fold": "2", "torus": "2",
                      "kappa": "0", "allowed": "1"},
             "cubic": {"rolling": "exact", "orbit": "2", "fold": "2", "torus": "2",
                       "kappa": "0", "allowed": "1"},
             "hertz": {"rolling": "exact", "orbit": "1", "fold": "1", "torus": "1",
                       "kappa": "exact", "allowed": "exact"}}
FOLD_BRACKET, FOLD_TOL = (30.0, 45.0), 1e-3     # m/s: S of Fig. 10 is 41.5
OVERLAY = (1.0, 0.2, 0.1, 0.02)                 # eps / y_fp of the overlay figure
# eq. (14)'s orbits simulated for the overlay: the low-frequency ones between
# H1 and H2, the high-frequency ones above S (SPEEDS among them)
OVERLAY_SPEEDS = (5.0, 10.0, 15.0, 20.0, 25.0, 200.0, 300.0)
KAPPA = "kappa* (eq. 17)"
ALLOWED = "allowed y_fp = kappa* eps [mm]"


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


def kind(quantity: str) -> str:
    """What a quantity is, for its floor and predicted order."""
    if quantity == KAPPA:
        return "kappa"
    if quantity == ALLOWED:
        return "allowed"
    return {"H": "rolling", "a": "rolling", "b": "rolling", "S": "fold",
            "T": "torus"}.get(quantity[0], "orbit")


def simulated(model: Mapping[str, Any], speed: float,
              ratio: Optional[float]) -> Tuple[float, float]:
    orbit = simulator.simulate(None, "--V", speed, *SIMULATION, params=model)
    print(f"smoothing: eps/y_fp = {ratio if ratio else 0:g}, V = {speed:g} m/s: "
          f"psi amplitude {orbit['psi_amplitude_rad']:.10e} rad, "
          f"{orbit['frequency_hz']:.8f} Hz", flush=True)
    return orbit["psi_amplitude_rad"], orbit["frequency_hz"]


def rolling_bounds(model: Mapping[str, Any]) -> Tuple[Optional[float], Optional[float]]:
    """Fig. 12's (a_12, b_12) bounds on straight rolling at A12_SPEED
    (spectrum.stable_before_hopf), its state continued from zero freeplay
    (rolling_state.rolling_state); (None, None) without one, and a_12 None
    where straight rolling is stable from the lightest load on (from eps =
    0.2 y_fp the links' stiffness in the gap removes the pitchforks)."""
    at = {k: v for k, v in model.items() if k not in ("Fstar", "yfp")}

    def state(Fstar):
        return rolling_state.rolling_state(Fstar, model["yfp"], "ratio", **at)
    found = spectrum.stable_before_hopf("figures", "Fstar", A12_GRID, state=state,
                                        V=A12_SPEED, yfp=model["yfp"], **at)
    if not found:
        return None, None
    return (None if found[0] == A12_GRID[0] else found[0]), found[1]


def allowed(model: Mapping[str, Any], ratio: float) -> Dict[str, float]:
    """Eq. (17) by the shared criterion, eps = ratio x y_fp (eq. 14: eps
    unused): {KAPPA, ALLOWED}."""
    at = {**gear.parameters(), "freeplay_law": model["freeplay_law"]}
    eps = ratio * CASE["yfp"] if ratio else freeplay.EPSILON
    found = kappa_criterion.criterion({**at, "eps_abs": eps})
    print(f"smoothing: eps/y_fp = {ratio if ratio else 0:g}: kappa* = {found['kappa']:.8g} "
          f"at F* = {found['Fstar']:g}", flush=True)
    return {KAPPA: found["kappa"], ALLOWED: found["kappa"] * eps}


def diagram(model: Mapping[str, Any],
            ratio: float) -> Tuple[List[Tuple[float, int]], Dict[str, Any]]:
    """Fig. 10's diagram at this smoothing on TORUS_MESH: (its torus
    points, the diagram stored for the overlay)."""
    rundir = paths.rundir(f"{FIGURE}/r{ratio:g}")
    # allow_failed: at 0.01 y_fp the low-frequency orbits stop (MX) near H1;
    # the torus points are on the high-frequency ones
    eq, found = ct.diagram_from_rest(rundir, "figures", allow_failed=True, figure=FIGURE,
                                     steps={"NTST": TORUS_MESH}, **model)
    tori = torus.speeds(rundir, found)
    print(f"smoothing: eps/y_fp = {ratio:g}: torus points "
          + ", ".join(f"{v:.4f}" for v, _ in tori), flush=True)
    return tori, {"eq": jobs.stored(eq, yfp_stored.COLUMNS), "hopf": found.hopf,
                  "folds": [(V, amp) for _, _, V, amp in found.folds()],
                  "branches": [b for run in found.branches
                               for b in jobs.stored(run, yfp_stored.COLUMNS)]}


def answers(ratio: Optional[float]
            ) -> Tuple[Dict[str, Optional[float]], Optional[Dict[str, Any]]]:
    """({quantity: value} at one smoothing (None: the limit), the Fig. 10
    diagram or eq. (14)'s simulated orbits for the overlay)."""
    model = values(ratio)
    hopf = naming.scanned("figures", "V", ct.SPEED_SCAN, **model)
    out = {f"{name} [m/s]": hopf.get(name) for name in ("H1", "H2", "H3")}
    out["a_12 [F*]"], out["b_12 [F*]"] = rolling_bounds(model)
    for speed in SPEEDS:
        amp, hz = simulated(model, speed, ratio)
        out[f"psi amplitude at {speed:g} m/s [rad]"] = amp
        out[f"frequency at {speed:g} m/s [Hz]"] = hz
    out["S [m/s]"] = simulator.fold_speed(*FOLD_BRACKET, FOLD_TOL, model)
    print(f"smoothing: eps/y_fp = {ratio if ratio else 0:g}: S = {out['S [m/s]']} m/s",
          flush=True)
    out.update(allowed(model, ratio))
    if ratio is None:
        orbits = {speed: simulated(model, speed, ratio) for speed in OVERLAY_SPEEDS}
        orbits.update({speed: (out[f"psi amplitude at {speed:g} m/s [rad]"],
                               out[f"frequency at {speed:g} m/s [Hz]"]) for speed in SPEEDS})
        return out, {"orbits": sorted(orbits.items())}
    try:
        tori, stored = diagram(model, ratio)
    except (runerror.RunError, RuntimeError) as exc:   # the table keeps the rest
        print(f"smoothing: eps/y_fp = {ratio:g}: Fig. 10's diagram stops, no torus points: "
              f"{getattr(exc, 'brief', exc)}", flush=True)
        return out, None
    out.update({f"TR{k + 1} [m/s]": v for k, (v, _) in enumerate(tori)})
    return out, stored


def fitted(quantity: str, limit: Optional[float], column: Sequence[Optional[float]]
           ) -> Tuple[Optional[float], Optional[Dict[str, Any]], str]:
    """(X(0) used, fit or None, how X(0) is known): the computed limit, or
    for the torus points the one fitted (convergence.extrapolated)."""
    near = [(r, x) for r, x in zip(RATIOS, column) if r <= ASYMPTOTIC and x is not None]
    if kind(quantity) == "torus":
        fit = convergence.extrapolated(*zip(*near), TORUS_RESOLUTION) if near else None
        return (fit["limit"], fit, "fitted") if fit else (near[-1][1] if near else None, None,
                                                          "finest")
    if limit is None:
        return None, None, "vanished"
    what = kind(quantity)
    floor = FLOOR[what] * abs(limit) if what in FLOOR else ABSOLUTE[what]
    fit = convergence.fitted_order([r for r, _ in near], [x - limit for _, x in near], floor)
    return limit, fit, "eq. (14)"


def compute() -> Dict[str, Any]:
    law()
    limit, simulated_limit = answers(None)
    smoothed = [answers(r) for r in RATIOS]
    return assemble(limit, [s for s, _ in smoothed],
                    {f"{r:g}": d for r, (_, d) in zip(RATIOS, smoothed) if r in OVERLAY and d},
                    simulated_limit["orbits"])


def assemble(limit: Mapping[str, Any], smoothed: Any, overlay: Any,
             limit_orbits: Any) -> Dict[str, Any]:
    """The result from the answers at the limit and at RATIOS: the table
    (X(0), X(eps) - X(0), the fit), its numbers for the reference set, the
    overlay's diagrams and eq. (14)'s orbits."""
    quantities = list(limit) + [q for s in smoothed for q in s if q not in limit]
    quantities = list(dict.fromkeys(quantities))
    table = {}
    for q in quantities:
        column = [s.get(q) for s in smoothed]
        x0, fit, how = fitted(q, limit.get(q), column)
        table[q] = {"limit": x0, "how": how, "values": column,
                    "errors": [None if x is None or x0 is None else x - x0 for x in column],
                    "fit": fit}
    numbers = {f"{q} at eps/y_fp = {r:g}": x for q, row in table.items()
               for r, x in zip(RATIOS, row["values"]) if x is not None}
    numbers.update({f"{q} at eq. (14)": limit[q] for q in limit if limit[q] is not None})
    numbers.update({f"{q}: p fitted": row["fit"]["p"] for q, row in table.items() if row["fit"]})
    return {"law": mlgmodel.LAWS[law()], "ratios": list(RATIOS), "speeds": list(SPEEDS),
            "asymptotic": ASYMPTOTIC, "table": table, "numbers": numbers,
            "overlay": overlay, "limit_orbits": limit_orbits}


def text(result: Mapping[str, Any]) -> str:
    ratios = result["ratios"]
    head = ["quantity", "eq. (14)"] + [f"{r:g}" for r in ratios] + ["p fitted", "p predicted"]
    lines = [head]
    predicted = PREDICTED.get(result["law"], {})
    marks = {"fitted": " (fit)", "finest": " (~)", "eq. (14)": "", "vanished": ""}
    for q, row in result["table"].items():
        fit = row["fit"]
        x0 = "vanished" if row["limit"] is None else f"{row['limit']:.10g}{marks[row['how']]}"
        p = f"{fit['p']:.2f}" if fit else ("< res." if kind(q) == "torus" else "exact")
        lines.append([q, x0] + ["-" if e is None else f"{e:+.3e}" for e in row["errors"]]
                     + [p, predicted.get(kind(q), "?")])
    widths = [max(len(line[k]) for line in lines) for k in range(len(head))]
    body = "\n".join("  ".join(c.ljust(w) for c, w in zip(line, widths)).rstrip()
                     for line in lines)
    return (f"smoothing: X(eps) - X(0) of the {result['law']} law against eq. (14), F* = 1, "
            f"y_fp = 1 mm, by eps / y_fp (columns); p fitted over eps / y_fp <= "
            f"{result['asymptotic']:g} (\"exact\": no difference above round-off; "
            f"\"(fit)\": X(0) fitted with p; \"(~)\": X(0) is X at the finest eps, "
            f"\"< res.\": the points spread by less than the mesh resolves, "
            f"{TORUS_RESOLUTION:g} m/s)" + (f" at {gear.describe()}" if not gear.current().baseline
                                           else "") + f"\n{body}\n")


def error_plot(result: Mapping[str, Any]) -> None:
    import matplotlib.pyplot as plt
    from mlgshimmy.shared import draw

    ratios = numpy.array(result["ratios"])
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    # against a computed limit only (not the torus points' finest value)
    rows = [(q, row) for q, row in result["table"].items()
            if row["limit"] and row["how"] == "eq. (14)" and kind(q) not in ("kappa", "allowed")]
    for (q, row), colour in zip(rows, draw.sequence(len(rows))):
        pairs = [(r, abs(e / row["limit"])) for r, e in zip(ratios, row["errors"])
                 if e is not None and e != 0]
        if pairs:
            ax.loglog(*zip(*pairs), "o-" if kind(q) == "rolling" else "s--", color=colour,
                      lw=1.1, ms=4, label=q)
    for p, style in ((3, ":"), (2, "-.")):
        ax.loglog(ratios, 0.3 * ratios ** p, "k" + style, lw=0.8, label=f"slope {p}")
    ax.set(xlabel=r"$\epsilon / y_{fp}$", ylabel=r"$|X(\epsilon) - X(0)| / |X(0)|$",
           title=f"the {result['law']} law against eq. (14), F* = 1, y_fp = 1 mm")
    ax.legend(fontsize=6, ncol=2)
    draw.figure_title(fig, "Smoothing error against eq. (14)")
    fig.tight_layout()
    draw.save(fig, FIGURE)


def overlay_plot(result: Mapping[str, Any]) -> None:
    """Fig. 10's diagram at each eps of OVERLAY in one colour each, as
    Fig. 10 draws it (amplitude, its zoom on small amplitudes, frequency),
    eq. (14)'s simulated orbits as points."""
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from mlgshimmy.shared import draw
    from mlgshimmy.shared.draw import magnitude as draw_magnitude

    fig = plt.figure(figsize=(10, 7.4))
    grid = fig.add_gridspec(2, 2, width_ratios=(1.6, 1))
    amp, zoom, freq = (fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1]),
                       fig.add_subplot(grid[1, :]))
    diagrams = result["overlay"]
    colours = dict(zip(diagrams, draw.sequence(len(diagrams))))
    handles = []
    for ratio, d in diagrams.items():
        for ax in (amp, zoom):
            draw_magnitude.diagram_in_V(ax, d, colours[ratio], None)
            draw.plot_branch(ax, jobs.loaded(d["eq"]), "V", "psi_amp", scale=draw.DEG,
                             color=colours[ratio])
        draw.plot_branch(freq, jobs.loaded(d["branches"]), "V", "freq", color=colours[ratio])
        handles.append(Line2D([], [], color=colours[ratio], lw=1.4,
                              label=rf"$\epsilon$ = {ratio} $y_{{fp}}$"))
    V, orbit = zip(*result["limit_orbits"])
    amps, hz = zip(*orbit)
    style = {"ls": "", "marker": "D", "ms": 4.5, "mfc": draw.palette.OPEN,
             "mec": draw.palette.NEUTRAL, "zorder": 6}
    for ax in (amp, zoom):
        ax.plot(V, numpy.array(amps) * draw.DEG, **style)
        ax.set(xlabel="V [m/s]", ylabel=r"$\psi$ amplitude [deg]")
    freq.plot(V, hz, **style)
    handles.append(Line2D([], [], label="eq. (14), simulated (switches located)", **style))
    amp.set(xlim=(0, ct.V_MAX), title="(a1) torsional amplitude")
    zoom.set(xlim=(0, 160), ylim=(-0.01, 0.45), title="(a2) zoom of (a1): small amplitudes")
    freq.set(xlabel="V [m/s]", ylabel="frequency [Hz]", xlim=(0, ct.V_MAX),
             title="(b) frequency")
    draw.legend(freq, extra=handles, color=draw.palette.NEUTRAL, axes=(amp, zoom, freq),
                loc="lower right", ncol=2)
    draw.figure_title(fig, r"Fig. 10 at several smoothing widths $\epsilon$ and eq. (14): "
                      r"$F^*$ = 1, $y_{fp}$ = 1 mm")
    fig.tight_layout()
    draw.save(fig, f"{FIGURE}_fig10")


def plot(result: Mapping[str, Any]) -> None:
    table = text(result)
    jobs.write_text(f"{paths.tables_dir()}/{FIGURE}.txt", table)
    print(table, end="")
    error_plot(result)
    overlay_plot(result)


if __name__ == "__main__":
    jobs.run_figure(FIGURE, compute, plot, module="mlgshimmy.studies.smoothing")
