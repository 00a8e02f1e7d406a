"""Design map: the paper's answers over a (rho, mu) grid of side-stay angles.

Each grid point is an independent job (shared.jobs.grid, like the sweep)
with its own run directory $MLG_RUN_ROOT/design_map/rho<deg>_mu<deg>/ and
result.json there with its provenance (shared.jobs.grid: git commit, AUTO
version, parameter set, settings()), at the complete equations (eom_terms =
2) and the `figures` set:

  zero freeplay, F* = 1: the critical speed (first Hopf point in V);
  y_fp = 1 mm, eps = 0.1 mm (freeplay.NOMINAL), F* = 1: the Hopf points
    of straight rolling, named by their mode (shared.naming: H1, H2 where
    the low-frequency pair loses and regains stability, H3 where the
    high-frequency pair loses it; a point that does not exist is vanished),
    the speeds at which straight rolling is stable, the fold S of the
    high-frequency orbit branch born at H3 and the bistable interval [S, H3]
    (stable straight rolling beside stable large shimmy);
  kappa* (eq. 17, eps = 0.1 mm, V <= 120 m/s, F* in [0.1, 2]) with the load,
    speed and mode where it is set (the criterion's recipe,
    kappa_criterion.least_unstable and kappa_star), the freeplay it allows,
    kappa* x eps in mm, and whether it is set on the oleo's stage switch,
    with kappa* over the loads off the switch beside it
    (kappa_criterion.kappa_star_off_switch);
  the static torque-link position y_tlk/y_fp of straight rolling at F* = 1
    (y_fp = 1 mm) and at kappa*'s point (whether the links sit against one
    side of the freeplay).

Each number the cheapest exact way: the Hopf points are stability changes of
straight rolling, found by eigenvalue scans of the library's exact Jacobian
and bisected to rounding (spectrum.stability_changes; AUTO's location agrees
to its tolerance and adds nothing), and so is kappa* (exact in y_fp at eps =
0.1 mm).  Only S needs AUTO: the orbits born at H3 (continuation.hopf_point,
periodic_from), followed past their folds up to psi_amp = PSI_AMP_STOP; S is
the fold of least V, where the stable large orbits begin.
Subcommands (angles in degrees: "a,b,c" or "start:stop:step"):

  design_map.py check   [--rho L --mu L]   validate every grid point (no AUTO)
  design_map.py targets [--rho L --mu L]   the result files, for make
  design_map.py jobs    [--rho L --mu L]   one shell command per grid point
                                           (GNU parallel, a Slurm array)
  design_map.py point rho<deg>_mu<deg>     compute one grid point
  design_map.py summary [--rho L --mu L] [--mark RHO,MU]
                                           the maps, the table, the json;
                                           --mark: the user's geometry, marked
                                           at its grid point or the nearest

`make [-jN] design-map [DESIGN_RHO=... DESIGN_MU=...] [RHO=.. MU=..]` runs
check, every point, summary: $MLG_RUN_ROOT/figures/design_map.png,
tables/design_map.txt and design_map.json (docs/design-map.md).
"""
from __future__ import annotations

import argparse
import functools
import os
import sys
import time
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import freeplay
from mlgshimmy.shared import geometry
from mlgshimmy.shared import jobs
from mlgshimmy.shared import kappa_criterion
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import naming
from mlgshimmy.shared import paths
from mlgshimmy.shared import rolling
from mlgshimmy.shared import spectrum
from mlgshimmy.shared.jobs import grid as jobgrid

# What make, make help, make submit and the report know of this study
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "design-map": {
        "help": "H1-H3, S, allowed freeplay, y_tlk over (rho, mu) (5 x 5; -j2; RHO, MU marked)",
        "time": "5 min",
        "grid": "DESIGN_GRID_ARGS",
        "report": {
            "command": "make -j2 design-map",
            "text": ("The design map over side-stay angles (rho, mu): critical speed, H1-H3, "
                     "the fold S, the bistable interval and the allowed freeplay "
                     "(docs/design-map.md)."),
            "tables": ["tables/design_map.txt"],
            "figures": ["figures/design_map.png"],
        },
    },
}

