"""A user's change of the model for one run: any constant or parameter of
c/mlg_parameters.h by its name, e.g. `make fig10 SET='k_tlk=3.51e7 I_psi=160'`
(MLG_SET in the environment).  Standard library only: make reads it before
anything is installed or built.

The names and units come from the X-macro tables of c/mlg_parameters.h,
read as text (tests/model/test_gear.py checks them against the built library),
so a typo gets "did you mean" without a build.  Ranges are the library's
own check (mlg_params_check), which shared.gear.check() runs before a
driver starts.  What a figure sets itself (its speed, load, freeplay and
smoothing, the strut's stage order) and the side-stay geometry (RHO, MU,
EOM, in degrees) cannot be overlaid: the message says what to use instead.

The freeplay law is overlaid by its name, `SET='freeplay_law=tanh'` (make's
FREEPLAY=tanh adds that entry): a name of the table MLG_FREEPLAY_LAWS of
c/freeplay_laws.h, read as text too, held as its index there (the switch
freeplay_law); the paper's law (15), atan, is no overlay.
"""
from __future__ import annotations

import math
import os
import re
from typing import Callable, Dict, List, Mapping, Optional, Sequence, Tuple

from mlgshimmy.shared import number_text
from mlgshimmy.shared.suggest import did_you_mean

ENV_SET = "MLG_SET"
HEADER = os.path.join(os.path.dirname(__file__), "..", "..", "..", "c", "mlg_parameters.h")
LAWS_HEADER = os.path.join(os.path.dirname(HEADER), "freeplay_laws.h")
LAW = "freeplay_law"
TABLES = ("MLG_CONTINUATION_PARAMETERS", "MLG_SWITCHES", "MLG_CONSTANTS")
NOT_OVERLAID = {
    **{name: "each figure sets it (its speed, load, freeplay and smoothing)"
       for name in ("V", "Fstar", "yfp", "eps_abs", "eps_rel")},
    "rho": "give the side-stay angle as RHO=<degrees>",
    "mu": "give the side-stay angle as MU=<degrees>",
    "eom_terms": "give the equations' level as EOM=0|1|2",
    "strut_variant": "the figures with the printed stage order are their own targets "
                     "(fig12_v1, fig18_v1)",
    "tyre_forces": "a switch for the library's tests only",
}


class OverlayError(ValueError):
    """A SET that is not one (the message names the make variable and the entry)."""


def _table_text(text: str, table: str) -> str:
    """The continued #define lines of one X-macro table."""
    start = text.index(f"#define {table}(X)")
    lines = []
    for line in text[start:].splitlines():
        lines.append(line)
        if not line.rstrip().endswith("\\"):
            break
    return "\n".join(lines)


def entries(table: str) -> List[Tuple[str, str]]:
    """(name, unit) of each entry of one X-macro table of c/mlg_parameters.h
    with a unit (TABLES), in the table's order."""
    with open(HEADER) as f:
        text = re.sub(r"/\*.*?\*/", "", f.read(), flags=re.S)
    return [(entry.group(1), entry.group(3))
            for entry in re.finditer(r"X\(\s*(\w+)\s*,([^\"]*?)\"([^\"]*)\"",
                                     _table_text(text, table))]


def known() -> Dict[str, str]:
    """{name: unit} of every parameter, switch and constant of the model."""
    return {name: unit for table in TABLES for name, unit in entries(table)}


def laws() -> Tuple[str, ...]:
    """The freeplay laws' names, in the order of their indices."""
    with open(LAWS_HEADER) as f:
        text = re.sub(r"/\*.*?\*/", "", f.read(), flags=re.S)
    return tuple(m.group(1) for m in
                 re.finditer(r"X\(\s*(\w+)\s*,", _table_text(text, "MLG_FREEPLAY_LAWS")))


def law_name(index: float) -> str:
    return laws()[int(index)]


def _law(entry: str, text: str) -> float:
    names = laws()
    if text not in names:
        raise OverlayError(f"SET: {entry!r}: no freeplay law named {text!r}"
                           + did_you_mean(text, names) + f" (the laws: {', '.join(names)})")
    return float(names.index(text))


def _number(entry: str, text: str) -> float:
    value = number_text.parse(text)
    if value is None:
        raise OverlayError(f"SET: {entry!r}: {text!r} is not a number: give {number_text.SYNTAX}")
    if not math.isfinite(value):
        raise OverlayError(f"SET: {entry!r}: the value must be finite")
    return value + 0.0       # -0 is 0


def parse(text: str) -> Tuple[Tuple[str, float], ...]:
    """SET's text (entries NAME=VALUE, separated by blanks or commas) as
    sorted (name, value) pairs; OverlayError names the entry at fault."""
    units = known()
    values: Dict[str, float] = {}
    for entry in text.replace(",", " ").split():
        name, sep, value = entry.partition("=")
        if not sep or not name:
            raise OverlayError(f"SET: {entry!r} is not NAME=VALUE (e.g. SET='k_tlk=3.51e7')")
        if name in NOT_OVERLAID:
            raise OverlayError(f"SET: {name} cannot be overlaid: {NOT_OVERLAID[name]}")
        if name not in units:
            hint = did_you_mean(name, units) or " (the names are those of c/mlg_parameters.h)"
            raise OverlayError(f"SET: no parameter or constant named {name!r}{hint}")
        if name in values:
            raise OverlayError(f"SET: {name} is given twice")
        values[name] = _law(entry, value) if name == LAW else _number(entry, value)
    if values.get(LAW) == 0.0:
        del values[LAW]       # the paper's law: the paper's gear
    return tuple(sorted(values.items()))


def from_environment(environ: Mapping[str, str] = os.environ) -> Tuple[Tuple[str, float], ...]:
    return parse(environ.get(ENV_SET, ""))


def value_text(value: float) -> str:
    """A value in tags and titles: distinct values never share one."""
    return f"{value:.12g}"


def text(items: Sequence[Tuple[str, float]], number: Callable[[float], str] = repr) -> str:
    """SET's text of (name, value) pairs, the law by its name: with the
    default number=repr, parse(text(items)) == items; value_text for messages."""
    return " ".join(f"{name}={law_name(value) if name == LAW else number(value)}"
                    for name, value in items)


def tag_word(name: str, value: float) -> str:
    """An entry in a gear's tag: 'k_tlk_35100000', 'freeplay_tanh'."""
    return f"freeplay_{law_name(value)}" if name == LAW else f"{name}_{value_text(value)}"


def describe(items: Sequence[Tuple[str, float]], units: Optional[Mapping[str, str]] = None) -> str:
    """'k_tlk = 3.51e+07 N/m, I_psi = 160 kg m^2, freeplay law tanh' ('' for none)."""
    units = units if units is not None else known()
    return ", ".join(f"freeplay law {law_name(value)}" if name == LAW else
                     f"{name} = {value_text(value)}"
                     + (f" {units[name]}" if units.get(name, "-") != "-" else "")
                     for name, value in items)
