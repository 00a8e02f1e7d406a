"""Torus (TR) points of the large-amplitude shimmy orbits, checked two ways,
and their curves in (V, F*).

Cases (CASES): Fig. 7's branches at F* = 0.2 and 1 (zero freeplay) and the
high-frequency branch of Fig. 10 (F* = 1, y_fp = 1 mm, epsilon = 0.1 mm).
For each case:
  1. the orbit branch in V on several meshes (MESHES: NTST, NCOL); the TR
     speed is where a complex Floquet pair crosses |mu| = 1 (floquet.py);
  2. simulations started next to the orbit (psi displaced by the orbit's
     amplitude, at most PSI0_MAX) SIDE m/s below and above the first and
     the last TR speed: after the other modes have died out, the psi
     peaks' spread grows or decays at the critical pair's rate ln|mu| / T,
     which AUTO predicts;
  3. the torus curve in (V, F*), AUTO ISW = 2 from each TR point, labelled
     by steps that cross the unit circle in one go (floquet.py says why).
`torus.py [case ...]` (default: every case) writes each case's result to
$MLG_RUN_ROOT/torus/<case>/result.json and all cases found there to
$MLG_RUN_ROOT/torus/result.json (the curves as arrays, for Fig. 11).
`make torus`.
"""
import json
import math
import os
import sys
import tempfile

import numpy

import autoglue
import continuation as ct
import floquet
import paths
import spectrum

CASES = {"fig07_F0.2": {"Fstar": 0.2, "yfp": 0.0},
         "fig07_F1": {"Fstar": 1.0, "yfp": 0.0},
         "fig10_F1": {"Fstar": 1.0, "yfp": 1.0, "eps_rel": 0.1}}
# largest step in V: the freeplay branch folds sharply at S (as fig10.py)
DSMAX = {"fig07_F0.2": 5.0, "fig07_F1": 5.0, "fig10_F1": 1.0}
MESHES = ((80, 4), (160, 4), (80, 7))
V_MAX = 600.0
SIDE = 25.0            # m/s either side of the TR speed for the simulations
SIM_T = (20.0, 80.0)   # s: fit the log of the peak spread over this span
SPAN = 2.0             # s: one peak-spread sample per SPAN
PSI0_MAX = 0.1         # rad: a larger displacement at rest lifts a wheel off at
                       # F* = 1, V = 560 (the orbit's own amplitude is 0.265)
CURVE_FSTAR = (0.02, 3.5)
CURVE_STEPS = 150      # AUTO steps of a torus curve each way


def orbit_branch(rundir, name, values, mesh, dsmax):
    """The orbits born at the last Hopf point of straight rolling below
    V_MAX (zero freeplay: the only one; with freeplay: H3, whose branch folds
    back at S and then carries the large-amplitude orbits), continued in V."""
    grid = numpy.linspace(0.5, V_MAX, 3000)
    hopfs = [v for v, kind, _ in spectrum.stability_changes("figures", "V", grid, **values)
             if kind == "HB"]
    if not hopfs:
        raise RuntimeError(f"torus: no Hopf point below {V_MAX:g} m/s at {values}")
    hb = ct.hopf_point(rundir, f"{name}_hb", "figures", "V", hopfs[-1], **values)
    return ct.periodic_from(rundir, name, hb, stop={"V": [0.5, V_MAX]}, DS=0.05, DSMAX=dsmax,
                            NMX=3000, NTST=mesh[0], NCOL=mesh[1])


def crossings(rundir, name):
    return floquet.torus_crossings(floquet.read(os.path.join(rundir, f"d.{name}")))


def on_branch(bd, v, key):
    """A measure of the orbit branch at speed v (the stable large-amplitude
    part: the last pass of the branch through v)."""
    V, y = numpy.asarray(bd[0]["V"]), numpy.asarray(bd[0][key])
    k = numpy.nonzero((V[:-1] - v) * (V[1:] - v) <= 0)[0][-1]
    s = (v - V[k]) / (V[k + 1] - V[k])
    return float(y[k] + s * (y[k + 1] - y[k]))


