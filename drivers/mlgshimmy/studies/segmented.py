"""Fig. 10 in the non-smooth limit: the periodic orbits of eq. (14) as
segmented boundary-value problems in AUTO (shared.segmented,
models/mlg_segmented.c), beside the smoothed eq. (15) at eps = 0.1 y_fp.
F* = 1, y_fp = 1 mm.

- Straight rolling lies in the gap, where eq. (14) is smooth: its Hopf
  points and stability by the eigenvalue scan (naming.scanned, spectrum).
- Each family of orbits (FAMILIES: high and low frequency) from an
  event-located simulation at its start speed (its last period gives the
  modes, gap, contact+, gap, contact-, and their durations), continued in
  V both ways until a contact segment's duration reaches zero (a
  grazing) or V leaves [V_MIN, V_MAX]: the high-frequency orbits up to
  600 m/s, and down through the fold S and back, unstable, to their
  grazing.  Stability from the monodromy, the product of the segments'
  (segmented.stability), at every saved solution.
- The check: at each family's check speeds, on its stable part, the psi
  amplitude and the frequency of AUTO's orbit against an independent
  event-located simulation from psi = 0.01 rad, within TOLERANCE.
- Stability changes away from a fold (P, where the low-frequency orbits'
  real multiplier passes +1; TR): the orbits between the two saved ones
  whose verdicts differ are run again, sampled REFINE times
  (segmented.resampled), and again between the two samples whose verdicts
  differ (PASSES): located to 1/REFINE^PASSES of the first bracket.  At
  P, the orbits the simulation settles on SIDE below and above it,
  symmetric or not (symmetry).
- Past each grazing, the orbits of the gap mode alone, from the Hopf point
  of straight rolling nearest it to the grazing orbit (segmented.gap_orbits),
  one of them checked by simulating one period from it.
- Fig. 12's stationary states under eq. (14) (V = 50 m/s, F* in Fig. 12's
  range): the pitchforks of straight rolling in the gap and the
  boundary-equilibrium points their yawed branches reach
  (shared.boundary_equilibria), classified; the smoothed law's pitchforks
  at each eps / y_fp of the smoothing table with their fitted order, and
  how close its yawed state comes to each BEP at APPROACH.
- The named points (numbers(): the reference set tests/reference/segmented).

    make segmented          # compute (about 5 min), the table and the figure
    make segmented-plot     # redraw from the cache
"""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Sequence, Tuple

import numpy

from mlgshimmy.shared import boundary_equilibria, branches, convergence, freeplay, gear, jobs
from mlgshimmy.shared import mlgmodel, naming, paths, runerror, segmented, yawed
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import simulator, spectrum

DECLARED = {
    "segmented": {
        "help": ("Fig. 10 under eq. (14): segmented AUTO orbits, grazing, checked by "
                 "simulation; Fig. 12's BEPs"),
        "time": "5 min",
        "report": {
            "command": "make segmented",
            "text": ("Fig. 10's diagram in the non-smooth limit (eq. 14): periodic orbits as "
                     "segmented boundary-value problems (one segment per mode, durations "
                     "unknown), their fold, grazings and the gap orbits past them, the "
                     "pitchfork P, checked against the event-located simulation, beside eq. "
                     "(15) at eps = 0.1 y_fp; Fig. 12's boundary-equilibrium points against "
                     "the smoothed pitchforks."),
            "tables": ["tables/segmented.txt"],
            "figures": ["figures/segmented.png", "figures/segmented_fig12.png"],
        },
    },
}
FIGURE = "segmented"
CASE = {"Fstar": 1.0, "yfp": 1.0, "eps_abs": 0.0, "eps_rel": 0.0}   # eq. (14) has no eps
SMOOTHED = {"Fstar": 1.0, "yfp": 1.0, "eps_abs": 0.0, "eps_rel": 0.1}
# each family of orbits: the speed of the simulated orbit it starts from,
# and the speeds of the check, on its stable part [m/s]
FAMILIES = {"high-frequency": {"start": 100.0, "checks": (50.0, 80.0, 150.0, 300.0, 500.0)},
            "low-frequency": {"start": 15.0, "checks": (7.0, 10.0, 13.0, 18.0, 24.0)}}
TOLERANCE = 1e-4                # relative, AUTO against simulation
AT_SPEED = 1e-3                 # m/s: AUTO's UZ at a check speed lies this close (the
                                # simulation runs at its own V)
MARGINAL = 1e-5                 # |mu| - 1 of a multiplier at a fold (or a run's start there)
# the check's simulation: 40 s from psi = 0.01 rad, the last second sampled every
# 10 us (the amplitude's sampling error below 3e-7 at 45 Hz)
CHECK_RUN = ("--t-end", 40, "--dt-out", 1e-5, "--psi0", 0.01, *segmented.TOLERANCES)
COLUMNS = ("V", "psi_amp", "freq")
ZOOM_V = 160.0                  # m/s: panel (a2)'s range
REFINE, PASSES = 40, 2           # samples of the orbits between two verdicts that differ,
                                 # and how many times (each within the last bracket)
