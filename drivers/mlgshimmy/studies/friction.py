"""Oleo seal friction against the low-speed shimmy (docs/model.md 10): the
critical friction moment M_f* above which Fig. 10's low-frequency orbits
(the shimmy between H1 and H2) no longer exist, and how it depends on the
regularisation speed v_fric and on the freeplay.

Straight rolling cannot answer it: at zero slip the regularised law is a
viscous damper M_fric r_seal / v_fric, so its Hopf points do not converge
as v_fric -> 0.  The orbits can.  For each case (a v_fric of LADDER at
Fig. 10's y_fp = 1 mm, and each y_fp of FREEPLAYS at v_fric = FREEPLAY_V):
  1. the low-frequency orbits from H1 at zero friction, continued in V up
     to V_END (V0 labelled);
  2. the orbit at V0 continued in M_fric up to its fold (LP);
  3. that fold continued in (V, M_fric) both ways, to where it meets
     straight rolling's Hopf curve (the orbits' amplitude goes to zero):
     above the fold curve there is no low-frequency orbit at that V.
M_f* is the fold curve's largest M_fric, with the speed where it lies.
Below the fold curve's ends the orbits shrink onto straight rolling at its
Hopf curve instead; that curve's largest M_fric (linear_threshold, from the
eigenvalues alone) must lie below M_f*, or the case is refused.  Its equivalent damping ratio is that of the viscous
damper dissipating as much per cycle on the zero-friction orbit there,
4 M / (pi omega A), relative to the torsional critical damping
2 sqrt(k_tlk r_tlk^2 I_psi) (links engaged).

The regularised law is checked against Coulomb's own (the simulator's
exact stick-slip, friction_law 1): at each rung of the ladder the orbit at
M_fric = CHECK_M (met in step 2) is continued in V, and its amplitude and
frequency at CHECK_V set against the settled simulated stick-slip there.

    make friction              # compute (cached) and plot: build/figures/friction.png
"""
from __future__ import annotations

import math
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import draw
from mlgshimmy.shared import gear
from mlgshimmy.shared import jobs
from mlgshimmy.shared import kappa_criterion
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import naming
from mlgshimmy.shared import paper
from mlgshimmy.shared import paths
from mlgshimmy.shared import simulator
from mlgshimmy.shared import spectrum

DECLARED = {
    "friction": {
        "help": "oleo seal friction: the critical M_fric of the low-speed shimmy, v_fric ladder",
        "time": "15 min",
        "report": {
            "command": "make friction",
            "text": ("Beyond the paper: the oleo seal friction moment above which Fig. 10's "
                     "low-frequency orbits no longer exist, against the regularisation speed "
                     "and the freeplay (docs/friction.md)."),
            "tables": ["tables/friction.txt"],
            "figures": ["figures/friction.png"],
        },
    },
}

CONDITIONS = {"Fstar": 1.0, "eps_abs": 0.0, "eps_rel": 0.1}   # Fig. 10's, y_fp apart
LADDER = (3e-3, 1e-3, 3e-4, 1e-4)       # m/s: v_fric, coarse to fine
FREEPLAYS = (0.5, 1.0, 2.0)             # mm
FREEPLAY_V = 3e-4                       # m/s: converged to 0.1 % at y_fp = 1 mm (the ladder)
V0 = 10.0              # m/s: where the orbit is continued in M_fric (inside H1-H2)
H_GRID = numpy.linspace(0.5, 80.0, 400)  # the scan for H1, H2 (m/s)
M_STOP = 1000.0        # N m: beyond any fold found
COLLAPSED_END = 0.05   # a fold curve's end below this part of its largest amplitude meets
                       # the Hopf curve; at this part of the fold's M_fric at V0 it
                       # stops, on its way to zero friction; any other end is a
                       # truncated curve: an error