DEFAULT_GRID = "-20:20:10"
EOM = 2                      # the complete equations (docs/model.md 8.4)
FSTAR = 1.0
FREEPLAY = freeplay.NOMINAL  # y_fp = 1 mm, eps = 0.1 mm
HIGH_HZ = naming.HIGH_HZ     # Hz: the high-frequency pair, whose H3 starts S's branch
PSI_AMP_STOP = 0.01          # rad: the branch from H3 is followed to here, past S
# fig10's steps but DSMAX 3: S is AUTO's located fold, whatever the step
# that reached it (S within 2e-5 m/s of DSMAX 1's at four geometries, for
# 60-75 % of the CPU)
ORBIT_STEPS = {"DS": 0.05, "DSMAX": 3.0, "NMX": 2000, "DSMIN": 1e-9}
# where the orbits stop (MX) at the fold S with DSMAX 3 before AUTO labels it
# (23 of the 441 geometries of the 2-degree map), Fig. 10's DSMAX 1
ORBIT_STEPS_RETRY = {**ORBIT_STEPS, "DSMAX": 1.0}
KAPPA_LOADS = kappa_criterion.ENVELOPE_LOADS[::2]        # as studies.criterion
KAPPA_FINER = (5, 4)
HOPF_NAMES = ("H1", "H2", "H3")   # the paper's points, by mode (shared.naming)
# the quantities of a point: (key, table heading, unit or "", format)
QUANTITIES = (("critical_V", "V_crit (zero freeplay)", "m/s", ".3f"),
              ("H1", "H1", "m/s", ".3f"), ("H2", "H2", "m/s", ".3f"), ("H3", "H3", "m/s", ".3f"),
              ("S", "S", "m/s", ".3f"), ("bistable_width", "H3 - S (bistable)", "m/s", ".3f"),
              ("kappa", "kappa*", "", ".4f"),
              ("kappa_yfp", "allowed y_fp at eps = 0.1 mm", "mm", ".4f"),
              ("kappa_Fstar", "F* at kappa*", "", ".3f"),
              ("off_switch_yfp", "allowed y_fp off the stage switch", "mm", ".4f"),
              ("ytlk_ratio", "y_tlk/y_fp, F* = 1", "", "+.3f"),
              ("ytlk_ratio_kappa", "y_tlk/y_fp at kappa*", "", "+.3f"))




def settings() -> Dict[str, Any]:
    """What a point's result depends on besides its angles, the code, the
    model and AUTO (recorded in its provenance, shared.jobs.grid)."""
    return {"eom_terms": EOM, "Fstar": FSTAR, "freeplay": FREEPLAY, "high_Hz": HIGH_HZ,
            "V_scan": [ct.V_MIN, ct.V_MAX, len(ct.SPEED_SCAN)],
            "psi_amp_stop": PSI_AMP_STOP, "orbit_steps": ORBIT_STEPS,
            "orbit_steps_retry": ORBIT_STEPS_RETRY,
            "kappa_loads": [float(F) for F in KAPPA_LOADS], "kappa_finer": KAPPA_FINER}


POINTS = jobgrid.Plane("rho", "mu", "design_map", "figures", settings)   # rho<deg>_mu<deg>


def axes(args: Any) -> List[Tuple[float, float]]:
    rhos = jobgrid.axis(args.rho, "DESIGN_RHO (--rho)", "angles in degrees")
    mus = jobgrid.axis(args.mu, "DESIGN_MU (--mu)", "angles in degrees")
    return jobgrid.plane(rhos, mus)


def at(rho: float, mu: float) -> Tuple[geometry.Geometry, Dict[str, float]]:
    """The geometry of a grid point and its model parameters (eom_terms = 2
    at every point, rho = mu = 0 included)."""
    return geometry.Geometry(rho, mu, EOM), geometry.model_angles(rho, mu, float(EOM))


def problem(point: Tuple[float, float]) -> Optional[str]:
    """Why the grid point (rho, mu) cannot be run, or None."""
    rho, mu = point
    try:
        _, values = at(rho, mu)
        for case in ({"yfp": 0.0}, FREEPLAY):
            mlgmodel.Model("figures", V=ct.V_MIN, Fstar=FSTAR, **case, **values).check()
    except geometry.GeometryError:
        return (f"rho = {rho:g} deg, mu = {mu:g} deg: the angles must lie within "
                "(-90, 90) degrees (DESIGN_RHO, DESIGN_MU)")
    except ValueError as exc:
        return f"rho = {rho:g} deg, mu = {mu:g} deg: {exc}"
    return None


