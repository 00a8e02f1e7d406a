"""The cached forms of the freeplay-magnitude runs (yfp_runs): diagrams in V,
orbits in y_fp and curves in (y_fp, V) as plain data, the parts of a figure
made of diagrams, and the numbers they print."""
from __future__ import annotations

import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple

from mlgshimmy.shared import jobs, naming, paths
from mlgshimmy.shared.yfp_runs import V_ORBITS, curve_points, diagram_in_V, orbit_curve, orbits_in_yfp


def stored_orbits(orbits: Sequence[Tuple[float, Tuple[List[Any], List[Any]]]]
                  ) -> List[Tuple[float, Dict[str, Any]]]:
    """The orbits of orbits_in_yfp for the cache: [(V, {"yfp", "psi_amp",
    "freq", "stable"})], each joined by orbit_curve."""
    out = []
    for V, runs in orbits:
        ys, amp, stable = orbit_curve(runs, "psi_amp")
        out.append((V, {"yfp": ys, "psi_amp": amp, "freq": orbit_curve(runs, "freq")[1],
                        "stable": stable}))
    return out


def orbit_names(orbits: Sequence[Tuple[float, Any]]) -> List[str]:
    """What a table calls each stored orbit: "V = 50", and "V = 50, orbit 2"
    for a second stable orbit at the same speed (a changed gear's)."""
    names, seen = [], {}
    for V, _ in orbits:
        seen[V] = seen.get(V, 0) + 1
        names.append(f"V = {V:g}" + (f", orbit {seen[V]}" if seen[V] > 1 else ""))
    return names


COLUMNS = ("V", "psi_amp", "freq")


def stored_diagram(diagram: Any) -> Dict[str, Any]:
    """A Diagram in V for the cache: y_fp, scaling, Hopf points, folds
    (V, psi_amp) and their orbits' frequencies [Hz], the orbit branches
    (jobs.stored) and per orbit run its first and smallest V (a turn AUTO
    may not label LP)."""
    return {"yfp": diagram.yfp, "scaling": diagram.scaling, "hopf": diagram.hopf,
            "hopf_names": [p["name"] for p in diagram.named],
            "folds": [(V, amp) for _, _, V, amp in diagram.folds()],
            "fold_hz": [run(lab)["freq"] for run, lab, _, _ in diagram.folds()],
            "branches": [b for run in diagram.branches for b in jobs.stored(run, COLUMNS)],
            "turns": [(run[0]["V"][0], min(run[0]["V"])) for run in diagram.branches]}


def diagram_jobs(figure: str, scaling: str, freeplays: Sequence[float], prefix: str = "",
                 orbits_at: Optional[float] = None, uzr: Sequence[float] = V_ORBITS,
                 **model: Any) -> Dict[str, Callable[..., Any]]:
    """The parts of a figure made of diagrams in V (jobs.Parts): one per
    y_fp, named <prefix>y<y_fp>, computing the stored diagram (runs
    <prefix>y<y_fp>_hb<i>, _po<i>, in the part's own run directory
    $MLG_RUN_ROOT/<figure>/<part>/); the one at y_fp = orbits_at (named
    ..._orbits) also continues its stable orbits at V_ORBITS in y_fp."""
    def job(y, name):
        def run():
            rundir = paths.rundir(os.path.join(figure, name))
            d = diagram_in_V(rundir, f"{prefix}y{y:g}", scaling, y, uzr=uzr, figure=figure,
                             **model)
            out = {"diagram": stored_diagram(d)}
            if y == orbits_at:
                out["orbits"] = stored_orbits(orbits_in_yfp(rundir, d, figure, **model))
            return out
        return run
    names = {y: f"{prefix}y{y:g}" + ("_orbits" if y == orbits_at else "") for y in freeplays}
    return {names[y]: job(y, names[y]) for y in freeplays}


def diagrams_of(done: Sequence[Mapping[str, Any]],
                prefix: str = "") -> Tuple[List[Dict[str, Any]], Any]:
    """(stored diagrams in order, stored orbits or None) from the computed
    parts {name: data} of diagram_jobs(..., prefix)."""
    done = [data for name, data in done.items() if name.startswith(prefix + "y")]
    orbits = [p["orbits"] for p in done if "orbits" in p]
    return [p["diagram"] for p in done], (orbits[0] if orbits else None)


def diagram_numbers(diagrams: Sequence[Mapping[str, Any]], prefix: str = "") -> Dict[str, float]:
    """{quantity: value}: the Hopf and fold speeds of stored diagrams, as
    "<prefix>y_fp = <y>: <name> [m/s]" (the Hopf points named by their mode,
    the folds by their family: shared.naming)."""
    out = {}
    for d in diagrams:
        for name, (V, _) in zip(d["hopf_names"], d["hopf"]):
            out[f"{prefix}y_fp = {d['yfp']:g}: {name} [m/s]"] = V
        for name, V in named_folds(d):
            out[f"{prefix}y_fp = {d['yfp']:g}: {name} [m/s]"] = V
    return out


def named_folds(diagram: Mapping[str, Any]) -> List[Tuple[str, float]]:
    """[(name, V)] of a stored diagram's folds (naming.fold_names)."""
    return naming.fold_names([(V, hz) for (V, _), hz in zip(diagram["folds"],
                                                           diagram["fold_hz"])])


def stored_curves(curves: Sequence[Tuple[Any, Any]],
                  columns: Sequence[str] = ("yfp", "V")) -> List[Dict[str, Any]]:
    """Curves (pairs of runs) for the cache: [{column: polyline}]
    (curve_points); "freq" is 1/T along a curve with the period printed."""
    out = []
    for curve in curves:
        line = {c: curve_points(curve, "yfp", c)[1] for c in columns if c != "freq"}
        if "freq" in columns:
            line["freq"] = 1.0 / curve_points(curve, "yfp", "T")[1]
        out.append(line)
    return out
