"""Fig. 11's codimension-two points: those shared.codim2 locates on every
drawn Hopf curve of straight rolling (GH, BT, ZH, HH; the zero-freeplay
curve too), each once, and the fold curves' ends they explain."""
from __future__ import annotations

from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

from mlgshimmy.figures.fig11.ends import BACK, in_plane, inside, nearest_point, on_hopf_locus
from mlgshimmy.figures.fig11.orbits import ROLLING
from mlgshimmy.figures.fig11.plane import F_MAX, GEOMETRY, MODEL, V_MAX, distance as plane_distance
from mlgshimmy.shared import codim2
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import jobs
from mlgshimmy.shared import mlgmodel

# Two located points of one type this close (in V/V_MAX, F*/F_MAX) are one:
# a curve's two directions share their start, and a slice's Hopf curve may
# retrace part of another (codim2 locates to 1e-8 of a curve's extent)
SAME = 1e-5
ZERO_FREEPLAY = {**GEOMETRY, "yfp": 0.0}
# |Re a2| below this is rounding: the modes of the paper's gear leave eta'
# alone (a2 ~ 1e-17 at H1-H3, naming.KINK_NOISE)
A2_NOISE = 1e-12


def model_at(values: Mapping[str, float], rolling: Optional[Callable[[float], Any]]
             ) -> Callable[[float, float], Tuple[Any, Any]]:
    """at(V, F*) -> (model, straight rolling) for codim2: the state the
    figure's solvers start from (orbits.ROLLING, continued from zero
    freeplay) where there is one, else the library's Newton solve."""
    def at(V, Fstar):
        model = mlgmodel.Model("figures", V=V, Fstar=Fstar, **values)
        return model, (rolling(Fstar) if rolling else model.equilibrium())
    return at


def _plain(point, curve, at):
    """A located point as the cache stores it (no NaN: None), a GH point
    with the oleo kink's a2 there (codim2.kink)."""
    out = {"type": point["type"], "V": point["a"], "Fstar": point["b"], "curve": curve}
    if point["type"] == "GH":
        point = dict(point)
        point["a2"], _ = codim2.kink(*at(point["a"], point["b"]))
    for key in ("omega", "l1", "l2", "dl1_db", "a2"):
        if key in point:
            out[key] = None if not numpy.isfinite(point[key]) else float(point[key])
    return out


def points(drawn: Mapping[str, Any]) -> List[Dict[str, Any]]:
    """[{"type", "V", "Fstar", "curve", "omega", "l1", and at GH "l2",
    "dl1_db", "a2"}] on the drawn Hopf curves ({"hopf": [...], "zero":
    [...]}, stored diagrams), in V, those inside the plane (ends.in_plane: a
    curve started on its lower edge may run below it); a branch codim2
    cannot follow is reported and left out."""
    found = []
    for kind, at in (("hopf", model_at(MODEL, ROLLING)), ("zero", model_at(ZERO_FREEPLAY, None))):
        for n, diagram in enumerate(drawn.get(kind, [])):
            for branch in jobs.loaded(diagram):
                curve = f"{kind}{n + 1}"
                result = ct.reported(f"fig11 codimension-two points on {curve}", lambda: (
                    codim2.along_hopf_curve(list(zip(branch["V"], branch["Fstar"])), at)),
                    errors=(RuntimeError, numpy.linalg.LinAlgError))
                found += [_plain(p, curve, at) for p in (result or {"points": []})["points"]]
    return once([p for p in found if in_plane(p)])


def once(found: Sequence[Dict[str, Any]]) -> List[Dict[str, Any]]:
    """The points in V, each once: one of a type within SAME of another is
    left out."""
    kept = []
    for p in sorted(found, key=lambda p: (p["V"], p["Fstar"])):
        if not any(q["type"] == p["type"] and distance(p, q) < SAME for q in kept):
            kept.append(p)
    return kept


def distance(p: Mapping[str, float], q: Mapping[str, float]) -> float:
    """Distance of two (V, F*) points in V/V_MAX, F*/F_MAX."""
    return float(numpy.hypot((p["V"] - q["V"]) / V_MAX, (p["Fstar"] - q["Fstar"]) / F_MAX))