def speeds(values: Mapping[str, float]) -> Dict[str, Any]:
    """The scans at F* = 1: {critical_V, hopf: [(V, Hz)] with freeplay,
    hopf_names: their names by mode (shared.naming), hopf_l1: their first
    Lyapunov coefficients, hopf_criticality: by the normal form
    (naming.by_coefficients: l1, or the oleo's kink), bp: the real-eigenvalue
    crossings in V (none expected), stable: [(V_from, V_to)] where straight
    rolling with freeplay is stable, within the scan's ct.V_MIN-ct.V_MAX}."""
    zero = spectrum.hopf_scan("figures", "V", ct.SPEED_SCAN, Fstar=FSTAR, yfp=0.0, **values)
    case = {"Fstar": FSTAR, **FREEPLAY, **values}
    changes = spectrum.stability_changes("figures", "V", ct.SPEED_SCAN, **case)
    hopf = [(v, hz) for v, kind, hz in changes if kind == "HB"]
    modes = [naming.mode("figures", "V", v, **case) for v, _ in hopf]
    return {"critical_V": zero[0][0] if zero else None, "hopf": hopf,
            "hopf_names": naming.names(modes),
            "hopf_l1": [m["l1"] for m in modes],
            "hopf_criticality": [naming.by_coefficients(m) for m in modes],
            "bp": [v for v, kind, _ in changes if kind == "BP"],
            "stable": spectrum.stable_intervals("figures", "V", [v for v, _, _ in changes],
                                                ct.V_MIN, ct.V_MAX, **case)}


def fold_S(rundir: str, start: Optional[float], values: Mapping[str, float]) -> Dict[str, Any]:
    """AUTO: the orbits born at H3 (its speed `start`, or None where it has
    vanished), followed to psi_amp = PSI_AMP_STOP, and their fold of least
    V, S (a fold within 0.1 % of the Hopf point is AUTO's spurious
    first-step LP, continuation.Diagram.folds).  {S, from_V, stop, folds,
    S_psi_amp}."""
    if start is None:
        return {"S": None, "from_V": None, "stop": "H3 vanished", "folds": [],
                "S_psi_amp": None}
    point = ct.hopf_point(rundir, "hb_high", "figures", "V", start, Fstar=FSTAR, **FREEPLAY,
                          **values)
    for steps in (ORBIT_STEPS, ORBIT_STEPS_RETRY):
        orbits = ct.periodic_from(rundir, "po_high", point,
                                  stop={"V": [ct.V_MIN, ct.V_MAX], "psi_amp": PSI_AMP_STOP},
                                  allow_mx=True, **steps)
        folds = [p for p in orbits("LP") if abs(p["V"] - start) > 1e-3 * start]
        last = orbits()[-1]["TY name"]
        if folds or last != "MX":
            break
        print(f"design_map: the orbits from H3 stop (MX) at V = {orbits()[-1]['V']:.3f} before "
              f"any fold at DSMAX {steps['DSMAX']:g}; again at DSMAX "
              f"{ORBIT_STEPS_RETRY['DSMAX']:g}", flush=True)
    # S: the fold of least V, where the stable large orbits begin (at rho =
    # mu = 0 the only one; where the links sit near a side of the freeplay the
    # branch first folds above H3, ~130 m/s, unstable on both sides)
    lowest = min(folds, key=lambda p: p["V"]) if folds else None
    return {"S": lowest["V"] if folds else None, "from_V": start,
            "folds": [p["V"] for p in folds],
            "S_psi_amp": lowest["psi_amp"] if folds else None,
            "stop": {"UZ": f"psi_amp = {PSI_AMP_STOP:g} rad or a V bound",
                     "MX": "MX (no convergence)"}.get(last, last)}