SIDE = 0.3                      # m/s: a pitchfork's sides, simulated
# the gap orbits past a grazing: their V spans about 1e-3 m/s, their amplitude 2e-3 rad
PAST_STEPS = {"DS": 2e-5, "DSMAX": 1e-4, "NMX": 3000}
# they stop this fraction of their span short of the grazing: AUTO's UZ solve fails at
# the grazing itself (the field by state bends there); the last PAST_FIT points place it
PAST_SHORT, PAST_FIT = 0.05, 20
FIG12_CASE = {"V": 50.0, "yfp": 1.0, "eps_abs": 0.0, "eps_rel": 0.0}   # Fig. 12's speed, freeplay
FIG12_LOADS = numpy.linspace(0.02, 3.5, 175)     # F*: Fig. 12's range
APPROACH = (0.0005, 0.001, 0.002)  # eps / y_fp: the smoothed yawed state at a BEP's load
ROUNDING = 1e-10                # relative: a pitchfork's difference below this is rounding
# the figure of Fig. 12's yawed states: points per branch, eq. (15)'s widths, its loads
BRANCH_POINTS, OVERLAY_RATIOS = 40, (0.1, 0.02, 0.005, 0.001)
YAW_LOADS = numpy.linspace(0.022, 0.46, 60)
ZOOM_SPAN = 1e-4                # F*: panel (b) from 2 ZOOM_SPAN below BEP2 to ZOOM_SPAN above P2