FOLD_DSMAX = 0.2       # the fold curve's steps (AUTO units), short near M_fric = 0
STEPS = {"DS": 0.05, "DSMAX": 0.5}
# the exact stick-slip check (friction_law 1 in the simulator): the regularised
# orbits at CHECK_M, continued in V from V0, against the simulated settled shimmy
CHECK_M = 5.0                       # N m: a third of M_f* at y_fp = 1 mm
CHECK_V = (5.0, 10.0, 15.0, 20.0)   # m/s: inside the orbits' range at every rung
SETTLE = 20.0                       # s simulated; measured over the last second
# eq. (17)'s kappa* with the regularised law, which straight rolling sees as the
# damper c_eq = M_fric r_seal / v_fric: at these equivalent damping ratios
# c_eq / (2 sqrt(k_tlk r_tlk^2 I_psi)), SAE 902015's 1-10 % and beyond
KAPPA_ZETA = (0.0, 0.005, 0.01, 0.03, 0.1, 1.0)
KAPPA_V = 1e-3                      # m/s: v_fric of those runs (only c_eq matters)
# the fold in M_fric is sharp at small v_fric: AUTO turns it only with DSMIN
# 1e-9 (1e-5 stops there, MX); the fold curve ends on the Hopf curve, where
# 1e-6 stops it once the amplitude is near zero


def low_frequency_pairs(values: Mapping[str, float]) -> List[Tuple[float, float]]:
    """The low-frequency Hopf points of straight rolling on H_GRID (V, Hz)."""
    return [(v, f) for v, f in spectrum.hopf_scan("figures", "V", H_GRID, **values)
            if f < naming.HIGH_HZ]


def low_frequency_hopf(values: Mapping[str, float]) -> List[Tuple[float, float]]:
    """H1 and H2 of straight rolling at zero friction (V, Hz): the first two
    low-frequency Hopf points of the eigenvalue scan."""
    low = low_frequency_pairs(values)
    if len(low) < 2:
        raise RuntimeError(f"friction: no low-frequency Hopf pair H1, H2 below "
                           f"{H_GRID[-1]} m/s at {values}")
    return low[:2]


def linear_threshold(values: Mapping[str, float]) -> float:
    """The least M_fric at which straight rolling has no low-frequency Hopf
    point on H_GRID (its linearisation: a damper M_fric r_seal / v_fric on
    the twist), to 1e-6 relative: the Hopf curve's largest M_fric."""
    def has_pair(moment):
        return bool(low_frequency_pairs({**values, "M_fric": moment}))
    hi = 1.0
    while has_pair(hi):
        hi *= 2.0
    return spectrum.bisect(has_pair, 0.0, hi, tol=1e-6 * hi)


def orbit_at_v0(rundir: str, tag: str,
                values: Mapping[str, float]) -> Tuple[float, float, Any, Any]:
    """Step 1: H1, H2 and the zero-friction low-frequency orbits from H1 in
    V up to 0.95 H2, with the orbit at V0 (an AUTO solution)."""
    (h1, _), (h2, _) = low_frequency_hopf(values)
    hopf = ct.hopf_points(rundir, "hb", "figures", "V", numpy.linspace(0.5, h1 + 1.0, 20),
                          limit=1, **values)[0]
    orbits = ct.periodic_from(rundir, "po", hopf, "V", stop={"V": [0.95 * h2]},
                              UZR={"V": [V0]}, DS=0.05, DSMAX=0.5)
    at_v0 = [p for p in orbits("UZ") if abs(p["V"] - V0) < 1e-6]
    if not at_v0:
        raise RuntimeError(f"friction {tag}: the low-frequency orbits from H1 = {h1:.4g} m/s "
                           f"do not reach V0 = {V0} m/s")
    return h1, h2, orbits, at_v0[0]