def kappa(values: Mapping[str, float], loads: Sequence[float] = KAPPA_LOADS,
          finer: Tuple[int, ...] = KAPPA_FINER) -> Dict[str, Any]:
    """kappa* over the envelope's loads (the criterion's recipe), the
    freeplay it allows (kappa_yfp = kappa* eps [mm]), whether its load lies
    in the oleo's stage-switch window, and kappa* over the loads off it."""
    least = functools.lru_cache(maxsize=None)(lambda F: kappa_criterion.least_unstable(F, **values))
    value, best = kappa_criterion.kappa_star(least, loads, values, finer=finer)
    off, off_best, window = kappa_criterion.kappa_star_off_switch(least, loads, values, finer=finer)
    return {"kappa": value, "kappa_Fstar": best["Fstar"], "kappa_V": best["V"],
            "kappa_mode": best["mode"], "kappa_eta": best["eta"], "kappa_yfp": best["first"],
            "switch_window": list(window) if window else None,
            "on_switch": bool(window and window[0] <= best["Fstar"] <= window[1]),
            "kappa_off_switch": off, "off_switch_Fstar": off_best["Fstar"],
            "off_switch_V": off_best["V"], "off_switch_yfp": off_best["first"]}


def link_position(values: Mapping[str, float], Fstar: float, yfp: float,
                  epsilon: Mapping[str, float]) -> float:
    """y_tlk/y_fp of straight rolling (continued from zero freeplay,
    shared.rolling) at load F*, freeplay y_fp [mm], epsilon {eps_abs,
    eps_rel}."""
    u = rolling.state("figures", Fstar, yfp, epsilon, **values)
    model = mlgmodel.Model("figures", Fstar=Fstar, V=rolling.V_SOLVE, yfp=yfp, **epsilon,
                           **values)
    return geometry.y_tlk(model, u) / (1e-3 * yfp)


def cpu() -> float:
    """CPU seconds of this process and its finished children (AUTO)."""
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


def compute(rho: float, mu: float, rundir: str) -> Dict[str, Any]:
    """Every number of one grid point, with the CPU seconds of each stage."""
    g, values = at(rho, mu)
    seconds, out = {}, {"rho_deg": g.rho_deg, "mu_deg": g.mu_deg, "eom_terms": EOM}

    def stage(name, work):      # CPU of this process and of its AUTO runs
        started = cpu()
        result = work()
        seconds[name] = round(cpu() - started, 2)
        return result
    scans = stage("scans", lambda: speeds(values))
    out.update(scans)
    # with side-stay angles the low-frequency pair can vanish (the links
    # then sit against one side of the freeplay at low speed)
    named = {name: v for name, (v, _) in zip(scans["hopf_names"], scans["hopf"])}
    out.update({name: named.get(name) for name in ("H1", "H2", "H3")})
    fold = stage("auto", lambda: fold_S(rundir, out["H3"], values))
    out.update({"S": fold["S"], "S_from_V": fold["from_V"], "S_folds": fold["folds"],
                "S_stop": fold["stop"], "S_psi_amp": fold["S_psi_amp"]})
    # [S, H3]: straight rolling stable (no Hopf point of it inside) beside
    # the stable large orbits
    S, H3 = fold["S"], fold["from_V"]
    out["bistable_width"] = (H3 - S if S is not None and S < H3 and
                             not any(S < v < H3 for v, _ in scans["hopf"]) else None)
    out.update(stage("kappa", lambda: kappa(values)))
    out["ytlk_ratio"] = stage("links", lambda: link_position(
        values, FSTAR, FREEPLAY["yfp"], {k: FREEPLAY[k] for k in ("eps_abs", "eps_rel")}))
    # no freeplay to sit in where kappa* = 0 (unstable without freeplay)
    out["ytlk_ratio_kappa"] = link_position(
        values, out["kappa_Fstar"], out["kappa_yfp"], freeplay.SCALINGS["fixed"]) \
        if out["kappa_yfp"] else None
    out["cpu_seconds"] = seconds
    return out


def run_point(name: str) -> None:
    rho, mu = POINTS.parse(name)
    started = time.monotonic()
    result = compute(rho, mu, paths.rundir(os.path.join("design_map", name)))
    result["wall_seconds"] = round(time.monotonic() - started, 1)
    POINTS.write(rho, mu, result)
    print(f"design_map: {name}: " + "; ".join(
        f"{key} {_cell(result.get(key), fmt, key)}" for key, _, _, fmt in QUANTITIES)
        + f"; {sum(result['cpu_seconds'].values()):.0f} s CPU "
          f"({', '.join(f'{k} {v:g}' for k, v in result['cpu_seconds'].items())})")


def _cell(value, fmt, key=""):
    if value is None:
        return "vanished" if key in HOPF_NAMES else "-"
    return format(value, fmt)