def stability_mask(bd: Any, branch: Any,
                   model: Any) -> Tuple[numpy.ndarray, List[Tuple[float, str, float, float]]]:
    """(stable per point, [(V, kind, V before, V after)] of its changes): the
    monodromy's verdict at every saved solution, a change placed at the
    fold (LP) between two verdicts that differ, else midway (refined
    locates it), its kind from the multiplier that left the unit circle
    (TR: a complex pair, PD: -1, BP: +1)."""
    saved = branches.labelled_points(branch)
    verdicts = []
    for i, lab, ty in saved:
        solution = bd(lab)
        verdict = segmented.stability(model.set(V=solution["V"]), solution)
        if ty != "LP" and abs(verdict["largest"] - 1.0) > MARGINAL:   # not at a fold
            verdicts.append((i, verdict))
    folds = [i for i, _, ty in saved if ty == "LP"]
    mask = numpy.zeros(len(branch), dtype=bool)
    changes = []
    for (a, sa), (b, sb) in zip(verdicts, verdicts[1:]):
        mask[a:b] = sa["stable"]
        if sa["stable"] == sb["stable"]:
            continue
        at = next((f for f in folds if a < f < b), None)
        if at is not None:
            mask[at:b] = sb["stable"]
            continue
        mask[(a + b) // 2:b] = sb["stable"]
        unstable = sb if sa["stable"] else sa
        mu = unstable["multipliers"]
        outside = mu[abs(mu) > 1.0]
        # a real multiplier through +1 away from a fold: a symmetric orbit's pitchfork
        kind = "TR" if abs(outside.imag).max() > 1e-6 else "PD" if outside.real.min() < 0 \
            else "BP"
        changes.append((float(0.5 * (branch["V"][a] + branch["V"][b])), kind,
                        float(branch["V"][a]), float(branch["V"][b])))
    if verdicts:
        mask[verdicts[-1][0]:] = verdicts[-1][1]["stable"]
        mask[:verdicts[0][0]] = verdicts[0][1]["stable"]
    return mask, changes


def refined(rundir: str, name: str, bd: Any, branch: Any, change: Tuple[float, str, float, float],
            ds: float, model: Any) -> Tuple[float, str, float, float]:
    """A stability change (stability_mask's) located again, PASSES times:
    the orbits from the saved one before it to the one after it run again
    (runs `name`, `name`_2, ...), labelled REFINE - 1 times between, and the
    two neighbouring samples whose verdicts differ bracket it for the next
    pass: (the last bracket's middle, kind, its ends)."""
    _, kind, Va, Vb = change
    label = next(lab for i, lab, _ in branches.labelled_points(branch) if branch["V"][i] == Va)
    start, end = bd(label), Vb
    for k in range(PASSES):
        width = abs(end - start["V"])
        run = segmented.resampled(rundir, f"{name}_{k + 1}" if k else name, start, "V",
                                  {"V": end}, numpy.linspace(start["V"], end, REFINE + 1)[1:-1],
                                  DS=numpy.sign(ds) * width / REFINE, DSMAX=width / REFINE,
                                  NMX=20 * REFINE)
        samples = sorted([start] + list(run("UZ")), key=lambda p: abs(p["V"] - start["V"]))
        stable = [segmented.stability(model.set(V=p["V"]), p)["stable"] for p in samples]
        j = next((j for j in range(len(samples) - 1) if stable[j] != stable[j + 1]), None)
        if j is None:
            raise runerror.RunError(f"segmented: run {name} from V = {start['V']:.6g} to "
                                    f"{end:.6g} m/s: no sample's verdict differs from the first's")
        start, end = samples[j], float(samples[j + 1]["V"])
    return 0.5 * (start["V"] + end), kind, float(start["V"]), end


def orbit_branches(rundir: str, family: str, values: Mapping[str, float]) -> Dict[str, Any]:
    """One family of orbits (FAMILIES), from its simulated orbit up and down
    in V: its modes, stored branches, folds, grazings, stability changes and
    the solutions at its check speeds."""
    start, checks = FAMILIES[family]["start"], FAMILIES[family]["checks"]
    print(f"segmented: {family} orbit of eq. (14) at V = {start:g} m/s by simulation",
          flush=True)
    orbit = segmented.simulated(values, start)
    print("segmented: modes " + ", ".join(segmented.MODE_NAMES[m] for m in orbit["modes"])
          + ", durations " + ", ".join(f"{T:.6e}" for T in orbit["durations"]) + " s",
          flush=True)
    model = mlgmodel.Model("figures", **segmented.law14(values))
    out = {"modes": [segmented.MODE_NAMES[m] for m in orbit["modes"]], "branches": [],
           "folds": [], "grazings": [], "changes": [], "at": []}
    for name, ds, stop in (("up", 0.5, {"V": ct.V_MAX}), ("down", -0.5, {"V": ct.V_MIN})):
        for bd in segmented.follow(rundir, f"{family}-{name}", values, orbit, start, stop=stop,
                                   DS=ds, at=[v for v in checks if (v - start) * ds > 0]):
            for branch in bd:
                mask, changes = stability_mask(bd, branch, model)
                changes = [refined(rundir, f"{family}-{name}-{c[1]}{k + 1}", bd, branch, c, ds,
                                   model) for k, c in enumerate(changes)]
                out["branches"].append({"columns": {c: numpy.asarray(branch[c]) for c in COLUMNS},
                                        "stable": mask, "labels": []})
                out["changes"] += changes
                for i, lab, ty in branches.labelled_points(branch):
                    point = bd(lab)
                    grazed = segmented.grazing(point, orbit["modes"])
                    if ty == "LP" or (ty == "UZ" and grazed):
                        out["grazings" if grazed else "folds"].append(
                            {"segments": grazed, **{c: point[c] for c in COLUMNS}})
                    checked = any(abs(point["V"] - v) < AT_SPEED for v in checks)
                    if ty == "UZ" and mask[i] and checked:
                        out["at"].append({"V": point["V"],
                                          "psi_amp": segmented.amplitude(point),
                                          "freq": 1.0 / segmented.period(point)})
    return out


def _sorted(xs, ys):
    order = numpy.argsort(xs)
    return numpy.asarray(xs)[order], numpy.asarray(ys)[order]


def check(values: Mapping[str, float],
          solutions: Sequence[Mapping[str, Any]]) -> List[Dict[str, Any]]:
    """The solutions (at the check speeds) against the event-located
    simulation there:
    [{V, AUTO's and the simulation's psi amplitude and frequency, relative
    errors}]."""
    rows = []
    for point in sorted(solutions, key=lambda p: p["V"]):
        sim = simulator.simulate(None, "--set", "figures", "--V", point["V"], *CHECK_RUN,
                                 params=segmented.law14(values))
        rows.append({"family": point["family"], "V": point["V"], "amp_auto": point["psi_amp"],
                     "amp_sim": sim["psi_amplitude_rad"], "freq_auto": point["freq"],
                     "freq_sim": sim["frequency_hz"],
                     "amp_rel": point["psi_amp"] / sim["psi_amplitude_rad"] - 1.0,
                     "freq_rel": point["freq"] / sim["frequency_hz"] - 1.0})
        print(f"segmented: V = {point['V']:g} m/s: psi amplitude {point['psi_amp']:.10e} "
              f"(simulation {sim['psi_amplitude_rad']:.10e}), frequency {point['freq']:.8f} "
              f"Hz (simulation {sim['frequency_hz']:.8f})", flush=True)
    return rows


def rolling(values: Mapping[str, float]) -> Dict[str, Any]:
    """Straight rolling of eq. (14): its Hopf points by name and the speeds
    where it is stable."""
    law = segmented.law14(values)
    hopf = naming.scanned("figures", "V", ct.SPEED_SCAN, **law)
    changes = [v for v, _, _ in spectrum.stability_changes("figures", "V", ct.SPEED_SCAN, **law)]
    return {"hopf": hopf, "stable": spectrum.stable_intervals("figures", "V", changes, ct.V_MIN,
                                                              ct.V_MAX, **law)}


def past_grazings(rundir: str, values: Mapping[str, float], families: Mapping[str, Any],
                  hopf: Mapping[str, float]) -> List[Dict[str, Any]]:
    """Each grazing continued past: the gap orbits from the Hopf point of
    straight rolling nearest it to the grazing's speed
    (segmented.gap_orbits); their branch, stability (the monodromy of the
    one midway), the amplitude where they end against the grazing orbit's,
    and the one midway against one period of the event-located simulation
    (segmented.one_period)."""
    model = mlgmodel.Model("figures", **segmented.law14(values))
    out = []
    for family, orbits in families.items():
        for k, g in enumerate(orbits["grazings"]):
            name, V_hopf = min(hopf.items(), key=lambda item: abs(item[1] - g["V"]))
            mid = 0.5 * (g["V"] + V_hopf)
            short = g["V"] + PAST_SHORT * (V_hopf - g["V"])
            bd = ct.reported(f"the gap orbits past the grazing at {g['V']:.6f} m/s", lambda: (
                segmented.gap_orbits(rundir, f"{family}-past{k + 1}", values, V_hopf, short,
                                     UZR={"V": [mid]}, **PAST_STEPS)))
            if bd is None:
                continue
            point = min(bd("UZ"), key=lambda p: abs(p["V"] - mid))   # not the stop's UZ
            end = bd[-1][-1]
            # V = a + b A^2 near a Hopf point: where the gap orbits reach the grazing's amplitude
            last = slice(-PAST_FIT, None)
            a, b = numpy.polynomial.polynomial.polyfit(
                numpy.asarray(bd[-1]["psi_amp"][last]) ** 2, bd[-1]["V"][last], 1)
            meets = float(a + b * g["psi_amp"] ** 2)
            verdict = segmented.stability(model.set(V=point["V"]), point)
            amp = segmented.amplitude(point)
            sim = segmented.one_period(values, point)
            branch = jobs.stored(bd, COLUMNS)
            for b in branch:       # AUTO's multipliers do not resolve |mu| - 1 ~ 1e-5
                b["stable"] = numpy.full(len(b["stable"]), verdict["stable"])
            out.append({"family": family, "hopf": name, "grazing": g["V"], "end": end["V"],
                        "meets": meets, "grazing_amp": g["psi_amp"],
                        "branch": branch, "largest": verdict["largest"],
                        "check": {"V": point["V"], "amp_auto": amp,
                                  "amp_sim": sim["psi_amplitude_rad"],
                                  "amp_rel": sim["psi_amplitude_rad"] / amp - 1.0,
                                  "closes": sim["closes"], "switches": sim["switches"]}})
            print(f"segmented: past the grazing at {g['V']:.8f} m/s: gap orbits from {name} "
                  f"({V_hopf:.8f}) reach its amplitude at {meets:.8f} m/s; at "
                  f"{point['V']:.6f} m/s |mu| = {verdict['largest']:.8f}, the simulation's "
                  f"amplitude {sim['psi_amplitude_rad']:.8e} against AUTO's {amp:.8e}, returns "
                  f"within {sim['closes']:.2e}, {sim['switches']} switches", flush=True)
    return out


def symmetry(values: Mapping[str, float], V: float) -> float:
    """How far the orbit the event-located simulation settles on at V is
    from symmetric: the relative difference of its two gap segments'
    durations (0 for the symmetric orbit, whose halves mirror each other);
    1 for an orbit that reaches one contact only."""
    orbit = segmented.simulated(dict(values), V)
    gaps = [T for T, m in zip(orbit["durations"], orbit["modes"]) if m == segmented.GAP]
    return abs(gaps[0] - gaps[1]) / max(gaps) if len(gaps) == 2 else 1.0


def boundary(at: Mapping[str, float]) -> Dict[str, Any]:
    """Fig. 12's stationary states under eq. (14): {"points": the BEPs on
    h+ (h- mirrors them, psi -> -psi), each with its pitchfork, psi, kind,
    sides and stability; "smoothed": {eps / y_fp: the pitchforks of the
    smoothed law (at's) in F*}; "orders": the fit of each pitchfork's
    P(eps) - P(0) where the smoothed law has as many; "approach": [per BEP,
    the smoothed yawed state's distance from the surface at its load, 1 -
    |y_tlk| / y_fp, at APPROACH], "approach_orders": their fits}."""
    law14 = segmented.law14({**at, **FIG12_CASE})
    found = [p for p in boundary_equilibria.from_pitchforks(law14, "Fstar", FIG12_LOADS)
             if p["surface"] == "freeplay_upper"]
    smoothed = {ratio: [v for v, kind, _ in spectrum.stability_changes(
        "figures", "Fstar", FIG12_LOADS, **{**at, **FIG12_CASE, "eps_rel": ratio}) if kind == "BP"]
        for ratio in freeplay.TABLE_RATIOS}
    orders = []
    for k, p in enumerate(found):
        near = [(r, forks[k] - p["pitchfork"]) for r, forks in smoothed.items()
                if len(forks) == len(found)]
        orders.append(convergence.fitted_order(*zip(*near), ROUNDING * p["pitchfork"])
                      if near else None)
    approach = [boundary_equilibria.smoothed_approach({**at, **FIG12_CASE}, p, "Fstar", APPROACH)
                for p in found]
    branches_ = yawed_branches(at, found)
    for p in found:
        print(f"segmented: Fig. 12 under eq. (14): pitchfork at F* = {p['pitchfork']:.10f}, "
              f"BEP at F* = {p['Fstar']:.10f}, psi = {p['psi']:.8e} rad ({p['kind']})", flush=True)
    return {"points": [{k: p[k] for k in ("pitchfork", "Fstar", "psi", "kind", "sides", "stable")}
                       for p in found],
            "smoothed": {f"{r:g}": forks for r, forks in smoothed.items()}, "orders": orders,
            "approach": approach, "branches": branches_,
            "approach_orders": [convergence.fitted_order([a["ratio"] for a in ap],
                                                         [a["gap"] for a in ap], 0.0)
                                for ap in approach]}


def yawed_branches(at: Mapping[str, float], found: Sequence[Mapping[str, Any]]) -> Dict[str, Any]:
    """Fig. 12's yawed states in (F*, y_tlk / y_fp), for the figure: eq.
    (14)'s gap branches from each BEP back to its pitchfork
    (boundary_equilibria.branch_in_psi), its contact+ states between the
    BEPs (on BRANCH_POINTS loads), and the smoothed law's largest yawed state
    (shared.yawed) at each of OVERLAY_RATIOS on YAW_LOADS and, near P2, on
    ZOOM_LOADS."""
    model = mlgmodel.Model("figures", **segmented.law14({**at, **FIG12_CASE}))
    held = [numpy.linspace(p["psi"], 0.0, BRANCH_POINTS + 1)[1:-1] for p in found]
    gap = [[(p["Fstar"], 1.0)] + boundary_equilibria.branch_in_psi(model, p, "Fstar", psis)
           + [(p["pitchfork"], 0.0)] for p, psis in zip(found, held)]
    contact, u = [], found[0]["u"]
    for F in numpy.linspace(found[0]["Fstar"], found[-1]["Fstar"], BRANCH_POINTS):
        u = boundary_equilibria.equilibrium_in_mode(model.set(Fstar=F), segmented.CONTACT_POS, u)
        contact.append((float(F), boundary_equilibria.tlk_ratio(model, u, "freeplay_upper")))
    zoom = numpy.linspace(found[-1]["Fstar"] - 2 * ZOOM_SPAN, found[-1]["pitchfork"] + ZOOM_SPAN,
                          BRANCH_POINTS)
    smoothed = {}
    for ratio in OVERLAY_RATIOS:
        freeplay_case = {"yfp": FIG12_CASE["yfp"], "eps_abs": 0.0, "eps_rel": ratio}
        points = []
        for F in numpy.r_[YAW_LOADS, zoom]:
            states = yawed.states("figures", float(F), freeplay_case, **at)["yawed"]
            m = yawed.model("figures", float(F), freeplay_case, **at)
            ratios = [boundary_equilibria.tlk_ratio(m, v, "freeplay_upper") for v in states]
            if ratios:
                points.append((float(F), max(ratios)))
        smoothed[f"{ratio:g}"] = points
    law = segmented.law14({**at, **FIG12_CASE})
    forks = [p["pitchfork"] for p in found]
    stable = spectrum.stable_intervals("figures", "Fstar", forks, 0.0, YAW_LOADS[-1], **law)
    return {"gap": gap, "contact": contact, "smoothed": smoothed, "rolling_stable": stable}


def numbers(result: Mapping[str, Any]) -> Dict[str, float]:
    """The named points of the reference set (tests/reference/segmented):
    straight rolling's Hopf points, each family's folds and grazings, AUTO's
    and the simulation's orbits at the check speeds, Fig. 12's pitchforks
    and BEPs under eq. (14) and the fitted orders."""
    out = {f"{name} [m/s]": v for name, v in result["rolling"]["hopf"].items()}
    for family, orbits in result["families"].items():
        out.update({f"{family} fold {k + 1} [m/s]": p["V"] for k, p in enumerate(orbits["folds"])})
        out.update({f"{family} grazing {k + 1} [m/s]": g["V"]
                    for k, g in enumerate(orbits["grazings"])})
        out.update({f"{family} {kind} {k + 1} [m/s]": V
                    for k, (V, kind, _, _) in enumerate(orbits["changes"])})
    for r in result["check"]:
        at = f"{r['family']} at {round(r['V'], 2):g} m/s"
        out.update({f"{at}: psi amplitude [rad]": r["amp_auto"],
                    f"{at}: frequency [Hz]": r["freq_auto"],
                    f"{at}: psi amplitude simulated [rad]": r["amp_sim"],
                    f"{at}: frequency simulated [Hz]": r["freq_sim"]})
    for k, p in enumerate(result["past"]):
        before = sum(q["family"] == p["family"] for q in result["past"][:k])
        at = f"{p['family']} past its grazing {before + 1}"
        out.update({f"{at}: gap orbits reach its amplitude [m/s]": p["meets"],
                    f"{at}: psi amplitude midway [rad]": p["check"]["amp_auto"]})
    found = result["boundary"]
    for k, (p, fit, ap) in enumerate(zip(found["points"], found["orders"],
                                         found["approach_orders"])):
        out.update({f"P{k + 1} [F*] (Fig. 12)": p["pitchfork"], f"BEP{k + 1} [F*] (Fig. 12)":
                    p["Fstar"], f"BEP{k + 1} psi [rad] (Fig. 12)": p["psi"]})
        if fit:
            out[f"P{k + 1} [F*] (Fig. 12): p fitted"] = fit["p"]
        if ap:
            out[f"BEP{k + 1} approach (Fig. 12): p fitted"] = ap["p"]
    return out


def compute() -> Dict[str, Any]:
    at = gear.parameters()
    values = {**at, **CASE}
    rundir = paths.rundir(FIGURE)
    families = {family: orbit_branches(rundir, family, values) for family in FAMILIES}
    for orbits in families.values():   # a pitchfork: the simulation on either side
        orbits["pitchforks"] = [{"V": V, "below": symmetry(values, V - SIDE),
                                 "above": symmetry(values, V + SIDE)}
                                for V, kind, _, _ in orbits["changes"] if kind == "BP"]
    rows = check(values, [{**p, "family": f} for f, o in families.items() for p in o.pop("at")])
    straight = rolling(values)
    past = past_grazings(rundir, values, families, straight["hopf"])
    print("segmented: eq. (15) at eps = 0.1 y_fp, for the overlay", flush=True)
    smooth = ct.speed_diagram(paths.rundir(f"{FIGURE}/smoothed"), "figures", {**at, **SMOOTHED},
                              figure=FIGURE, **ct.SPEED_ORBIT_STEPS)
    result = {"families": families, "check": rows, "rolling": straight, "past": past,
              "boundary": boundary(at),
              "smoothed": [jobs.stored(run, COLUMNS) for _, run in smooth.parts],
              "smoothed_hopf": smooth.hopf}
    return {**result, "numbers": numbers(result)}


def text(result: Mapping[str, Any]) -> str:
    lines = ["segmented: Fig. 10 (F* = 1, y_fp = 1 mm) under eq. (14)", ""]
    lines += [f"  {name} = {v:.6f} m/s (straight rolling, eigenvalue scan)"
              for name, v in result["rolling"]["hopf"].items()]
    for family, orbits in result["families"].items():
        lines += ["", f"  {family} orbits, segments " + ", ".join(orbits["modes"]) + ":"]
        lines += [f"  S = {p['V']:.6f} m/s (fold, psi amplitude {p['psi_amp']:.6e} rad)"
                  for p in orbits["folds"]]
        lines += [f"  grazing at V = {g['V']:.6f} m/s (the duration of segment"
                  f"{'s' if len(g['segments']) > 1 else ''} "
                  f"{', '.join(map(str, g['segments']))} reaches 0)"
                  for g in orbits["grazings"]]
        lines += [f"  stability change ({kind}) at V = {V:.4f} m/s (between {min(a, b):.4f} and "
                  f"{max(a, b):.4f})" for V, kind, a, b in orbits["changes"]]
        lines += [f"  at the pitchfork {p['V']:.4f} m/s the simulation's gap segments differ by "
                  f"{p['below']:.1e} at {p['V'] - SIDE:.2f} m/s, {p['above']:.1e} at "
                  f"{p['V'] + SIDE:.2f} m/s (0: the symmetric orbit; 1: one contact only)"
                  for p in orbits.get("pitchforks", [])]
    lines += ["", f"  the stable orbits against the event-located simulation (tolerance "
              f"{TOLERANCE:g} relative):",
              "  orbits          V [m/s]  psi amp AUTO [rad]  psi amp sim. [rad]  rel.      "
              "freq AUTO [Hz]  freq sim. [Hz]  rel."]
    for r in result["check"]:
        lines.append(f"  {r['family']:<14}  {r['V']:<7g}  {r['amp_auto']:.10e}    "
                     f"{r['amp_sim']:.10e}    {r['amp_rel']:+.2e} {r['freq_auto']:.8f}     "
                     f"{r['freq_sim']:.8f}     {r['freq_rel']:+.2e}")
    lines += ["", "  past each grazing, the orbits of the gap mode alone (the standard model) "
              "from the Hopf point nearest it, to the grazing orbit's amplitude:"]
    for p in result["past"]:
        c = p["check"]
        lines += [f"  {p['family']}: from {p['hopf']} towards the grazing at "
                  f"{p['grazing']:.8f} m/s: they reach the grazing orbit's psi amplitude at "
                  f"{p['meets']:.8f} m/s;",
                  f"    at V = {c['V']:.6f} m/s {'stable' if p['largest'] < 1 else 'unstable'} "
                  f"(|mu| = 1 {p['largest'] - 1:+.1e}); one period simulated from AUTO's orbit: "
                  f"psi amplitude {c['amp_rel']:+.2e} relative, returns within {c['closes']:.2e}, "
                  f"{c['switches']} switches crossed"]
    return "\n".join(lines + boundary_text(result["boundary"])) + "\n"


def boundary_text(found: Mapping[str, Any]) -> List[str]:
    """The table's lines on Fig. 12's BEPs and the smoothed pitchforks."""
    lines = ["", "  Fig. 12 under eq. (14) (V = 50 m/s, y_fp = 1 mm): straight rolling's "
             "pitchforks P in the gap, and the",
             "  boundary-equilibrium points (BEP) where their yawed states reach y_tlk = y_fp "
             "(psi -> -psi: -y_fp):",
             "  P [F*]        BEP [F*]      P - BEP     psi at BEP [rad]  kind         gap "
             "admissible  stable there"]
    for p in found["points"]:
        side = "above" if p["sides"]["gap"] > 0 else "below"
        stable = ", ".join(m for m, ok in p["stable"].items() if ok) or "neither"
        lines.append(f"  {p['pitchfork']:.10f}  {p['Fstar']:.10f}  "
                     f"{p['pitchfork'] - p['Fstar']:+.3e}  {p['psi']:.8e}    {p['kind']:<11}  "
                     f"{side} the BEP     {stable}")
    ratios = list(found["smoothed"])
    lines += ["", "  the smoothed law's pitchforks, P(eps) - P(0) at eps / y_fp = "
              + ", ".join(ratios) + " (-: none), fitted order:"]
    for k, (p, fit) in enumerate(zip(found["points"], found["orders"])):
        cells = [f"{forks[k] - p['pitchfork']:+.3e}" if len(forks) == len(found["points"]) else "-"
                 for forks in found["smoothed"].values()]
        lines.append(f"  P{k + 1}: " + "  ".join(cells)
                     + (f"   p = {fit['p']:.2f}" if fit else ""))
    lines += ["", "  the smoothed law's yawed state at each BEP's load: 1 - |y_tlk| / y_fp at "
              "eps / y_fp = " + ", ".join(f"{r:g}" for r in APPROACH) + ", fitted order:"]
    for k, (ap, fit) in enumerate(zip(found["approach"], found["approach_orders"])):
        lines.append(f"  BEP{k + 1}: " + "  ".join(f"{a['gap']:.4e}" for a in ap)
                     + (f"   p = {fit['p']:.2f}" if fit else ""))
    return lines


def plot(result: Mapping[str, Any]) -> None:
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from mlgshimmy.shared import draw

    table = text(result)
    jobs.write_text(f"{paths.tables_dir()}/{FIGURE}.txt", table)
    print(table, end="")
    families = result["families"].values()
    ours = [jobs.loaded(orbits["branches"]) for orbits in families]
    folds = [p for orbits in families for p in orbits["folds"]]
    smoothed = [jobs.loaded(run) for run in result["smoothed"]]
    fig = plt.figure(figsize=(10, 7.4))
    grid = fig.add_gridspec(2, 2, width_ratios=(1.6, 1))
    amp, zoom, freq = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1]), \
        fig.add_subplot(grid[1, 0])
    stable = result["rolling"]["stable"]
    edges = sorted({ct.V_MIN, ct.V_MAX, *[v for ab in stable for v in ab],
                    *result["rolling"]["hopf"].values()})
    for ax, column, scale in ((amp, "psi_amp", draw.DEG), (zoom, "psi_amp", draw.DEG),
                              (freq, "freq", 1.0)):
        for runs in smoothed:
            draw.plot_branch(ax, runs, "V", column, scale=scale, color=draw.palette.GUIDE)
        for branch in ours:
            draw.plot_branch(ax, branch, "V", column, scale=scale)
        if column == "psi_amp":
            for a, b in zip(edges, edges[1:]):
                ok = any(lo <= 0.5 * (a + b) <= hi for lo, hi in stable)
                ax.plot([a, b], [0, 0], **draw.style_of(ok))
        for k, p in enumerate(folds):
            draw.mark(ax, p["V"], p[column] * scale, "LP", name=f"S{k + 1}" if k else "S")
        for orbits, branch in zip(families, ours):
            # in (a1) the points below the zoom's 160 m/s are left to the zoom
            low = ZOOM_V if ax is amp else 0.0
            for g in orbits["grazings"]:
                if g["V"] > low:
                    draw.mark(ax, g["V"], g[column] * scale, "GR")
            for V, kind, _, _ in [c for c in orbits["changes"] if c[0] > low]:
                y = numpy.interp(V, *_sorted(numpy.concatenate([b["V"] for b in branch]),
                                             numpy.concatenate([b[column] for b in branch])))
                draw.mark(ax, V, y * scale, kind)
        if column == "psi_amp":
            for name, V in result["rolling"]["hopf"].items():
                draw.mark(ax, V, 0.0, "HB", name=name)
        ax.set_xlabel("V [m/s]")
    for r in result["check"]:
        amp.plot(r["V"], r["amp_sim"] * draw.DEG, "x", color=draw.palette.MARKER, ms=6)
        freq.plot(r["V"], r["freq_sim"], "x", color=draw.palette.MARKER, ms=6)
    for ax in (amp, zoom):
        ax.set_ylabel(r"$\psi$ amplitude [deg]")
    amp.set_xlim(0, ct.V_MAX)
    amp.set_title("(a1) torsional amplitude")
    zoom.set_xlim(0, ZOOM_V)
    zoom.set_ylim(-0.01, 0.3)
    zoom.set_title("(a2) zoom of (a1)")
    freq.set_xlim(0, ct.V_MAX)
    freq.set_ylabel("frequency [Hz]")
    freq.set_title("(b) frequency")
    extra = [Line2D([], [], color=draw.palette.GUIDE,
                    label=r"eq. (15), $\epsilon$ = 0.1 $y_{fp}$ (stable solid, unstable dashed)"),
             Line2D([], [], ls="", marker="x", color=draw.palette.MARKER,
                    label="event-located simulation")]
    graze = fig.add_subplot(grid[1, 1])
    grazing_panel(graze, result, ours)
    draw.figure_title(fig, r"Fig. 10 under eq. (14): $F_z^*$ = 1, $y_{fp}$ = 1 mm, "
                      "segmented orbits")
    fig.tight_layout()
    draw.legend(fig, extra=extra, axes=(amp, zoom, freq, graze))   # below the panels
    draw.save(fig, FIGURE)
    fig12_plot(result["boundary"])