def fold_in_friction(rundir: str, tag: str, orbit: Any) -> Any:
    """Step 2: the orbit continued in M_fric to its fold: (the LP solution,
    the orbit at CHECK_M on the way).  Past the fold the orbits shrink onto
    straight rolling, where AUTO may stop (MX): only the fold is used."""
    run = ct.periodic_from(rundir, "mf", orbit, "M_fric", stop={"M_fric": [M_STOP]},
                           UZR={"M_fric": [CHECK_M]}, NMX=3000, allow_mx=True, DSMIN=1e-9,
                           **STEPS)
    if not run("LP"):
        raise RuntimeError(f"friction {tag}: the orbit at V0 = {V0} m/s has no fold in M_fric "
                           "(its branch shrinks onto straight rolling: v_fric too large)")
    fold = run("LP")[0]
    level = [p for p in run("UZ") if abs(p["M_fric"] - CHECK_M) < 1e-6 < fold["M_fric"] - CHECK_M]
    if not level:
        raise RuntimeError(f"friction {tag}: the orbit at V0 = {V0} m/s folds at M_fric = "
                           f"{fold['M_fric']:.4g} N m, below CHECK_M = {CHECK_M}")
    return fold, level[0]


def orbits_at_speeds(rundir: str, orbit: Any) -> Dict[str, Dict[str, float]]:
    """The orbit at CHECK_M (and V0) continued in V both ways: {V: (psi_amp
    [rad], freq [Hz])} at each of CHECK_V, the first met from V0."""
    found = {V0: (orbit["psi_amp"], orbit["freq"])}
    for name, ds, end in (("cv_up", 0.05, max(CHECK_V) + 1.0), ("cv_down", -0.05,
                                                                 min(CHECK_V) - 1.0)):
        run = ct.periodic_from(rundir, name, orbit, "V", stop={"V": [end]},
                               UZR={"V": list(CHECK_V)}, DS=ds, DSMAX=0.5)
        # a point there, whatever AUTO typed it (a UZ may come out as BP)
        for p in (p for branch in run for p in branch):
            for v in CHECK_V:
                if abs(p["V"] - v) < 1e-6:
                    found.setdefault(v, (p["psi_amp"], p["freq"]))
    missing = [v for v in CHECK_V if v not in found]
    if missing:
        raise RuntimeError(f"friction: the orbits at M_fric = {CHECK_M} N m do not reach "
                           f"V = {missing} m/s")
    return {str(v): {"psi_amp": float(found[v][0]), "freq": float(found[v][1])} for v in CHECK_V}


def stick_slip(V: float, psi0: float, values: Mapping[str, float]) -> Dict[str, Any]:
    """The exact Coulomb law (friction_law 1) simulated from straight rolling
    with psi displaced by psi0, SETTLE s: the settled shimmy's half
    peak-to-peak psi [rad] and frequency [Hz] over the last second, and the
    slip-to-stick transitions."""
    freeplay = {k: values[k] for k in ("yfp", "eps_abs", "eps_rel")}
    params = {**gear.simulator_params(), "M_fric": CHECK_M, "friction_law": 1}
    out = simulator.simulate(None, *simulator.start_args(V, values["Fstar"], freeplay, None,
                                                         psi0, SETTLE, 1e-4, params))
    return {"psi_amp": out["psi_amplitude_rad"], "freq": out["frequency_hz"],
            "sticks": int(out["crossings_slip_pos"] + out["crossings_slip_neg"])}


