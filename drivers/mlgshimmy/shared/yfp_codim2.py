"""The codimension-two points on the freeplay-magnitude figures' Hopf curves
in (y_fp, V) (yfp_stored.stored_curves), located by shared.codim2, and the
table's lines for them (Figs. 14 and 18)."""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence

import numpy

from mlgshimmy.shared import codim2, mlgmodel, rolling
from mlgshimmy.shared.freeplay import width
from mlgshimmy.shared.yfp_runs import FSTAR, values


def codim2_points(curves: Sequence[Mapping[str, Any]], scaling: str, other: str = "V",
                  fixed: Optional[Mapping[str, float]] = None,
                  **model: Any) -> List[Dict[str, Any]]:
    """The codimension-two points shared.codim2 locates on Hopf curves in
    (y_fp, `other`) ("V": Fig. 14's, at F* = FSTAR; "Fstar": Fig. 18's,
    `fixed` {"V": V_LIMIT}), given as {other: [...], "yfp": [...]},
    straight rolling continued from zero freeplay (rolling.state), each
    trial point moved back onto the curve in V (Fig. 14) or y_fp (Fig. 18):
    straight rolling does not depend on V, nor at the paper's gear on y_fp.
    [{"type", other, "yfp", "omega", "l1", and at GH "dl1_dyfp"}]; a curve
    it cannot follow is reported and left out."""
    fixed = {"Fstar": FSTAR} if fixed is None else fixed

    def at(x, yfp):
        there = {**fixed, other: x}
        Fstar = there.pop("Fstar")
        model_there = mlgmodel.Model("figures", **there, **values(scaling, yfp, Fstar, **model))
        eps, rest = width(scaling, model)   # the Model's smoothing width, as values() sets it
        return model_there, rolling.state("figures", Fstar, yfp, eps, **rest)
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
                 **({"dl1_dyfp": p["dl1_db"]} if "dl1_db" in p else {})}
                for p in found["points"]]
    return out


def codim2_lines(points: Sequence[Mapping[str, Any]], other: str = "V") -> List[str]:
    """The table's lines of codim2_points."""
    unit = " m/s" if other == "V" else ""
    return [f"{p['type']} on a Hopf curve at {other} = {p[other]:.6g}{unit}, "
            f"y_fp = {p['yfp']:.6g} mm ({p['omega'] / (2 * numpy.pi):.4g} Hz)"
            + (f": l2 not computed; dl1/dy_fp = {p['dl1_dyfp']:+.4g} /mm" if p["type"] == "GH"
               else "") for p in points] or ["codimension-two points on the Hopf curves: none"]