def nearest(cells: Sequence[Mapping[str, Any]],
            mark: Optional[Tuple[float, float]]) -> Optional[Mapping[str, Any]]:
    """The cell of the grid point nearest to the user's geometry `mark`
    (rho, mu) [deg], or None without one."""
    if mark is None:
        return None
    return min(cells, key=lambda c: (c["rho_deg"] - mark[0]) ** 2 + (c["mu_deg"] - mark[1]) ** 2)


def headline(c: Mapping[str, Any]) -> str:
    """What a designer reads first at one geometry, from the numbers the
    map computes (saying so where one was not found)."""
    stable = ", ".join(f"{a:.3f}-{b:.3f}" for a, b in c["stable"]) or "no speed"
    parts = [f"straight rolling stable at V = {stable} m/s with 1 mm of freeplay"]
    S, H3 = c["S"], c["H3"]
    if c["bistable_width"] is not None:
        parts.append(f"bistable band [S, H3] = [{S:.3f}, {H3:.3f}] m/s")
    elif H3 is None:
        parts.append("no bistable band: H3 vanished")
    elif S is None:
        parts.append(f"bistable band not known: no fold S found ({c['S_stop']})")
    elif S >= H3:
        parts.append(f"no bistable band: S = {S:.3f} lies above H3 = {H3:.3f} m/s")
    else:
        parts.append(f"no bistable band: straight rolling changes stability inside "
                     f"[S, H3] = [{S:.3f}, {H3:.3f}] m/s")
    others = [f"{name} {v:.3f}" for name, (v, _) in zip(c["hopf_names"], c["hopf"])
              if name not in HOPF_NAMES]
    if others:
        parts.append("other Hopf points " + ", ".join(others) + " m/s")
    if c.get("hopf_criticality"):    # maps computed before it was stored have none
        parts.append("by the normal form: " + ", ".join(
            f"{name} {verdict}" for name, verdict in zip(c["hopf_names"], c["hopf_criticality"])))
    where = (f"F* = {c['kappa_Fstar']:.3f}" + (", on the oleo's stage switch" if c["on_switch"]
                                                 else ""))
    parts.append(f"no freeplay allowed (unstable without freeplay at {where}, "
                 f"V = {c['kappa_V']:.1f} m/s)" if c["kappa"] == 0 else
                 f"allowed freeplay {c['kappa_yfp']:.4f} mm (kappa* {c['kappa']:.4f} at {where})")
    if c["on_switch"]:
        parts[-1] += (f"; away from the switch {c['off_switch_yfp']:.4f} mm "
                      f"(kappa* {c['kappa_off_switch']:.4f} at F* = {c['off_switch_Fstar']:.3f})")
    return "; ".join(parts)


