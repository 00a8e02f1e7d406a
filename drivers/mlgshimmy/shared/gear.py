"""The gear every figure and study of a process is made for: the paper's
gear, changed by a side-stay geometry (shared.geometry: RHO, MU, EOM) and
by an overlay of any other constant or parameter, the freeplay law among
them (shared.overlay: SET, FREEPLAY).

    make fig10 RHO=10 MU=10 SET='k_tlk=3.51e7'      # mk/gear.mk sets
    MLG_RHO_DEG=10 MLG_MU_DEG=10 MLG_SET='k_tlk=3.51e7' python3 -m mlgshimmy.figures.fig10

Read once per process (current()).  With nothing given it is the paper's
gear, the baseline: parameters() is {} and every run is made as before.
Otherwise parameters() holds the geometry's {rho, mu [rad], eom_terms} and
the overlay, which the drivers pass wherever they build a model
(continuation.Start, spectrum scans, mlgmodel.Model) and simulator_params()
to the simulator; AUTO runs started from a solution carry them in PAR and
the run's constants file (mlgmodel.register_constants).

Each gear has its own tree under the base run root: a geometry alone in
geometry/<tag>/ (e.g. geometry/rho10_mu10_eom2), with an overlay in
gear/<tag>/ (e.g. gear/k_tlk_35100000, gear/rho10_mu10_eom2+k_tlk_35100000).
Every cached result records record() and is refused on read when it was
made for another gear (shared.jobs.cache).  Figures say so in their
title (stamp()) and tables in a line (describe()).
"""
from __future__ import annotations

import functools
import json
import os
import sys
from typing import Any, Dict, Mapping, Optional, Sequence, Tuple

from mlgshimmy.shared import geometry, overlay

GEOMETRY_TREE, OVERLAY_TREE = "geometry", "gear"
ENV_BASE = "MLG_BASE_RUN_ROOT"


class Gear:
    """A geometry (shared.geometry.Geometry) and an overlay ((name, value) pairs)."""

    def __init__(self, gear: Optional[geometry.Geometry] = None,
                 changes: Tuple[Tuple[str, float], ...] = ()):
        self.geometry = gear or geometry.Geometry()
        self.overlay = tuple(sorted(changes))

    def __repr__(self) -> str:
        return f"Gear({self.geometry!r}, {self.overlay!r})"

    def __eq__(self, other) -> bool:
        return isinstance(other, Gear) and self.key() == other.key()

    def __hash__(self) -> int:
        return hash(self.key())

    def key(self) -> Tuple[Tuple[float, float, int], Tuple[Tuple[str, float], ...]]:
        return (self.geometry.key(), self.overlay)

    @property
    def baseline(self) -> bool:
        """The paper's gear: no angle, the printed equations, nothing overlaid."""
        return self.geometry.baseline and not self.overlay

    @property
    def symmetric(self) -> bool:
        """rho = mu = 0: straight rolling at psi = delta = 0."""
        return self.geometry.symmetric

    @property
    def tag(self) -> str:
        """The name of its tree: the geometry's tag, then each overlaid
        name_value, joined by '+' ('baseline' for the paper's gear)."""
        if self.baseline:
            return "baseline"
        words = [] if self.geometry.baseline else [self.geometry.tag]
        words += [overlay.tag_word(name, value) for name, value in self.overlay]
        return "+".join(words)

    def parameters(self) -> Dict[str, float]:
        """The model parameters it sets ({} at the baseline)."""
        return {**self.geometry.parameters(), **dict(self.overlay)}

    def law(self) -> int:
        """The freeplay law's index (c/freeplay_laws.h; 0: eq. 15)."""
        return int(dict(self.overlay).get(overlay.LAW, 0))

    def simulator_params(self) -> Dict[str, str]:
        """--param NAME=VALUE of the simulator (shared.simulator.run's params)."""
        return {name: repr(value) for name, value in self.parameters().items()}

    def describe(self) -> str:
        """One line for titles and tables ('' at the baseline)."""
        return "; ".join(part for part in (self.geometry.describe(),
                                           overlay.describe(self.overlay)) if part)

    def suffix(self) -> str:
        """What a title gets appended ('' at the baseline)."""
        return f" [{self.describe()}]" if not self.baseline else ""

    def record(self) -> dict:
        """The gear as a result's provenance stores it."""
        g = self.geometry
        return {"rho_deg": g.rho_deg, "mu_deg": g.mu_deg, "eom_terms": g.eom_terms,
                "set": dict(self.overlay)}

    @classmethod
    def from_record(cls, record: dict) -> "Gear":
        return cls(geometry.Geometry(record["rho_deg"], record["mu_deg"], record["eom_terms"]),
                   tuple(record["set"].items()))

