"""The side-stay geometry a model is made at: the angles rho, mu of the
side-stay axis (degrees on the command line, radians in the model) and the
level of the equations of motion eom_terms (docs/model.md section 8).  No
AUTO import and no library needed.  The process's model, of which the
geometry is one part, is shared.gear's.

    make fig10 RHO=10 MU=10 [EOM=2]      # mk/gear.mk sets the environment:
    MLG_RHO_DEG=10 MLG_MU_DEG=10 MLG_EOM=2 python3 -m mlgshimmy.figures.fig10

Read from MLG_RHO_DEG, MLG_MU_DEG and MLG_EOM (from_environment), checked
with a message naming the make variable.  With none of them set, or at
rho = mu = 0 with eom_terms = 0, it is the paper's gear: parameters() is
{}.  Otherwise parameters() = {rho, mu [rad], eom_terms}.  A missing angle
is 0; EOM defaults to 2 (the complete equations, the only level that
conserves energy at non-zero angles) when an angle is given, else to 0.

y_tlk(): the torque-link apex deflection at a state, y_tlk = r_tlk(eta)
(psi + beta sin p) (docs/model.md 8.1; c/freeplay.h).
"""
from __future__ import annotations

import functools
import math
import os
import re
from typing import Any, Dict, Mapping, Optional, Tuple

from mlgshimmy.shared import number_text, overlay

ENV_RHO, ENV_MU, ENV_EOM = "MLG_RHO_DEG", "MLG_MU_DEG", "MLG_EOM"
MAKE_VARIABLE = {ENV_RHO: "RHO", ENV_MU: "MU", ENV_EOM: "EOM"}
EOM_LEVELS = (0, 1, 2)
# each level in a reader's words, for titles and tables
EOM_WORDS = {0: "the equations of motion as printed",
             1: "the printed equations with the side-stay corrections",
             2: "the complete equations of motion"}
EOM_WITH_ANGLES = 2


class GeometryError(ValueError):
    """A geometry that is not one (the message names the make variable)."""


# c/parameters.c's mlg_params_check: beyond |sin p| = 0.99 the geometry is
# degenerate (cos p ~ 0, I_beta -> 0).  Checked here too, in degrees, so that
# make refuses RHO/MU before any recipe runs (or directory is made).
SIN_P_MAX = 0.99


@functools.lru_cache(maxsize=1)
def _phi0() -> float:
    """The rake phi0 [rad] of c/mlg_parameters.h (both parameter sets)."""
    with open(overlay.HEADER) as f:
        return float(re.search(r"X\(\s*phi0\s*,\s*([^,]+),", f.read()).group(1))


def _sin_p(rho_deg: float, mu_deg: float) -> float:
    """sin p, p the side-stay angle (docs/model.md 4.13), at the rake phi0."""
    rho, mu, phi0 = math.radians(rho_deg), math.radians(mu_deg), _phi0()
    return math.sin(rho) * math.cos(phi0) - math.cos(rho) * math.sin(mu) * math.sin(phi0)


def _check_side_stay(g: "Geometry") -> None:
    """GeometryError in degrees, naming RHO and MU, where the library would
    refuse the angles (for make's RHO and MU: from_environment)."""
    sp = _sin_p(g.rho_deg, g.mu_deg)
    if abs(sp) > SIN_P_MAX:
        raise GeometryError(
            f"RHO={g.rho_deg:g} MU={g.mu_deg:g}: the side-stay angle p = "
            f"{math.degrees(math.asin(max(-1.0, min(1.0, sp)))):.4g} deg (docs/model.md "
            f"4.13) makes the gear geometry degenerate (cos p ~ 0); give angles with "
            f"|p| <= {math.degrees(math.asin(SIN_P_MAX)):.4g} deg")


def _name(value: float) -> str:
    """An angle in a tag: distinct angles never share one (12 digits)."""
    return f"{value:.12g}"


def model_angles(rho_deg: float, mu_deg: float, eom_terms: float) -> Dict[str, float]:
    """The model parameters of side-stay angles in degrees: rho and mu in
    radians, and the eom_terms level (the one place degrees become them)."""
    return {"rho": math.radians(rho_deg), "mu": math.radians(mu_deg), "eom_terms": eom_terms}