def fig12_plot(found: Mapping[str, Any]) -> None:
    """segmented_fig12.png: Fig. 12's yawed states in (F*, y_tlk / y_fp) at
    V = 50 m/s under eq. (14) (its gap and contact branches, the
    pitchforks P and the BEPs B) and under eq. (15) at OVERLAY_RATIOS; (a)
    Fig. 12's yawed range, (b) near P2."""
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.ticker import MaxNLocator
    from mlgshimmy.shared import draw

    branches_ = found["branches"]
    fig, (full, zoom) = plt.subplots(1, 2, figsize=(10, 4.8))
    colours = dict(zip(branches_["smoothed"], draw.sequence(len(branches_["smoothed"]))))
    forks = [p["pitchfork"] for p in found["points"]]
    last = found["points"][-1]
    for ax, (lo, hi) in ((full, (0.0, YAW_LOADS[-1])),
                         (zoom, (last["Fstar"] - 2 * ZOOM_SPAN, last["pitchfork"] + ZOOM_SPAN))):
        ax.axhline(1.0, color=draw.palette.GUIDE, lw=3, zorder=0)
        for ratio, points in branches_["smoothed"].items():
            inside = sorted(p for p in points if lo <= p[0] <= hi)
            if inside:
                ax.plot(*numpy.array(inside).T, color=colours[ratio], lw=1.2)
        for branch in branches_["gap"] + [branches_["contact"]]:
            F, y = numpy.array(branch).T
            ax.plot(F, y, **{**draw.style_of(True), "lw": 2.0})
        edges = sorted({lo, hi, *[f for f in forks if lo < f < hi]})
        for a, b in zip(edges, edges[1:]):
            ok = any(s <= 0.5 * (a + b) <= e for s, e in branches_["rolling_stable"])
            ax.plot([a, b], [0.0, 0.0], **{**draw.style_of(ok), "lw": 2.0})
        for k, p in enumerate(found["points"]):
            draw.mark(ax, p["pitchfork"], 0.0, "BP", name=f"P{k + 1}")
            draw.mark(ax, p["Fstar"], 1.0, "BEP", name=f"B{k + 1}")
        ax.set_xlim(lo, hi)
        ax.set_xlabel(r"$F_z^*$")
    full.set_ylim(-0.05, 1.12)
    zoom.set_ylim(-0.05, 1.12)
    zoom.ticklabel_format(axis="x", useOffset=False)
    zoom.xaxis.set_major_locator(MaxNLocator(5))
    full.set_ylabel(r"$y_{tlk} / y_{fp}$ of the yawed state ($\psi > 0$)")
    full.set_title("(a) the yawed states between the pitchforks")
    zoom.set_title("(b) zoom near P2")
    extra = [Line2D([], [], **{**draw.style_of(True), "lw": 2.0},
                    label="eq. (14): gap, then contact"),
             Line2D([], [], color=draw.palette.GUIDE, lw=3,
                    label=r"contact edge $y_{tlk} = y_{fp}$")]
    extra += [Line2D([], [], color=c, lw=1.2, label=rf"eq. (15), $\epsilon$ = {r} $y_{{fp}}$")
              for r, c in colours.items()]
    draw.figure_title(fig, r"Fig. 12's yawed states under eq. (14): V = 50 m/s, $y_{fp}$ = 1 mm")
    fig.tight_layout()
    draw.legend(fig, extra=extra, stability=False)
    draw.save(fig, f"{FIGURE}_fig12")