def fold_in_speed_and_friction(rundir: str, tag: str, fold: Any) -> Dict[str, List[float]]:
    """Step 3: the fold continued in (V, M_fric) both ways, up to the Hopf
    curve, or zero friction, at each end: {V, M_fric, psi_amp, freq} along it."""
    # a step past M_fric = 0 leaves the domain, and AUTO's fold system turns
    # that into NaN, not a shorter step: the curve stops at a small M_fric
    floor = COLLAPSED_END * fold["M_fric"]
    halves = ct.fold_curve(rundir, "fold", fold, parameters=("V", "M_fric"),
                           stop={"V": [0.5, H_GRID[-1]], "M_fric": [floor]}, both_ways=True,
                           NMX=400, allow_mx=True, DSMIN=1e-6,
                           **{**STEPS, "DSMAX": FOLD_DSMAX})
    curve = {k: numpy.concatenate([halves[1][0][k][::-1], halves[0][0][k]])
             for k in ("V", "M_fric", "psi_amp", "freq")}
    largest = numpy.max(curve["psi_amp"])
    for end in (0, -1):
        # AUTO stops within its location tolerance of the floor (5.4e-6 seen)
        frictionless = curve["M_fric"][end] <= floor * (1.0 + 1e-4)
        if curve["psi_amp"][end] > COLLAPSED_END * largest and not frictionless:
            raise RuntimeError(f"friction {tag}: the fold curve stops at V = "
                               f"{curve['V'][end]:.4g} m/s with the orbits' amplitude "
                               f"{curve['psi_amp'][end]:.3g} rad: truncated, not at the Hopf curve")
    return curve


def case(tag: str, yfp: float, v_fric: float) -> Dict[str, Any]:
    """Steps 1-3 for one case: the fold curve, M_f* and the orbit it is
    measured against."""
    values = {**CONDITIONS, "yfp": yfp, "v_fric": v_fric, **gear.parameters()}
    rundir = paths.rundir(f"friction/{tag}")
    h1, h2, orbits, orbit = orbit_at_v0(rundir, tag, values)
    fold, level = fold_in_friction(rundir, tag, orbit)
    # the law's check, made once at the paper's gear
    checked = orbits_at_speeds(rundir, level) if yfp == 1.0 and gear.current().baseline else None
    curve = fold_in_speed_and_friction(rundir, tag, fold)
    k = int(numpy.argmax(curve["M_fric"]))
    if k in (0, len(curve["V"]) - 1):
        raise RuntimeError(f"friction {tag}: the largest M_fric lies at an end of the fold curve")
    branch = {name: numpy.asarray(orbits[0][name]) for name in ("V", "psi_amp", "freq")}
    order = numpy.argsort(branch["V"])
    V_star = float(curve["V"][k])
    if not min(branch["V"]) <= V_star <= max(branch["V"]):
        raise RuntimeError(f"friction {tag}: M_f* lies at V = {V_star:.4g} m/s, outside the "
                           f"zero-friction orbits ({min(branch['V']):.4g}-{max(branch['V']):.4g})")
    amp = float(numpy.interp(V_star, branch["V"][order], branch["psi_amp"][order]))
    freq = float(numpy.interp(V_star, branch["V"][order], branch["freq"][order]))
    linear = linear_threshold(values)
    if linear >= curve["M_fric"][k]:
        raise RuntimeError(f"friction {tag}: straight rolling keeps a low-frequency Hopf point "
                           f"up to M_fric = {linear:.4g} N m, above the fold curve's "
                           f"{curve['M_fric'][k]:.4g}: v_fric too large for the orbits to decide")
    return {"tag": tag, "yfp": yfp, "v_fric": v_fric, "H1": h1, "H2": h2,
            "fold_at_V0": float(fold["M_fric"]), "linear": linear,
            "critical": float(curve["M_fric"][k]), "at_V": V_star,
            "orbit": {"psi_amp": amp, "freq": freq},
            "zeta": equivalent_damping_ratio(values, float(curve["M_fric"][k]), amp, freq),
            "curve": {key: value.tolist() for key, value in curve.items()},
            "at_check_m": checked}


def torsional_critical(values: Mapping[str, float]) -> float:
    """2 sqrt(k_tlk r_tlk^2 I_psi) [N m s/rad]: the twist's critical damping
    with the links engaged, at straight rolling."""
    model = mlgmodel.Model("figures", V=V0, **values)
    r = model.r_tlk(model.equilibrium()["eta"])
    return 2.0 * math.sqrt(model["k_tlk"] * r * r * model["I_psi"])


