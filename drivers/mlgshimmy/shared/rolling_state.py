"""Straight rolling at a load and a freeplay, for the eigenvalue scans of
kappa* and the stage switch: solved once per load at rho = mu = 0, the
branch continued from zero freeplay (shared.rolling) at side-stay angles."""
import functools
from typing import Any, Dict, Tuple

from mlgshimmy.shared import mlgmodel, rolling
from mlgshimmy.shared.freeplay import width


@functools.lru_cache(maxsize=1024)
def straight_rolling(parameter_set: str, Fstar: float,
                     overrides: Tuple[Tuple[str, Any], ...]) -> Dict[str, float]:
    """The straight-rolling state at load F* with the parameter overrides
    ((name, value) pairs).  It is the same for every V > 0 (docs/model.md
    4.20), and at rho = mu = 0 for every freeplay (the torque links carry
    no load at psi = 0), so the scans solve it once per load there
    (rolling_state)."""
    return mlgmodel.Model(parameter_set, Fstar=Fstar, **dict(overrides)).equilibrium()


def rolling_state(Fstar: float, yfp: float, scaling: str = "fixed",
                  parameter_set: str = "figures", **model: Any) -> Dict[str, float]:
    """straight_rolling at this freeplay.  At rho = mu = 0 it is solved once
    per load.  With side-stay angles (rho or mu in `model` non-zero)
    straight rolling twists the links (docs/model.md 8.7): its state depends
    on the freeplay, and at light load several equilibria coexist, so it is
    the one continued from zero freeplay (shared.rolling; NoRollingState
    beyond a fold in y_fp)."""
    if model.get("rho", 0.0) or model.get("mu", 0.0):
        eps, rest = width(scaling, model)
        return rolling.state(parameter_set, Fstar, yfp, eps, **rest)
    return straight_rolling(parameter_set, Fstar, tuple(sorted(model.items())))