def table(cells: Sequence[Mapping[str, Any]], mark: Optional[Tuple[float, float]] = None) -> str:
    """The table's text: one row per geometry, then one headline per
    geometry; the user's geometry `mark` (or the grid point nearest it)
    flagged."""
    yours = nearest(cells, mark)
    head = ["rho", "mu"] + [f"{h}" + (f" [{u}]" if u else "") for _, h, u, _ in QUANTITIES] \
        + ["kappa*: V, mode", "on switch", "CPU [s]"]
    rows = [head]
    for c in cells:
        rows.append([f"{c['rho_deg']:g}", f"{c['mu_deg']:g}"]
                    + [_cell(c.get(key), fmt, key) for key, _, _, fmt in QUANTITIES]
                    + [f"{c['kappa_V']:.1f}, {c['kappa_mode']}",
                       "yes" if c["on_switch"] else "no",
                       f"{sum(c['cpu_seconds'].values()):.0f}"])
    widths = [max(len(r[k]) for r in rows) for k in range(len(head))]
    lines = ["  ".join(cell.rjust(w) for cell, w in zip(row, widths)) for row in rows]
    cpu = [sum(c["cpu_seconds"].values()) for c in cells]
    windows = [tuple(c["switch_window"]) for c in cells if c["switch_window"]]
    mine = [] if yours is None else [
        f"Your gear: rho = {mark[0]:g}, mu = {mark[1]:g} deg"
        + ("" if (yours["rho_deg"], yours["mu_deg"]) == tuple(mark) else
           f"; nearest grid point ({yours['rho_deg']:g}, {yours['mu_deg']:g})")
        + " (marked *)"]
    return "\n".join([
        "Design map: side-stay angles rho, mu [deg], eom_terms = 2, `figures` set, F* = 1 "
        "unless stated;",
        "y_fp = 1 mm, eps = 0.1 mm for H1-H3, S and y_tlk/y_fp at F* = 1; kappa* by eq. (17) "
        "(eps = 0.1 mm, V <= 120 m/s, F* in [0.1, 2]);",
        "allowed y_fp = kappa* eps: the largest freeplay with straight rolling stable up to "
        "120 m/s at every load, for eps = 0.1 mm, the smoothing width of eq. (15);",
        "on switch: kappa* set in the oleo's stage-switch window (F* "
        + (f"{min(w[0] for w in windows):.3f}-{max(w[1] for w in windows):.3f}" if windows
           else "none") + "), where it depends on the switch's steepness; off the "
        "stage switch: kappa* eps over the other loads;",
        "S: fold of least V of the orbits born at H3 (where the stable large orbits begin); "
        "bistable: [S, H3] with straight rolling stable in it;",
        f"headlines, stable at V: the speeds of stable straight rolling within the scan's "
        f"{ct.V_MIN:g}-{ct.V_MAX:g} m/s (y_fp = 1 mm, F* = 1);",
        "y_tlk/y_fp at kappa*: at its load and freeplay (+-1: against a side); H1, H2: the "
        f"low-frequency (< {HIGH_HZ:g} Hz) pair loses, regains stability, H3: the "
        "high-frequency pair loses it (vanished: no such point)."] + lines + [
        f"CPU per geometry: mean {numpy.mean(cpu):.1f} s, max {max(cpu):.1f} s, "
        f"total {sum(cpu):.0f} s over {len(cells)} geometries"] + mine + [""] + [
        f"{'*' if c is yours else ' '} ({c['rho_deg']:g}, {c['mu_deg']:g}): {headline(c)}"
        for c in cells]) + "\n"


def summary(points: Sequence[Tuple[float, float]], results: Sequence[Mapping[str, Any]],
            provenance: Optional[Mapping[str, Any]],
            mark: Optional[Tuple[float, float]] = None) -> None:
    """The table, its JSON and the maps from the points' results (their
    records, every point's checked present and of one provenance by
    shared.jobs.grid); mark: the user's geometry (rho, mu) [deg] or None."""
    cells = list(results)
    text = table(cells, mark)
    print(text, end="")
    tables = paths.tables_dir()
    jobs.write_text(os.path.join(tables, "design_map.txt"), text)
    yours = nearest(cells, mark)
    jobs.write_json(os.path.join(tables, "design_map.json"),
                    {"grid": {"rho_deg": sorted({c["rho_deg"] for c in cells}),
                              "mu_deg": sorted({c["mu_deg"] for c in cells})},
                     "eom_terms": EOM, "freeplay": FREEPLAY, "epsilon_mm": freeplay.EPSILON,
                     "mark": None if yours is None else
                     {"rho_deg": mark[0], "mu_deg": mark[1], "nearest":
                      [yours["rho_deg"], yours["mu_deg"]]},
                     "points": [dict(c, headline=headline(c)) for c in cells]}, indent=1)
    print(f"design_map: wrote {os.path.relpath(os.path.join(tables, 'design_map.txt'), paths.ROOT)}"
          ", design_map.json")
    plot(cells, mark)


SWITCH_FLAGGED = ("kappa", "kappa_yfp", "kappa_Fstar")   # panels hatched where on_switch
# each panel's title in the reader's words and its cells' format (fewer
# digits than the table's, so that they can be read; "none" where a value is
# missing, a vanished Hopf point too), by QUANTITIES' key
PANELS = {"critical_V": ("critical speed without freeplay [m/s]", ".1f"),
          "H1": ("H1 [m/s]", ".2f"), "H2": ("H2 [m/s]", ".1f"), "H3": ("H3 [m/s]", ".1f"),
          "S": ("fold S [m/s]", ".1f"), "bistable_width": ("bistable band H3 - S [m/s]", ".1f"),
          "kappa": (r"$\kappa^*$ (eq. 17)", ".3f"),
          "kappa_yfp": (r"allowed freeplay $y_{fp}$ [mm]", ".4f"),
          "kappa_Fstar": (r"load $F^*$ that sets $\kappa^*$", ".2f"),
          "off_switch_yfp": (r"allowed $y_{fp}$ away from the stage switch [mm]", ".4f"),
          "ytlk_ratio": (r"links' position $y_{tlk}/y_{fp}$ at $F^*$ = 1", "+.2f"),
          "ytlk_ratio_kappa": (r"links' position $y_{tlk}/y_{fp}$ at $\kappa^*$", "+.2f")}
