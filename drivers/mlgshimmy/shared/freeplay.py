"""The torque-link stiffness profile of eq. (15), or of the gear's freeplay
law (shared.gear: FREEPLAY=), under the two ways of varying the freeplay
y_fp (section III), with no AUTO import: Fig. 15 draws from it alone, the
magnitude figures (shared.yfp_runs) run AUTO on it.

Scalings: "ratio" keeps eps = 0.1 y_fp (PAR eps_rel = 0.1, eps_abs = 0),
"fixed" keeps eps = 0.1 mm (eps_abs = 0.1, eps_rel = 0).
"""
from __future__ import annotations

from typing import Any, Dict, Mapping, Tuple

import numpy
from numpy.typing import ArrayLike

from mlgshimmy.shared import gear, mlgmodel, overlay

SCALINGS = {"ratio": {"eps_abs": 0.0, "eps_rel": 0.1},
            "fixed": {"eps_abs": 0.1, "eps_rel": 0.0}}
EPSILON = 0.1        # eps/y_fp ("ratio") or eps in mm ("fixed")


def width(scaling: str, model: Mapping[str, Any]) -> Tuple[Dict[str, float], Dict[str, Any]]:
    """(the scaling's {eps_abs, eps_rel} with `model`'s overrides of them,
    the rest of `model`): the criterion at another smoothing width."""
    eps = {k: model.get(k, v) for k, v in SCALINGS[scaling].items()}
    return eps, {k: v for k, v in model.items() if k not in eps}
# The freeplay of Figs. 10-12, the lift-off edge and the atlas (section IV.B):
# y_fp = 1 mm, eps = 0.1 mm.
NOMINAL = {"yfp": 1.0, "eps_abs": 0.0, "eps_rel": 0.1}
FIG13_FREEPLAYS = (0.2, 0.5, 1.0, 2.0)                 # y_fp [mm], "ratio"
FIG14_FREEPLAYS = (0.05, 0.098, 0.11, 0.15, 0.35, 1.0)  # y_fp [mm], "fixed"
# eps / y_fp of the smoothing error's table against eq. (14) (docs/model.md 9.3)
TABLE_RATIOS = (1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01)


def epsilon(case: Mapping[str, float]) -> float:
    """The smoothing width eps = eps_abs + eps_rel * y_fp [mm] of a freeplay case."""
    return case["eps_abs"] + case["eps_rel"] * case["yfp"]


def law_label() -> str:
    """The gear's freeplay law, as a legend or title names it."""
    law = gear.current().law()
    return "eq. (15)" if law == 0 else f"the {overlay.law_name(law)} law"


def force(y_m: ArrayLike, yfp_m: float, eps_m: float, k_tlk: float = 1.0) -> numpy.ndarray:
    """The gear's freeplay law: force [N] at the deflections y_m [m]
    (eq. (14) at eps_m = 0)."""
    law = gear.current().law()
    return numpy.array([mlgmodel.torque_link_force(law, k_tlk, v, yfp_m, eps_m) for v in y_m])


def profile(yfp: float, scaling: str, k_tlk: float, span: float = 3.0,
            n: int = 801) -> Tuple[numpy.ndarray, numpy.ndarray]:
    """The gear's law: (y_tlk [mm], M_kpsi/r_tlk [N]) over |y_tlk| <= span*y_fp."""
    eps = epsilon({**SCALINGS[scaling], "yfp": yfp})
    y = numpy.linspace(-span * yfp, span * yfp, n)
    return y, force(1e-3 * y, 1e-3 * yfp, 1e-3 * eps, k_tlk)