def equivalent_damping_ratio(values: Mapping[str, float], moment: float, amplitude: float,
                             freq: float) -> float:
    """The viscous damping dissipating as much per cycle as a Coulomb moment
    on a harmonic twist of this amplitude and frequency, 4 M / (pi omega A),
    relative to torsional_critical."""
    omega = 2.0 * math.pi * freq
    return 4.0 * moment / (math.pi * omega * amplitude) / torsional_critical(values)


def kappa_against_friction() -> List[Dict[str, Any]]:
    """Eq. (17)'s kappa* (shared.kappa_criterion.criterion) with the regularised
    friction at each damping ratio of KAPPA_ZETA: [{zeta, c_eq, M_fric,
    kappa, Fstar, V, mode}]."""
    critical = torsional_critical({**CONDITIONS, "yfp": 1.0, **gear.parameters()})
    out = []
    for zeta in KAPPA_ZETA:
        moment = zeta * critical * KAPPA_V / mlgmodel.Model("figures")["r_seal"]
        model = {**gear.parameters(), "M_fric": moment, "v_fric": KAPPA_V}
        found = kappa_criterion.criterion(model)
        print(f"friction: kappa* = {found['kappa']:.4g} at damping ratio {zeta:g}", flush=True)
        out.append({"zeta": zeta, "c_eq": zeta * critical, "M_fric": moment, **found})
    return out


def cases() -> Dict[str, Tuple[float, float]]:
    """(tag, y_fp, v_fric) of the ladder and of the freeplays (shared ones once);
    at another gear (make friction RHO=10 MU=10) the converged rung alone."""
    if not gear.current().baseline:
        return {f"yfp1_v{FREEPLAY_V:g}": (1.0, FREEPLAY_V)}
    out = {f"yfp1_v{v:g}": (1.0, v) for v in LADDER}
    out.update({f"yfp{y:g}_v{FREEPLAY_V:g}": (y, FREEPLAY_V) for y in FREEPLAYS})
    return out


def exact_check(ladder: Sequence[Mapping[str, Any]]) -> Dict[str, Dict[str, Any]]:
    """The simulator's exact stick-slip at CHECK_M and each of CHECK_V, from
    the finest rung's orbit amplitude: {V: {psi_amp, freq, sticks}}."""
    finest = min(ladder, key=lambda c: c["v_fric"])
    values = {**CONDITIONS, "yfp": 1.0, **gear.parameters()}
    return {str(V): stick_slip(V, finest["at_check_m"][str(V)]["psi_amp"], values)
            for V in CHECK_V}


def compute() -> Dict[str, Any]:
    print("friction: critical seal friction of the low-frequency shimmy, Fig. 10's conditions"
          + gear.suffix())
    found = [case(tag, *args) for tag, args in cases().items()]
    ladder = [c for c in found if c["yfp"] == 1.0]
    return {"cases": found, "stick_slip": exact_check(ladder) if gear.current().baseline else {},
            "kappa": kappa_against_friction()}


def check_rows(result: Mapping[str, Any]) -> List[Tuple[float, float, float, float]]:
    """[(V, v_fric, relative amplitude difference, relative frequency
    difference)] of every rung against the exact stick-slip."""
    rows = []
    for c in sorted((c for c in result["cases"] if c["at_check_m"]), key=lambda c: -c["v_fric"]):
        for V in CHECK_V:
            exact, regular = result["stick_slip"][str(V)], c["at_check_m"][str(V)]
            rows.append((V, c["v_fric"], regular["psi_amp"] / exact["psi_amp"] - 1.0,
                         regular["freq"] / exact["freq"] - 1.0))
    return rows