def grazing_panel(ax: Any, result: Mapping[str, Any], ours: Sequence[Any]) -> None:
    """(c): the high-frequency orbits on both sides of their grazing near H3:
    the segmented orbits up to it, the gap mode's from H3 beyond it."""
    from matplotlib.ticker import FuncFormatter
    from mlgshimmy.shared import draw

    past = [p for p in result["past"] if p["family"] == "high-frequency"]
    if not past:
        ax.set_axis_off()
        return
    p = past[0]
    V_hopf = result["rolling"]["hopf"][p["hopf"]]
    width = V_hopf - p["grazing"]
    for branch in ours[:1] + [jobs.loaded(p["branch"])]:
        draw.plot_branch(ax, branch, "V", "psi_amp", scale=draw.DEG)
    grazed = next(g for g in result["families"]["high-frequency"]["grazings"]
                  if g["V"] == p["grazing"])
    draw.mark(ax, p["grazing"], grazed["psi_amp"] * draw.DEG, "GR")
    draw.mark(ax, V_hopf, 0.0, "HB", name=p["hopf"])
    lo, hi = p["grazing"] - 4 * width, V_hopf + 2 * width
    for a, b in ((lo, V_hopf), (V_hopf, hi)):
        ok = any(s <= 0.5 * (a + b) <= e for s, e in result["rolling"]["stable"])
        ax.plot([a, b], [0, 0], **draw.style_of(ok))
    ax.plot(p["check"]["V"], p["check"]["amp_sim"] * draw.DEG, "x", color=draw.palette.MARKER,
            ms=6)
    ax.set_xlim(lo, hi)
    ax.set_ylim(-0.02 * grazed["psi_amp"] * draw.DEG, 1.15 * grazed["psi_amp"] * draw.DEG)
    ax.set_xticks(V_hopf + 1e-3 * numpy.arange(numpy.ceil((lo - V_hopf) / 1e-3),
                                                  numpy.floor((hi - V_hopf) / 1e-3) + 1))
    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{1e3 * (v - V_hopf):.0f}"))
    ax.set_xlabel(f"V - {p['hopf']} [mm/s] ({p['hopf']} = {V_hopf:.4f} m/s)")
    ax.set_ylabel(r"$\psi$ amplitude [deg]")
    ax.set_title(f"(c) past the grazing G near {p['hopf']}: gap orbits")


if __name__ == "__main__":
    jobs.run_figure(FIGURE, compute, plot, module="mlgshimmy.studies.segmented")
