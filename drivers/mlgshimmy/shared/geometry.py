"""The side-stay geometry every figure and study is made at: the angles rho,
mu of the side-stay axis (degrees on the command line, radians in the
model) and the level of the equations of motion eom_terms (docs/model.md
section 8).  No AUTO import and no library needed.

    make fig10 RHO=10 MU=10 [EOM=2]      # mk/geometry.mk sets the environment:
    MLG_RHO_DEG=10 MLG_MU_DEG=10 MLG_EOM=2 python3 -m mlgshimmy.figures.fig10

The geometry is read once per process from MLG_RHO_DEG, MLG_MU_DEG and
MLG_EOM (current()), checked with a message naming the make variable.  With
none of them set, or at rho = mu = 0 with eom_terms = 0, it is the paper's
gear, the baseline: parameters() is {} and nothing a driver does changes.
Otherwise parameters() = {rho, mu [rad], eom_terms}, which the drivers pass
wherever they build a model (continuation.Start, spectrum scans,
magnitude's scans, mlgmodel.Model) and simulator_params() to the simulator;
AUTO runs started from a solution carry them in PAR.  A missing angle is 0;
EOM defaults to 2 (the complete equations, the only level that conserves
energy at non-zero angles) when an angle is given, else to 0.

A geometry's runs, caches, tables and figures live in their own tree,
$MLG_BASE_RUN_ROOT/geometry/<tag>/ (tag e.g. rho10_mu10_eom2), which make
exports as MLG_RUN_ROOT (`python3 -m mlgshimmy.shared.geometry make BASE`
gives make the tag and the tree).  Figures say so in their title (stamp(),
from shared.draw.save) and tables in a line (describe()).

y_tlk(): the torque-link apex deflection at a state, y_tlk = r_tlk(eta)
(psi + beta sin p) (docs/model.md 8.1; c/freeplay.h).
"""
import functools
import json
import math
import os
import sys
from typing import Dict, Mapping, Optional

ENV_RHO, ENV_MU, ENV_EOM = "MLG_RHO_DEG", "MLG_MU_DEG", "MLG_EOM"
ENV_BASE = "MLG_BASE_RUN_ROOT"
MAKE_VARIABLE = {ENV_RHO: "RHO", ENV_MU: "MU", ENV_EOM: "EOM"}
EOM_LEVELS = (0, 1, 2)
EOM_WITH_ANGLES = 2
KEYS = ("rho", "mu", "eom_terms")       # the model parameters a geometry sets
TREE = "geometry"                       # $MLG_BASE_RUN_ROOT/geometry/<tag>/


class GeometryError(ValueError):
    """A geometry that is not one (the message names the make variable)."""


def _name(value: float) -> str:
    """An angle in a tag: distinct angles never share one (12 digits)."""
    return f"{value:.12g}"


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

    def key(self):
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
        return {"rho": math.radians(self.rho_deg), "mu": math.radians(self.mu_deg),
                "eom_terms": float(self.eom_terms)}

    def simulator_params(self) -> Dict[str, str]:
        """--param NAME=VALUE of the simulator (shared.simulator.run's params)."""
        return {name: repr(value) for name, value in self.parameters().items()}

    def describe(self) -> str:
        """One line for titles and tables ("" at the baseline)."""
        if self.baseline:
            return ""
        return (f"side stay rho = {self.rho_deg:g} deg, mu = {self.mu_deg:g} deg, "
                f"eom_terms = {self.eom_terms}")

    def suffix(self) -> str:
        """What a title gets appended ("" at the baseline)."""
        return f" [{self.describe()}]" if not self.baseline else ""


def _number(environ: Mapping[str, str], name: str) -> Optional[float]:
    text = environ.get(name, "").strip()
    if not text:
        return None
    try:
        value = float(text)
    except ValueError:
        raise GeometryError(f"{MAKE_VARIABLE[name]}={text!r} ({name}) is not a number "
                            "(degrees)") from None
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
    return Geometry(rho or 0.0, mu or 0.0, eom)