def numbers(result: Mapping[str, Any]) -> Dict[str, Optional[float]]:
    """{quantity: value}: M_f* of every case, where it lies, and its damping ratio."""
    out = {}
    for c in result["cases"]:
        at = f"y_fp = {c['yfp']:g} mm, v_fric = {c['v_fric']:g} m/s"
        out[f"M_f* [N m], {at}"] = c["critical"]
        out[f"V at M_f* [m/s], {at}"] = c["at_V"]
        out[f"M_f* as damping ratio [%], {at}"] = 100.0 * c["zeta"]
        out[f"linear threshold (Hopf curve's largest M_fric) [N m], {at}"] = c["linear"]
    for V, exact in result["stick_slip"].items():
        at = f"M_fric = {CHECK_M:g} N m, V = {float(V):g} m/s"
        out[f"exact stick-slip psi amplitude [mrad], {at}"] = 1e3 * exact["psi_amp"]
        out[f"exact stick-slip frequency [Hz], {at}"] = exact["freq"]
    for k in result["kappa"]:
        at = (f"friction as damping ratio {100 * k['zeta']:g} % (c_eq = {k['c_eq']:.4g} "
              f"N m s/rad)")
        out[f"kappa* (eq. 17), {at}"] = k["kappa"]
    for V, v_fric, amp, freq in check_rows(result):
        at = f"M_fric = {CHECK_M:g} N m, V = {V:g} m/s, v_fric = {v_fric:g} m/s"
        out[f"regularised - exact, relative: psi amplitude, {at}"] = amp
        out[f"regularised - exact, relative: frequency, {at}"] = freq
    return out


def conclusions(result: Mapping[str, Any]) -> List[str]:
    """What the friction does to the paper's conclusions, in the result's
    numbers: the lines the report shows first."""
    finest = min((c for c in result["cases"] if c["yfp"] == 1.0), key=lambda c: c["v_fric"])
    zetas = [100 * c["zeta"] for c in result["cases"] if c["v_fric"] <= FREEPLAY_V]
    band = (f"{min(zetas):.2g}" if f"{min(zetas):.2g}" == f"{max(zetas):.2g}"
            else f"{min(zetas):.2g}-{max(zetas):.2g}")
    kappa = {k["zeta"]: k for k in result["kappa"]}
    gaps = [max(abs(a), abs(f)) for _, v, a, f in check_rows(result) if v == finest["v_fric"]]
    exact = [f"Exact stick-slip (simulator) against the regularised orbits at M_fric = "
             f"{CHECK_M:g} N m, V = {', '.join(f'{v:g}' for v in CHECK_V)} m/s: amplitude and "
             f"frequency within {max(gaps):.1g} (relative) at v_fric = {finest['v_fric']:g} m/s."
             ] if gaps else []
    return [
        f"Low-speed shimmy (H1-H2, Fig. 10): no low-frequency orbit exists above M_f* = "
        f"{finest['critical'] / finest['yfp']:.3g} N m per mm of freeplay (F* = 1), a Coulomb "
        f"damping ratio of {band} % of critical; "
        "SAE 902015 finds oleo friction below 1 % (severe) to above 10 % (favourable): "
        f"only seal friction below {max(zetas):.2g} % leaves the low-speed shimmy of Fig. 10.",
        f"Allowed freeplay, eq. (17): kappa* = {kappa[0.0]['kappa']:.3g} without friction; with "
        f"the regularised friction, a damper at straight rolling, {kappa[0.01]['kappa']:.3g} at "
        f"1 % and {kappa[0.1]['kappa']:.3g} at 10 %, {kappa[max(kappa)]['kappa']:.3g} at "
        f"{100 * max(kappa):g} % (set by the {kappa[max(kappa)]['mode']} mode). In Coulomb's "
        "limit the twist sticks at straight rolling and the linear criterion no longer measures "
        "the shimmy: M_f* does."] + exact