class Geometry:
    """Side-stay angles in degrees and the eom_terms level."""

    def __init__(self, rho_deg: float = 0.0, mu_deg: float = 0.0, eom_terms: int = 0):
        self.rho_deg = float(rho_deg) + 0.0     # -0 is 0
        self.mu_deg = float(mu_deg) + 0.0
        self.eom_terms = int(eom_terms)
        for name, value in (("RHO", self.rho_deg), ("MU", self.mu_deg)):
            if not (math.isfinite(value) and abs(value) < 90.0):
                raise GeometryError(f"{name}={value:g}: the side-stay angle must be finite and "
                                    "within (-90, 90) degrees")
        if self.eom_terms not in EOM_LEVELS:
            raise GeometryError(f"EOM={eom_terms} must be 0 (as printed), 1 (side-stay "
                                "corrections) or 2 (complete equations)")

    def __repr__(self) -> str:
        return f"Geometry({self.rho_deg:g}, {self.mu_deg:g}, {self.eom_terms})"

    def __eq__(self, other) -> bool:
        return isinstance(other, Geometry) and self.key() == other.key()

    def __hash__(self) -> int:
        return hash(self.key())

    def key(self) -> Tuple[float, float, int]:
        return (self.rho_deg, self.mu_deg, self.eom_terms)

    @property
    def baseline(self) -> bool:
        """The paper's gear with the printed equations."""
        return self.key() == (0.0, 0.0, 0)

    @property
    def symmetric(self) -> bool:
        """rho = mu = 0: straight rolling at psi = delta = 0 (any level)."""
        return self.rho_deg == 0.0 and self.mu_deg == 0.0

    @property
    def tag(self) -> str:
        return f"rho{_name(self.rho_deg)}_mu{_name(self.mu_deg)}_eom{self.eom_terms}"

    def mirror(self) -> "Geometry":
        """The mirror gear (-rho, -mu): f(Su; -rho, -mu) = S f(u; rho, mu)."""
        return Geometry(-self.rho_deg, -self.mu_deg, self.eom_terms)

    def parameters(self) -> Dict[str, float]:
        """The model parameters of this geometry, {} at the baseline (so that
        every baseline run is made exactly as before)."""
        if self.baseline:
            return {}
        return model_angles(self.rho_deg, self.mu_deg, float(self.eom_terms))

    def simulator_params(self) -> Dict[str, str]:
        """--param NAME=VALUE of the simulator (shared.simulator.run's params)."""
        return {name: repr(value) for name, value in self.parameters().items()}

    def describe(self) -> str:
        """One line for titles and tables ("" at the baseline)."""
        if self.baseline:
            return ""
        return (f"side stay rho = {self.rho_deg:g} deg, mu = {self.mu_deg:g} deg, "
                f"{EOM_WORDS[self.eom_terms]}")

    def suffix(self) -> str:
        """What a title gets appended ("" at the baseline)."""
        return f" [{self.describe()}]" if not self.baseline else ""


def _number(environ: Mapping[str, str], name: str) -> Optional[float]:
    text = environ.get(name, "").strip()
    if not text:
        return None
    value = number_text.parse(text)
    if value is None:
        raise GeometryError(f"{MAKE_VARIABLE[name]}={text!r} ({name}) is not a number "
                            f"in degrees: give {number_text.SYNTAX}")
    return value


def from_environment(environ: Mapping[str, str] = os.environ) -> Geometry:
    """The geometry MLG_RHO_DEG, MLG_MU_DEG, MLG_EOM name (unset or empty:
    the baseline); GeometryError naming the make variable."""
    rho, mu = _number(environ, ENV_RHO), _number(environ, ENV_MU)
    eom_text = environ.get(ENV_EOM, "").strip()
    if eom_text:
        if eom_text not in ("0", "1", "2"):
            raise GeometryError(f"EOM={eom_text} must be 0 (as printed), 1 (side-stay "
                                f"corrections) or 2 (complete equations) ({ENV_EOM})")
        eom = int(eom_text)
    else:
        eom = EOM_WITH_ANGLES if (rho is not None or mu is not None) else 0
    g = Geometry(rho or 0.0, mu or 0.0, eom)
    _check_side_stay(g)
    return g


V_FROM = 0.5    # m/s, continuation.V_MIN: where runs along V start with side-stay angles


def y_tlk(model: Any, u: Mapping[str, float]) -> float:
    """The torque-link apex deflection [m] at the state u ({name: value}):
    r_tlk(eta) psi_s, psi_s = psi + beta sin p, the twist the links resist
    (eq. 15; c/freeplay.h), p the side-stay angle of mlg_diagnose."""
    from mlgshimmy.shared import domain
    d = domain.diagnose(model, u)
    return d["r_tlk"] * (u["psi"] + u["beta"] * math.sin(d["p"]))