def predicted_rate(steps, bd, v):
    """ln|mu| / T of the critical complex pair at the step nearest v [1/s]."""
    values = numpy.array([s[0] for s in steps])
    g, _ = floquet.critical(steps[int(numpy.argmin(numpy.abs(values - v)))][1])
    return math.log1p(g) * on_branch(bd, v, "freq")


def simulated_rate(values, v, psi0):
    """Growth rate [1/s] of the psi peaks' relative spread in a simulation
    from psi0 (log-linear fit over SIM_T, one sample per SPAN seconds)."""
    import attractor
    import simulator
    eps = 0.1 * values["yfp"]
    with tempfile.TemporaryDirectory() as tmp:
        csv = os.path.join(tmp, "run.csv")
        simulator.simulate(csv, "--set", "figures", "--V", v, "--Fstar", values["Fstar"],
                           "--yfp", values["yfp"], "--eps-abs", eps, "--eps-rel", 0,
                           "--t-end", SIM_T[1], "--psi0", psi0)
        data = numpy.loadtxt(csv, delimiter=",", skiprows=1, usecols=(0, 1))
    fit = attractor.spread_trend(data[:, 0], data[:, 1], SIM_T[0], SIM_T[1], SPAN)
    return fit["rate"], fit["first"], fit["last"]


def tr_point(rundir, name, bd, v, slope):
    """AUTO's TR label near speed v, a crossing of the branch bd (which ends
    at V_MAX): the branch's own label if it has one within 0.5 m/s; else
    back from the end to v + 3h, then fixed steps of -2h, one of them
    across, h such that |mu| - 1 changes by 4e-5 or more over a step (AUTO's
    count of stable multipliers, tolerance 1e-5, then changes with the
    sign; AUTO tests nothing on the first step after a restart).  Where
    AUTO still does not label it, h is doubled (twice)."""
    labelled = [p for p in bd("TR") if abs(p["V"] - v) < 0.5]
    if labelled:
        return labelled[0]
    end = [p for p in bd() if p["TY name"] in ("UZ", "EP")][-1]      # V = V_MAX
    for factor in (1, 2, 4):
        h = factor * max(2e-5 / abs(slope), 0.05)
        back = ct.run(rundir, f"{name}_back{factor}", "periodic", data=end,
                      ICP=["V", 11] + ct.MEASURES, DS=-1.0, DSMAX=5.0,
                      UZSTOP={"V": v + 3 * h})
        cross = ct.run(rundir, f"{name}_cross{factor}", "periodic", data=back("UZ")[-1],
                       ICP=["V", 11] + ct.MEASURES, DS=-2 * h, DSMIN=1e-4, DSMAX=2 * h,
                       IADS=0, NMX=4)
        if cross("TR"):
            return cross("TR")[0]
    raise autoglue.RunError(f"run {name}: AUTO labelled no TR near V = {v:.3f} "
                            f"(steps up to {4 * h:.3g} m/s across it)")


TORUS_ICP = ["V", "Fstar", 11, 12] + ct.MEASURES


def torus_curve(rundir, name, tr):
    """The TR point continued in (V, F*) both ways, within CURVE_FSTAR and
    V <= V_MAX.  AUTO's first ISW = 2 run from a TR label only builds the
    extended system's data (then EP); the curve is continued from there."""
    first = ct.run(rundir, f"{name}_start", "periodic", data=tr, ISW=2, ICP=TORUS_ICP,
                   DS=0.01, DSMAX=0.05, NMX=5)
    stop = {"Fstar": list(CURVE_FSTAR), "V": [0.5, V_MAX]}
    parts = []
    for sign, part in ((1, "up"), (-1, "down")):
        bd = ct.run(rundir, f"{name}_{part}", "periodic", data=first("EP")[-1], ISW=2,
                    ICP=TORUS_ICP, DS=sign * 0.05, DSMAX=2.0, NMX=CURVE_STEPS, UZSTOP=stop,
                    allow_mx=True, time_limit=900)
        parts.append({"V": list(map(float, bd[0]["V"])),
                      "Fstar": list(map(float, bd[0]["Fstar"])),
                      "freq": list(map(float, bd[0]["freq"])),
                      "ends": [p["TY name"] for p in bd() if p["TY name"] in ("EP", "MX", "UZ")]})
    return parts