@functools.lru_cache(maxsize=1)
def current() -> Geometry:
    """The geometry of this process (read once)."""
    return from_environment()


def parameters() -> Dict[str, float]:
    """current().parameters(): {} at the baseline."""
    return current().parameters()


def simulator_params() -> Dict[str, str]:
    return current().simulator_params()


def suffix() -> str:
    return current().suffix()


def describe() -> str:
    return current().describe()


V_FROM = 0.5    # m/s, continuation.V_MIN


def start_speed() -> float:
    """Where a run along V from "V = 0" starts: 0 at rho = mu = 0 (as the
    paper's figures); V_FROM with side-stay angles, where straight rolling
    yaws the wheels and at V = 0 the tyre states are undetermined (AUTO
    stops, MX, at its first step)."""
    return 0.0 if current().symmetric else V_FROM


def tree(base: str, geometry: Geometry) -> str:
    """The run root of a geometry under base (base itself at the baseline,
    and when base already is that geometry's tree: a make started from one)."""
    base = os.path.abspath(base)
    if geometry.baseline:
        return base
    if os.path.basename(base) == geometry.tag and \
            os.path.basename(os.path.dirname(base)) == TREE:
        return base
    return os.path.join(base, TREE, geometry.tag)


def base_root() -> str:
    """The run root of the baseline: MLG_BASE_RUN_ROOT (make exports it with
    a geometry), else MLG_RUN_ROOT, else build/."""
    from mlgshimmy.shared import paths
    return os.path.abspath(os.environ.get(ENV_BASE) or paths.run_root())


def baseline_numbers(figure: str) -> Optional[dict]:
    """The "numbers" of the baseline's cached result of a figure, to print
    beside a geometry's (None at the baseline or if not computed)."""
    if current().baseline:
        return None
    try:
        with open(os.path.join(base_root(), figure, "result.json")) as f:
            data = json.load(f)["data"]
    except (OSError, ValueError, KeyError, TypeError):
        return None
    numbers = data.get("numbers") if isinstance(data, dict) else None
    return numbers if isinstance(numbers, dict) else None


def stamp(fig) -> None:
    """Name the geometry in a figure's title (shared.draw.save calls it):
    appended to its suptitle, or a suptitle of its own; nothing at the
    baseline."""
    if current().baseline:
        return
    title = getattr(fig, "_suptitle", None)
    if title is not None and title.get_text():
        title.set_text(title.get_text() + suffix())
    else:
        fig.suptitle(describe(), y=1.0, va="bottom", fontsize="medium")


def y_tlk(model, u) -> float:
    """The torque-link apex deflection [m] at the state u ({name: value}):
    r_tlk(eta) psi_s, psi_s = psi + beta sin p, the twist the links resist
    (eq. 15; c/freeplay.h), p the side-stay angle of mlg_diagnose."""
    from mlgshimmy.shared import domain
    d = domain.diagnose(model, u)
    return d["r_tlk"] * (u["psi"] + u["beta"] * math.sin(d["p"]))


def main(argv) -> None:
    """`make BASE`: "<tag> <tree> <rho> <mu> <eom>" of the environment's
    geometry, for mk/geometry.mk; a bad geometry exits 1 naming the
    variable."""
    if len(argv) != 2 or argv[0] != "make":
        sys.exit("usage: python3 -m mlgshimmy.shared.geometry make BASE_RUN_ROOT")
    try:
        g = from_environment()
    except GeometryError as exc:
        sys.exit(f"geometry: {exc}")
    print(g.tag if not g.baseline else "baseline", tree(argv[1], g),
          f"{g.rho_deg:.12g}", f"{g.mu_deg:.12g}", g.eom_terms)


if __name__ == "__main__":
    main(sys.argv[1:])