def from_environment(environ: Mapping[str, str] = os.environ) -> Gear:
    """The gear MLG_RHO_DEG, MLG_MU_DEG, MLG_EOM and MLG_SET name;
    GeometryError or OverlayError naming the make variable."""
    return Gear(geometry.from_environment(environ), overlay.from_environment(environ))


@functools.lru_cache(maxsize=1)
def current() -> Gear:
    """The gear of this process (read once)."""
    return from_environment()


def parameters() -> Dict[str, float]:
    return current().parameters()


def simulator_params() -> Dict[str, str]:
    return current().simulator_params()


def suffix() -> str:
    return current().suffix()


def describe() -> str:
    return current().describe()


def start_speed() -> float:
    """Where a run along V from "V = 0" starts: 0 at rho = mu = 0 (as the
    paper's figures); geometry.V_FROM with side-stay angles, where straight
    rolling yaws the wheels and at V = 0 the tyre states are undetermined
    (AUTO stops, MX, at its first step)."""
    return 0.0 if current().symmetric else geometry.V_FROM


def tree(base: str, model: Gear) -> str:
    """The run root of a gear under base (base itself at the baseline,
    and when base already is that gear's tree: a make started from one)."""
    base = os.path.abspath(base)
    if model.baseline:
        return base
    kind = OVERLAY_TREE if model.overlay else GEOMETRY_TREE
    if os.path.basename(base) == model.tag and os.path.basename(os.path.dirname(base)) == kind:
        return base
    return os.path.join(base, kind, model.tag)


def base_root() -> str:
    """The run root of the baseline: MLG_BASE_RUN_ROOT (make exports it with
    a gear), else MLG_RUN_ROOT, else build/."""
    from mlgshimmy.shared import paths
    return os.path.abspath(os.environ.get(ENV_BASE) or paths.run_root())


def baseline_numbers(figure: str) -> Optional[dict]:
    """The "numbers" of the baseline's cached result of a figure, to print
    beside another gear's (None at the baseline or if not computed)."""
    if current().baseline:
        return None
    try:
        with open(os.path.join(base_root(), figure, "result.json")) as f:
            stored = json.load(f)
        data = stored["data"]
        made_for = stored["provenance"].get("model")
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return None
    if made_for is not None and Gear.from_record(made_for) != Gear():
        return None      # not the paper's gear: never shown as the baseline
    numbers = data.get("numbers") if isinstance(data, dict) else None
    return numbers if isinstance(numbers, dict) else None


def stamp(fig: Any) -> None:
    """Name the gear in a figure's title (shared.draw.save calls it):
    appended to its suptitle; else, where one axes alone has a title (the
    figure's, as Fig. 11's), on a line under it; else a suptitle of its
    own (a figure-level one above a single axes' title leaves a blank
    band between the two); nothing at the baseline."""
    if current().baseline:
        return
    title = getattr(fig, "_suptitle", None)
    titled = [ax for ax in fig.axes if ax.get_title()]
    if title is not None and title.get_text():
        title.set_text(title.get_text() + suffix())
    elif len(titled) == 1:
        titled[0].set_title(f"{titled[0].get_title()}\n{describe()}")
    else:
        fig.suptitle(describe(), y=1.0, va="bottom", fontsize="medium")


def check() -> None:
    """The library's range check of the gear at both parameter sets
    (ValueError naming the parameter, in its units); the drivers' entry
    points call it before any run."""
    from mlgshimmy.shared import mlgmodel
    model = current()
    for parameter_set in ("figures", "table"):
        try:
            mlgmodel.Model(parameter_set, **model.parameters())
        except ValueError as exc:
            given = overlay.text(model.overlay, overlay.value_text)
            raise ValueError(f"SET='{given}': {exc}" if model.overlay else str(exc)) from None


def main(argv: Sequence[str]) -> None:
    """`make BASE`: "<tag> <tree> <rho> <mu> <eom>" of the environment's
    gear, for mk/gear.mk; a bad one exits 1 naming the variable."""
    if len(argv) != 2 or argv[0] != "make":
        sys.exit("usage: python3 -m mlgshimmy.shared.gear make BASE_RUN_ROOT")
    try:
        model = from_environment()
    except (geometry.GeometryError, overlay.OverlayError) as exc:
        sys.exit(f"gear: {exc}")
    g = model.geometry
    print(model.tag, tree(argv[1], model), f"{g.rho_deg:.12g}", f"{g.mu_deg:.12g}",
          g.eom_terms)


if __name__ == "__main__":
    main(sys.argv[1:])