def at_gh(located: Sequence[Mapping[str, Any]], tol: float) -> Callable[[Mapping[str, Any]], bool]:
    """A predicate for ends.explained: whether a curve's end lies within
    `tol` of a located GH point."""
    return lambda stop: any(p["type"] == "GH" and distance(p, stop) < tol for p in located)


def past_gh(folds: Sequence[Any], located: Sequence[Mapping[str, Any]], tol: float,
            switch: Optional[Tuple[float, float]]) -> List[Any]:
    """The fold curves (stored diagrams), each branch that stops (MX) on the
    Hopf locus (ends.on_hopf_locus), outside the stage-switch window
    `switch` and not within `tol` of a located GH point, while an earlier
    point of it is, cut there: past the GH point the
    run follows the Hopf curve itself, its orbits shrunk to nothing (rho =
    5, mu = -15 deg: psi amplitude 4e-5 rad near the GH point, 4e-7 rad
    along 8 m/s of the Hopf curve after it), until it stops.  Its MX label
    moves to the cut, where ends.explained finds the GH point."""
    gh = [p for p in located if p["type"] == "GH"]
    out = []
    for n, diagram in enumerate(folds):
        kept = []
        for record in diagram:
            columns = record["columns"]
            mx = [(i, lab) for i, lab, kind in record["labels"] if kind == "MX"]
            end = mx and {"V": float(columns["V"][mx[-1][0]]),
                          "Fstar": float(columns["Fstar"][mx[-1][0]])}
            d, cut = min((nearest_point(p, columns) for p in gh), default=(numpy.inf, 0))
            if not end or d >= tol or inside(switch, end["Fstar"]) or at_gh(gh, tol)(end) \
                    or not on_hopf_locus(end):
                kept.append(record)
                continue
            print(f"fig11 fold{n + 1} runs on along the Hopf locus past the GH point at "
                  f"V = {columns['V'][cut]:.5g}, F* = {columns['Fstar'][cut]:.5g} to "
                  f"V = {end['V']:.5g}, F* = {end['Fstar']:.5g}: cut at the GH point")
            kept.append(cut_at(record, cut, mx[-1][1]))
        out.append(kept)
    return out


def cut_at(record: Mapping[str, Any], cut: int, label: int) -> Dict[str, Any]:
    """A stored branch up to its point `cut`, which becomes an MX end with
    AUTO label `label` (past_gh, retraced_past_gh)."""
    return {"columns": {c: v[:cut + 1] for c, v in record["columns"].items()},
            "stable": record["stable"][:cut + 1],
            "labels": [x for x in record["labels"] if x[0] < cut] + [[cut, label, "MX"]]}


def retraced_past_gh(folds: Sequence[Any], located: Sequence[Mapping[str, Any]],
                     tol: float) -> List[Any]:
    """The fold curves (stored diagrams), each branch that passes within
    `tol` of a located GH point after its start and from there on only
    retraces fold curves drawn already (every later point within `tol` of
    its own path up to the GH point or of another branch of `folds`), cut
    at the GH point, which becomes its MX end (ends.explained then names
    it).  At the GH point the orbits shrink to nothing; AUTO goes through
    and back along the same curve, the orbits half a period shifted (rho =
    20, mu = 5 deg: the fold curve from S2 down to the GH point at
    (135.66 m/s, F* = 0.7785) and back through its start to V = 0.5 m/s,
    where the other direction ends too): drawn twice over, a dashed curve
    looks solid."""
    gh = [p for p in located if p["type"] == "GH"]
    everything = [record["columns"] for diagram in folds for record in diagram]
    out = []
    for n, diagram in enumerate(folds):
        kept = []
        for record in diagram:
            columns = record["columns"]
            cut = next((i for i in range(1, len(columns["V"]))
                        if any(distance(p, {"V": columns["V"][i], "Fstar": columns["Fstar"][i]})
                               < tol for p in gh)), None)
            others = [c for c in everything if c is not columns]
            if cut is None or cut == len(columns["V"]) - 1 or not all(
                    min(plane_distance(point, c) for c in others
                        + [{k: v[:cut + 1] for k, v in columns.items()}]) < tol
                    for point in ({"V": columns["V"][i], "Fstar": columns["Fstar"][i]}
                                  for i in range(cut + 1, len(columns["V"])))):
                kept.append(record)
                continue
            print(f"fig11 fold{n + 1} passes the GH point at V = {columns['V'][cut]:.5g}, "
                  f"F* = {columns['Fstar'][cut]:.5g} and retraces drawn fold curves after it: "
                  "cut at the GH point")
            kept.append(cut_at(record, cut, max((x[1] for x in record["labels"]), default=0)))
        out.append(kept)
    return out