def plot(result: Mapping[str, Any]) -> None:
    import matplotlib.pyplot as plt
    ladder = [c for c in result["cases"] if c["yfp"] == 1.0]
    ladder.sort(key=lambda c: -c["v_fric"])
    steps = [abs(b["critical"] - a["critical"]) for a, b in zip(ladder, ladder[1:])]
    notes = [f"ladder: M_f* changes by {s:.3g} N m from v_fric = {a['v_fric']:g} to "
             f"{b['v_fric']:g} m/s" for s, a, b in zip(steps, ladder, ladder[1:])]
    notes += [f"kappa* = {k['kappa']:.4g} at friction damping ratio {100 * k['zeta']:g} %: "
              f"set by the {k['mode']} mode at F* = {k['Fstar']:.3g}, V = {k['V']:.4g} m/s"
              for k in result["kappa"]]
    paper.report("friction", numbers(result), notes=conclusions(result) + notes)
    fig, ((curves, trend), (exact, kappa)) = plt.subplots(2, 2, figsize=(11, 9))
    for c in sorted(result["cases"], key=lambda c: (c["yfp"], -c["v_fric"])):
        label = rf"$y_{{fp}}$ = {c['yfp']:g} mm, $v_\varepsilon$ = {c['v_fric']:g} m/s"
        line, = curves.plot(c["curve"]["V"], c["curve"]["M_fric"], label=label)
        curves.plot(c["at_V"], c["critical"], "o", color=line.get_color())
    curves.set_xlabel("V [m/s]")
    curves.set_ylabel(r"$M_f$ [N m]")
    curves.set_title("(a) fold of the low-frequency orbits: none above")
    curves.legend(fontsize=7)
    trend.semilogx([c["v_fric"] for c in ladder], [c["critical"] for c in ladder], "o-",
                   color=draw.STABLE)
    trend.set_xlabel(r"regularisation speed $v_\varepsilon$ [m/s]")
    trend.set_ylabel(r"$M_f^*$ [N m]")
    trend.set_title(r"(b) $M_f^*$ at $y_{fp}$ = 1 mm against $v_\varepsilon$")
    rows = check_rows(result)
    if not rows:
        exact.text(0.5, 0.5, "the law's exact check is made\nat the paper's gear (make friction)",
                   ha="center", va="center", transform=exact.transAxes)
    for V in CHECK_V if rows else ():
        mine = [(v, abs(amp)) for at, v, amp, _ in rows if at == V]
        exact.loglog([v for v, _ in mine], [gap for _, gap in mine], "o-",
                     label=f"V = {V:g} m/s")
    exact.set_xlabel(r"regularisation speed $v_\varepsilon$ [m/s]")
    exact.set_ylabel(r"|orbit's $\psi$ amplitude / stick-slip's $-$ 1|")
    exact.set_title(rf"(c) regularised orbits against exact stick-slip, $M_f$ = {CHECK_M:g} N m")
    if rows:
        exact.legend(fontsize=7)
    zetas = [100 * k["zeta"] for k in result["kappa"]]
    kappa.semilogx(zetas[1:], [k["kappa"] for k in result["kappa"][1:]], "o-",
                   color=draw.STABLE, label="with friction (regularised)")
    kappa.axhline(result["kappa"][0]["kappa"], color=draw.UNSTABLE, linestyle="--",
                  label="without friction")
    kappa.set_xlabel(r"friction as damping ratio $M_f r_s / (v_\varepsilon c_{crit})$ [%]")
    kappa.set_ylabel(r"$\kappa^*$ (eq. 17)")
    kappa.set_title(r"(d) $\kappa^*$: straight rolling sees the friction as a damper")
    kappa.legend(fontsize=7)
    draw.figure_title(fig, r"Seal friction: critical $M_f^*$ of the low-speed shimmy, "
                      r"$F^*$ = 1, $\epsilon = 0.1\,y_{fp}$")   # draw.save adds the gear
    fig.tight_layout()
    draw.save(fig, "friction")


if __name__ == "__main__":
    jobs.run_figure("friction", compute, plot, module="mlgshimmy.studies.friction")