def compute(case):
    values = CASES[case]
    rundir = paths.rundir(os.path.join("torus", case))
    entry = {"parameters": values, "meshes": [], "simulations": []}
    base = None
    for mesh in MESHES:
        name = f"po_{mesh[0]}_{mesh[1]}"
        try:
            bd = orbit_branch(rundir, name, values, mesh, DSMAX[case])
        except autoglue.RunError as exc:
            if base is None:            # the first mesh must succeed
                raise
            # a finer mesh that fails (Fig. 10's branch: MX at the fold S
            # with NCOL = 7) is reported, not a reason to drop the others
            entry["meshes"].append({"NTST": mesh[0], "NCOL": mesh[1], "error": exc.brief})
            print(f"torus: {case}: NTST = {mesh[0]}, NCOL = {mesh[1]}: failed: {exc.brief}",
                  flush=True)
            continue
        found = crossings(rundir, name)
        entry["meshes"].append({"NTST": mesh[0], "NCOL": mesh[1], "crossings": found})
        print(f"torus: {case}: NTST = {mesh[0]}, NCOL = {mesh[1]}: " + (", ".join(
            f"V = {c['value']:.3f} ({'loses' if c['direction'] > 0 else 'regains'} "
            f"stability, angle {c['angle']:.4f} rad)" for c in found) or "no torus crossing"),
            flush=True)
        if base is None:
            base = (name, bd, found)
    name, bd, found = base
    steps = floquet.read(os.path.join(rundir, f"d.{name}"))
    for c in found:
        v0 = c["value"]
        c["freq"] = on_branch(bd, v0, "freq")
        c["psi_amp"] = on_branch(bd, v0, "psi_amp")
        c["modulation_hz"] = c["angle"] / (2 * math.pi) * c["freq"]
    # one simulation either side of the first and the last crossing
    ends = sorted({found[0]["value"], found[-1]["value"]}) if found else []
    for v in sorted({w for v0 in ends for w in (v0 - SIDE, v0 + SIDE) if 0.5 < w <= V_MAX}):
        psi0 = min(on_branch(bd, v, "psi_amp"), PSI0_MAX)
        rate, first, last = simulated_rate(values, v, psi0)
        sim = {"V": v, "predicted_rate": predicted_rate(steps, bd, v),
               "simulated_rate": rate, "spread_first": first, "spread_last": last}
        entry["simulations"].append(sim)
        print(f"torus: {case}: V = {v:.2f}: modulation rate AUTO "
              f"{sim['predicted_rate']:+.4f} /s, simulation {rate:+.4f} /s", flush=True)
    entry["curves"] = []
    for k, c in enumerate(found):
        try:
            tr = tr_point(rundir, f"tr{k + 1}", bd, c["value"], c["slope_per_unit"])
            entry["curves"].append({"from_V": float(tr["V"]),
                                    "parts": torus_curve(rundir, f"tr{k + 1}", tr)})
        except autoglue.RunError as exc:
            entry["curves"].append({"from_V": c["value"], "error": exc.brief})
            print(f"torus: {case}: torus curve from V = {c['value']:.3f} failed: "
                  f"{exc.brief}", flush=True)
    return entry


def write_json(path, data):
    with tempfile.NamedTemporaryFile("w", dir=os.path.dirname(path), delete=False) as out:
        json.dump(data, out, indent=1)
    os.replace(out.name, path)


def main():
    cases = sys.argv[1:] or list(CASES)
    unknown = [c for c in cases if c not in CASES]
    if unknown:
        sys.exit(f"torus: unknown case(s) {', '.join(unknown)}; cases: {', '.join(CASES)}")
    for case in cases:
        try:
            entry = compute(case)
        except (autoglue.RunError, RuntimeError, ValueError) as exc:
            sys.exit(f"torus: {case}: {exc}")
        write_json(os.path.join(paths.RUN_ROOT, "torus", case, "result.json"), entry)
    found = {}
    for case in CASES:
        path = os.path.join(paths.RUN_ROOT, "torus", case, "result.json")
        if os.path.exists(path):
            with open(path) as f:
                found[case] = json.load(f)
    path = os.path.join(paths.RUN_ROOT, "torus", "result.json")
    write_json(path, found)
    print(f"torus: wrote {path} (cases {', '.join(found)})")


if __name__ == "__main__":
    main()
