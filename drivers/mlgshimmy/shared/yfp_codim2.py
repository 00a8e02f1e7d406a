"""The codimension-two points on the freeplay-magnitude figures' Hopf curves
in (y_fp, V) (yfp_stored.stored_curves), located by shared.codim2, and the
table's lines for them (Figs. 14 and 18), with what Fig. 14's diagrams in V
say of each GH point's l2 (fold_check)."""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence

import numpy

from mlgshimmy.shared import bautin, codim2, mlgmodel, naming, rolling
from mlgshimmy.shared.freeplay import width
from mlgshimmy.shared.yfp_runs import FSTAR, values

# a turn of the orbits from a Hopf point within this distance of it [m/s] is
# the fold of cycles the GH point's normal form speaks of (the one next to
# Fig. 14's GH point lies 1.2 m/s below its Hopf point, the diagrams' other
# folds tens of m/s away)
FOLD_NEAR = 5.0
# steps in V smaller than this [m/s] do not count as a direction (AUTO's first
# steps from a Hopf point may go 1e-8 m/s the other way)
STEP_NOISE = 1e-6
HOPF_TOL = 1e-3    # [m/s] a branch starting this near a Hopf point is born there


def first_turn(V: Sequence[float]) -> Optional[float]:
    """The speed where a branch of orbits first reverses its direction in V
    (a fold, whether AUTO labels it LP or not), or None."""
    V = numpy.asarray(V, dtype=float)
    steps = numpy.diff(V)
    moving = numpy.flatnonzero(numpy.abs(steps) > STEP_NOISE)
    if len(moving) == 0:
        return None
    back = moving[numpy.sign(steps[moving]) != numpy.sign(steps[moving[0]])]
    return float(V[back[0]]) if len(back) else None


def _rolling(scaling, Fstar, yfp, model):
    """Straight rolling continued from zero freeplay (rolling.state) at the
    Model's smoothing width, as values() sets it."""
    eps, rest = width(scaling, model)
    return rolling.state("figures", Fstar, yfp, eps, **rest)


def codim2_points(curves: Sequence[Mapping[str, Any]], scaling: str, other: str = "V",
                  fixed: Optional[Mapping[str, float]] = None,
                  **model: Any) -> List[Dict[str, Any]]:
    """The codimension-two points shared.codim2 locates on Hopf curves in
    (y_fp, `other`) ("V": Fig. 14's, at F* = FSTAR; "Fstar": Fig. 18's,
    `fixed` {"V": V_LIMIT}), given as {other: [...], "yfp": [...]},
    straight rolling continued from zero freeplay (rolling.state), each
    trial point moved back onto the curve in V (Fig. 14) or y_fp (Fig. 18):
    straight rolling does not depend on V, nor at the paper's gear on y_fp.
    [{"type", other, "yfp", "omega", "l1", and at GH "l2", "dl1_dyfp"}]; a
    curve it cannot follow is reported and left out."""
    fixed = {"Fstar": FSTAR} if fixed is None else fixed

    def at(x, yfp):
        there = {**fixed, other: x}
        Fstar = there.pop("Fstar")
        model_there = mlgmodel.Model("figures", **there, **values(scaling, yfp, Fstar, **model))
        return model_there, _rolling(scaling, Fstar, yfp, model)
    out = []
    for n, curve in enumerate(curves):
        try:
            found = codim2.along_hopf_curve(list(zip(curve[other], curve["yfp"])), at,
                                            along=0 if other == "V" else 1)
        except (RuntimeError, numpy.linalg.LinAlgError) as exc:
            print(f"REPORTED: codimension-two points on Hopf curve {n + 1} left out: {exc}")
            continue
        out += [{"type": p["type"], other: p["a"], "yfp": p["b"], "omega": p["omega"],
                 "l1": p["l1"] if numpy.isfinite(p["l1"]) else None,
                 **({"l2": p["l2"], "dl1_dyfp": p["dl1_db"]} if p["type"] == "GH" else {})}
                for p in found["points"]]
    return out


def fold_check(gh: Mapping[str, Any], diagrams: Sequence[Mapping[str, Any]], scaling: str,
               **model: Any) -> List[Dict[str, Any]]:
    """What Fig. 14's diagrams in V (yfp_stored.stored_diagram) say of a GH
    point's l2: near it the fold of limit cycles runs beside the Hopf curve
    on the side of y_fp where l1 l2 < 0 (bautin.fold_of_cycles).  For the
    diagram nearest the point on each side, its Hopf point nearest the GH
    point's speed: [{"yfp", "hopf", "l1" there, "fold": the first turn of
    the orbits from it (first_turn) within FOLD_NEAR of it, or None,
    "predicted": the normal form's fold speed, None where l1 l2 > 0}]."""
    out = []
    for side in (-1, 1):
        near = [d for d in diagrams if side * (d["yfp"] - gh["yfp"]) > 0 and d["hopf"]]
        if not near:
            continue
        d = min(near, key=lambda d: abs(d["yfp"] - gh["yfp"]))
        hopf = min((V for V, _ in d["hopf"]), key=lambda V: abs(V - gh["V"]))
        mode = naming.mode("figures", "V", hopf,
                           state=lambda V: _rolling(scaling, FSTAR, d["yfp"], model),
                           **values(scaling, d["yfp"], FSTAR, **model))
        distance, _ = bautin.fold_of_cycles(mode["l1"], gh["l2"], 2 * numpy.pi * mode["freq_hz"],
                                            mode["mu_slope"])
        turns = [first_turn(b["columns"]["V"]) for b in d["branches"]
                 if abs(b["columns"]["V"][0] - hopf) < HOPF_TOL]
        folds = [V for V in turns if V is not None and abs(V - hopf) < FOLD_NEAR]
        out.append({"yfp": d["yfp"], "hopf": hopf, "l1": mode["l1"],
                    "fold": min(folds, key=lambda V: abs(V - hopf)) if folds else None,
                    "predicted": None if numpy.isnan(distance) else hopf + distance})
    return out


def agrees(check: Sequence[Mapping[str, Any]]) -> bool:
    """Whether each diagram of fold_check has a fold where the normal form
    puts one, and none where it puts none."""
    return all((c["fold"] is None) == (c["predicted"] is None) for c in check)


def _fold_text(check):
    """fold_check's findings as the table writes them."""
    parts = [f"y_fp = {c['yfp']:g}: " + (f"S at {c['fold']:.5g} m/s" if c["fold"] is not None
                                         else "no fold")
             + (f" (normal form: {c['predicted']:.5g})" if c["predicted"] is not None
                else " (normal form: none)") for c in check]
    return "; ".join(parts) + (": agrees" if agrees(check) else ": DISAGREES")


def codim2_lines(points: Sequence[Mapping[str, Any]], other: str = "V",
                 checks: Optional[Sequence[Any]] = None) -> List[str]:
    """The table's lines of codim2_points; checks: fold_check's list per
    point (None: not checked)."""
    unit = " m/s" if other == "V" else ""
    checks = checks or [None] * len(points)
    return [f"{p['type']} on a Hopf curve at {other} = {p[other]:.6g}{unit}, "
            f"y_fp = {p['yfp']:.6g} mm ({p['omega'] / (2 * numpy.pi):.4g} Hz)"
            + (f": l2 = {p['l2']:+.4g}, dl1/dy_fp = {p['dl1_dyfp']:+.4g} /mm" if p["type"] == "GH"
               else "") + (f"; the fold of cycles by the diagrams, {_fold_text(c)}" if c else "")
            for p, c in zip(points, checks)] or ["codimension-two points on the Hopf curves: none"]