POSITION = ("ytlk_ratio", "ytlk_ratio_kappa")   # on a scale of their own: -1, 1 the gap's sides


def grid_of(cells: Sequence[Mapping[str, Any]], key: str, rhos: List[float],
            mus: List[float]) -> numpy.ndarray:
    """One quantity as [mu, rho] (NaN where it is None)."""
    values = numpy.full((len(mus), len(rhos)), numpy.nan)
    for c in cells:
        if c.get(key) is not None:
            values[mus.index(c["mu_deg"]), rhos.index(c["rho_deg"])] = c[key]
    return values


def changes(cells: Sequence[Mapping[str, Any]], rhos: List[float],
            mus: List[float]) -> Tuple[Dict[str, numpy.ndarray], str]:
    """({key: [mu, rho] change in %}, what from): each quantity but the
    links' positions against the paper's geometry rho = mu = 0 where the
    grid has it, else against its median over the grid; NaN throughout
    where that reference is zero or missing."""
    baseline = 0.0 in rhos and 0.0 in mus
    out = {}
    for key, _, _, _ in QUANTITIES:
        if key in POSITION:
            continue
        values = grid_of(cells, key, rhos, mus)
        finite = values[numpy.isfinite(values)]
        ref = (values[mus.index(0.0), rhos.index(0.0)] if baseline
               else numpy.median(finite) if finite.size else numpy.nan)
        out[key] = (100.0 * (values - ref) / abs(ref) if numpy.isfinite(ref) and ref != 0
                    else numpy.full_like(values, numpy.nan))
    return out, ("the paper's geometry" if baseline else "the grid's median")