def l2_signs(located: Sequence[Dict[str, Any]], folds: Sequence[Any],
             ends: Sequence[Mapping[str, Any]]) -> None:
    """Each located GH point where a fold curve of orbits ends (`ends`:
    ends.explained's "generalised_hopf"; `folds`: the drawn fold curves,
    stored diagrams) gets "l2_sign" and "l2_from" (the curve), the check of
    its l2: near a GH point the fold curve leaves along the Hopf curve on
    the side where l1 l2 < 0 (Kuznetsov, section 8.3), so sign l2 =
    -sign(dl1/dF* dF*), dF* from the GH point to the fold curve BACK steps
    before its end."""
    for stop in ends:
        gh = min((p for p in located if p["type"] == "GH"), key=lambda p: distance(p, stop))
        n = int(stop["curve"][len("fold"):]) - 1
        for branch in jobs.loaded(folds[n]):
            V, F = numpy.asarray(branch["V"]), numpy.asarray(branch["Fstar"])
            at = numpy.flatnonzero((V == stop["V"]) & (F == stop["Fstar"]))
            if len(at) and at[0] >= BACK:
                side = F[at[0] - BACK] - gh["Fstar"]
                gh["l2_sign"] = -int(numpy.sign(gh["dl1_db"] * side))
                gh["l2_from"] = stop["curve"]


def coefficient(p: Mapping[str, Any]) -> str:
    """The point's coefficient as the table writes it: at GH l2 (shared.bautin),
    the side dl1/dF* makes subcritical, whether the side a fold curve
    leaves on agrees with l2's sign (l2_signs), and the oleo kink's a2
    where it is more than rounding (A2_NOISE; at l1 = 0 a nonzero a2 is
    the leading term: the point is then the one-sided expansion's GH)."""
    if p["type"] == "GH":
        side = "F* above" if (p["dl1_db"] or 0.0) > 0 else "F* below"
        text = f"l2 = {p['l2']:+.3g}; dl1/dF* = {p['dl1_db']:+.3g} (subcritical for {side})"
        if "l2_sign" in p:
            verdict = "agrees" if p["l2_sign"] == numpy.sign(p["l2"]) else "DISAGREES"
            text += (f"; the side {p['l2_from']} leaves on says l2 "
                     f"{'< 0' if p['l2_sign'] < 0 else '> 0'}: {verdict}")
        if abs(p["a2"] or 0.0) > A2_NOISE:
            text += f"; the oleo's kink: Re a2 = {p['a2']:+.3g}"
        return text
    if p["type"] in ("ZH", "HH"):
        return "l1 = " + ("none" if p["l1"] is None else f"{p['l1']:+.4g}")
    return "omega -> 0"


def lines(located: Sequence[Mapping[str, Any]],
          switch: Optional[Tuple[float, float]]) -> List[str]:
    """The table's lines, one per located point; those inside the stage
    switch's window `switch` (ends.inside) say so: l1 swings there with
    the switch's stiffness, smoothed over 1e-5 m."""
    return [f"{p['type']} on {p['curve']} at V = {p['V']:.6g} m/s, F* = {p['Fstar']:.6g}, "
            f"{p['omega'] / (2 * numpy.pi):.4g} Hz"
            f"{' (inside the oleo stage switch)' if inside(switch, p['Fstar']) else ''}: "
            f"{coefficient(p)}" for p in located] or ["codimension-two points on the Hopf "
                                                      "curves (codim2): none"]
