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
  3. each window of instability (a crossing out, then back in) at its
     middle: |mu| - 1 on the base and a fine mesh (FINE_MESH), from AUTO's
     Floquet multipliers and from the monodromy matrix integrated along the
     orbit (multiplier_check), and a long simulation at a tight tolerance
     (WINDOW_SIM_T, WINDOW_RTOL);
  4. the torus curve in (V, F*), AUTO ISW = 2 from each TR point, labelled
     by steps that cross the unit circle in one go (floquet.py says why),
     its start seeded with the critical Floquet eigenfunction (seeded).
Fig. 11 continues its own torus curves with the same recipes (mlgshimmy.shared.torus).
`python3 -m mlgshimmy.studies.torus_check [case ...]` (default: every case)
writes each case's result to
$MLG_RUN_ROOT/torus/<case>/result.json and all cases found there to
$MLG_RUN_ROOT/torus/result.json (the curves as arrays).
`make torus`.
"""
from __future__ import annotations

import json
import math
import os
import sys
from typing import Any, Dict

from mlgshimmy.shared import runerror
from mlgshimmy.shared import floquet
from mlgshimmy.shared import gear
from mlgshimmy.shared import paths
from mlgshimmy.shared.jobs.atomic import write_json
from mlgshimmy.shared.torus import (V_MAX, curve_arrays, multiplier_check, on_branch,
                                    orbit_branch, predicted_rate, simulated_rate,
                                    torus_crossings, torus_curve, tr_point, windows)

# What make, make help, make submit and the report know of this study
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "torus": {
        "help": "torus points of Figs. 7 and 10: meshes, windows, curves",
        "time": "> 7 min",
    },
}

CASES = {"fig07_F0.2": {"Fstar": 0.2, "yfp": 0.0},
         "fig07_F1": {"Fstar": 1.0, "yfp": 0.0},
         "fig10_F1": {"Fstar": 1.0, "yfp": 1.0, "eps_rel": 0.1}}
# largest step in V: the freeplay branch folds sharply at S (as fig10.py)
DSMAX = {"fig07_F0.2": 5.0, "fig07_F1": 5.0, "fig10_F1": 1.0}
MESHES = ((80, 4), (160, 4), (80, 7))
PSI0_MAX = 0.1         # rad: a larger displacement at rest lifts a wheel off at
                       # F* = 1, V = 560 (the orbit's own amplitude is 0.265)
SIDE = 25.0            # m/s either side of the TR speed for the simulations
FINE_MESH = (320, 7)   # the window check's mesh
WINDOW_SIM_T = (150.0, 300.0)  # s: a window's pair grows by ~0.01 /s, seen only after
                               # the other modes (~ -0.04 /s) have died out
WINDOW_RTOL = 1e-10    # CVODE rtol of the window simulations (atol 1e-2 of it):
                       # at the default 1e-8 the BDF damping is of the growth's size


def compute(case: str) -> Dict[str, Any]:
    values = {**CASES[case], **gear.parameters()}
    rundir = paths.rundir(os.path.join("torus", case))
    entry = {"parameters": values, "meshes": [], "simulations": []}
    base = None
    for mesh in MESHES:
        name = f"po_{mesh[0]}_{mesh[1]}"
        try:
            bd = orbit_branch(rundir, name, values, mesh, DSMAX[case])
        except runerror.RunError as exc:
            if base is None:            # the first mesh must succeed
                raise
            # a finer mesh that fails (Fig. 10's branch: MX at the fold S
            # with NCOL = 7) is reported, not a reason to drop the others
            entry["meshes"].append({"NTST": mesh[0], "NCOL": mesh[1], "error": exc.brief})
            print(f"torus: {case}: NTST = {mesh[0]}, NCOL = {mesh[1]}: failed: {exc.brief}",
                  flush=True)
            continue
        found = torus_crossings(rundir, name)
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
    labels = {}

    def label(k):
        if k not in labels:
            labels[k] = tr_point(rundir, f"tr{k + 1}", bd, found[k]["value"],
                                 found[k]["slope_per_unit"])
        return labels[k]
    # each window of instability: its middle on the base and the fine mesh,
    # and a long simulation there at a tight tolerance
    entry["windows"] = []
    for a, b in windows(found):
        v = 0.5 * (a["value"] + b["value"])
        window = {"from": a["value"], "to": b["value"], "V": v, "checks": []}
        try:
            for mesh in (MESHES[0], FINE_MESH):
                window["checks"].append(multiplier_check(
                    rundir, f"window{found.index(a) + 1}_{mesh[0]}_{mesh[1]}",
                    label(found.index(a)), v, mesh))
        except runerror.RunError as exc:
            window["error"] = exc.brief
        g = window["checks"][-1]["auto"] if window["checks"] else None
        rate, first, last = simulated_rate(values, v, min(on_branch(bd, v, "psi_amp"), PSI0_MAX),
                                           WINDOW_SIM_T, WINDOW_RTOL)
        window["simulation"] = {"predicted_rate": math.log1p(g) * on_branch(bd, v, "freq")
                                if g is not None else None, "simulated_rate": rate,
                                "spread_first": first, "spread_last": last}
        entry["windows"].append(window)
        print(f"torus: {case}: window {a['value']:.2f}-{b['value']:.2f}: |mu| - 1 at "
              f"{v:.2f}: " + ", ".join(f"({c['NTST']}, {c['NCOL']}) AUTO {c['auto']:+.3e}, "
                                       f"monodromy {c['monodromy']:+.3e}"
                                       for c in window["checks"])
              + f"; simulation {rate:+.4f} /s", flush=True)
    entry["curves"] = []
    for k, c in enumerate(found):
        try:
            tr = label(k)
            entry["curves"].append({"from_V": float(tr["V"]),
                                    "parts": curve_arrays(torus_curve(rundir, f"tr{k + 1}", tr))})
        except runerror.RunError as exc:
            entry["curves"].append({"from_V": c["value"], "error": exc.brief})
            print(f"torus: {case}: torus curve from V = {c['value']:.3f} failed: "
                  f"{exc.brief}", flush=True)
    return entry


def main() -> None:
    cases = sys.argv[1:] or list(CASES)
    unknown = [c for c in cases if c not in CASES]
    if unknown:
        sys.exit(f"torus: unknown case(s) {', '.join(unknown)}; cases: {', '.join(CASES)}")
    for case in cases:
        try:
            entry = compute(case)
        except (runerror.RunError, RuntimeError, ValueError) as exc:
            sys.exit(f"torus: {case}: {exc}")
        write_json(os.path.join(paths.run_root(), "torus", case, "result.json"), entry, indent=1)
    found = {}
    for case in CASES:
        path = os.path.join(paths.run_root(), "torus", case, "result.json")
        if os.path.exists(path):
            with open(path) as f:
                found[case] = json.load(f)
    path = os.path.join(paths.run_root(), "torus", "result.json")
    write_json(path, found, indent=1)
    print(f"torus: wrote {path} (cases {', '.join(found)})")


if __name__ == "__main__":
    main()