def plot(cells: Sequence[Mapping[str, Any]], mark: Optional[Tuple[float, float]] = None) -> None:
    """Every quantity of QUANTITIES as a map over (rho, mu), its values in
    the cells, coloured on two scales that the panels share (the palette's
    diverging map): the change from the paper's geometry in %, limited by
    angle_map.change_limit, and the links' position in the freeplay gap
    from -1 to 1 (against its sides)."""
    import matplotlib.pyplot as plt
    from matplotlib.colors import Normalize
    from matplotlib.patches import Patch, Rectangle

    from mlgshimmy.shared import draw
    from mlgshimmy.shared.draw.angle_map import MAX_LABELLED, angle_map, change_limit
    palette = draw.palette
    rhos = sorted({c["rho_deg"] for c in cells})
    mus = sorted({c["mu_deg"] for c in cells})
    yours = nearest(cells, mark)
    change, against = changes(cells, rhos, mus)
    limit = change_limit(change.values())
    scales = {"change": Normalize(-limit, limit), "position": Normalize(-1.0, 1.0)}
    numbers = {key: grid_of(cells, key, rhos, mus) for key, _, _, _ in QUANTITIES}

    def text(key: str, value: float) -> str:
        return format(value, PANELS[key][1]) if numpy.isfinite(value) else "none"

    # one size for every cell's number, the longest filling its cell's width
    # (a panel is about 200 pt wide)
    longest = max(len(text(key, v)) for key, values in numbers.items() for v in values.flat)
    fontsize = min(12.0, 300.0 / (len(rhos) * longest))
    fig, axes_ = plt.subplots(3, 4, figsize=(15, 11.5), constrained_layout=True)
    meshes = {}
    for ax, (key, _, _, _) in zip(axes_.flat, QUANTITIES):
        scale = "position" if key in POSITION else "change"
        meshes[scale] = angle_map(ax, rhos, mus, numbers[key] if scale == "position"
                                  else change[key], functools.partial(text, key),
                                  palette.DIVERGING_MAP, norm=scales[scale],
                                  numbers=numbers[key], fontsize=fontsize)
        for c in cells:
            j, i = rhos.index(c["rho_deg"]), mus.index(c["mu_deg"])
            if key in SWITCH_FLAGGED and c["on_switch"]:
                ax.add_patch(Rectangle((j - 0.5, i - 0.5), 1, 1, fill=False, hatch="//",
                                       ec=palette.GUIDE, lw=0))
            if c is yours:
                ax.add_patch(Rectangle((j - 0.44, i - 0.44), 0.88, 0.88, fill=False, lw=2.2,
                                       ec=palette.LIFTOFF, ls="--"))
        if 0.0 in rhos and 0.0 in mus:     # the paper's geometry
            ax.add_patch(Rectangle((rhos.index(0.0) - 0.5, mus.index(0.0) - 0.5), 1, 1,
                                   fill=False, lw=2.2, ec=draw.NEUTRAL))
        ax.set_title(PANELS[key][0], fontsize=11)
    for ax in axes_.flat[len(QUANTITIES):]:
        ax.set_visible(False)
    panels = dict(zip([key for key, _, _, _ in QUANTITIES], axes_.flat))
    fig.colorbar(meshes["change"], ax=[ax for key, ax in panels.items() if key not in POSITION],
                 shrink=0.6, extend="both", label=f"change from {against} [%]")
    fig.colorbar(meshes["position"], ax=[panels[key] for key in POSITION], location="bottom",
                 shrink=0.8, label=r"links' position $y_{tlk}/y_{fp}$: $\pm$1 against a side "
                                   "of the freeplay gap")
    legend = [Patch(fill=False, ec=draw.NEUTRAL, lw=2.2,
                    label=r"the paper's geometry $\rho = \mu = 0$"),
              Patch(fill=False, hatch="//", ec=palette.GUIDE,
                    label=r"$\kappa^*$ set on the oleo's stage switch (read the value away "
                          "from it)")]
    if yours is not None:
        at_point = (yours["rho_deg"], yours["mu_deg"]) == tuple(mark)
        legend.append(Patch(fill=False, ec=palette.LIFTOFF, ls="--", lw=2.2, label=(
            f"your gear rho = {mark[0]:g}, mu = {mark[1]:g} deg" + ("" if at_point else
            f" (nearest grid point {yours['rho_deg']:g}, {yours['mu_deg']:g})"))))
    fig.legend(handles=legend, loc="upper center", bbox_to_anchor=(0.5, 0.0),
               ncol=len(legend), fontsize=10, frameon=False)
    fig.suptitle(f"Design map over the side-stay angles ({geometry.EOM_WORDS[2]}, our "
                 "calibrated parameter set;\n"
                 r"$y_{fp}$ = 1 mm, $\epsilon$ = 0.1 mm, $F^*$ = 1 unless stated; "
                 r"allowed $y_{fp}$ = $\kappa^*\epsilon$ at $\epsilon$ = 0.1 mm); "
                 + ("the cells hold the values, the colours compare them"
                    if max(len(rhos), len(mus)) <= MAX_LABELLED else
                    "the colours compare the values, the table holds them"))
    draw.save(fig, "design_map")


def mark_of(text: str) -> Tuple[float, ...]:
    """(rho, mu) [deg] of --mark "RHO,MU" (either may be empty: 0)."""
    parts = text.split(",")
    if len(parts) != 2:
        raise ValueError(f"--mark {text!r}: give RHO,MU in degrees")
    return tuple(float(part) if part.strip() else 0.0 for part in parts)


def main(argv: Optional[Sequence[str]] = None) -> None:
    # --mark concerns the summary alone: the grid and its jobs do not see it
    parser = argparse.ArgumentParser(add_help=False, allow_abbrev=False)
    parser.add_argument("--mark", default="")
    known, rest = parser.parse_known_args(argv)
    try:
        mark = mark_of(known.mark) if known.mark else None
    except ValueError as exc:
        sys.exit(f"design_map: {exc}")
    jobgrid.main("design_map", __doc__.splitlines()[0], "point", POINTS,
                 [("--rho", DEFAULT_GRID, "rho values [deg]: a,b,c or start:stop:step"),
                  ("--mu", DEFAULT_GRID, "mu values [deg]: a,b,c or start:stop:step")],
                 axes, run_job=run_point, problem=problem,
                 summary=lambda points, results, provenance: summary(points, results,
                                                                      provenance, mark),
                 argv=rest)


if __name__ == "__main__":
    main()
