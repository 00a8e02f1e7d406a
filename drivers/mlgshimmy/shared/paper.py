"""The paper's printed numbers next to ours: one table per figure, printed
and stored as build/tables/<fig>.txt, and as <fig>.json for the
reproduction report (mlgshimmy.report).

    paper.report("fig10", ours_figures, ours_table)

ours_* map a quantity (e.g. "H1 [m/s]") to a value.  A figure for which
the paper prints numbers (PAPER) gets the columns paper, ours, relative
error and a status (status()); a figure for which it prints none gets the
column of ours alone, and a note naming the values the paper withholds as
held-out checks (HELD_OUT), if any."""
from __future__ import annotations

import json
import os
from typing import Any, Dict, List, Mapping, Optional, Sequence

import numpy

from mlgshimmy.shared import paths
from mlgshimmy.shared.jobs import catalogue
from mlgshimmy.shared.jobs.atomic import write_text
from mlgshimmy.shared import gear

# As each figure declares them (shared.jobs.catalogue): every result value
# section IV prints, by the figure that shows it ("paper"; inputs the text
# names, as V = 300 m/s of Fig. 8 or the 120 m/s of IV.E, are not results),
# the quantity the `figures` set was fitted to ("calibrated", model.md
# section 5), and the values the paper replaces by symbols ("held_out": our
# quantity -> the paper's symbol; ours are reported, the paper's never
# guessed).
_FIGURES = catalogue.figures()
PAPER = {e["name"]: e["paper"] for e in _FIGURES if "paper" in e}
CALIBRATED = {(e["name"], q) for e in _FIGURES for q in e.get("calibrated", [])}
HELD_OUT = {e["name"]: e["held_out"] for e in _FIGURES if "held_out" in e}
# Printed numbers a second figure shows again ("repeats": its quantity ->
# [figure, quantity] where it is printed first): counted once, there.
REPEATS = {(e["name"], q): tuple(first) for e in _FIGURES
           for q, first in e.get("repeats", {}).items()}
CLOSE = 0.02   # relative error up to which a value outside the printed digits is "close"


def printed_precision(value: float) -> float:
    """Half a unit of the last digit the paper prints (346.1 -> 0.05)."""
    text = repr(float(value))
    decimals = len(text.split(".")[1].rstrip("0")) if "." in text else 0
    return 0.5 * 10.0 ** -decimals


def status(figure: str, quantity: str, printed: Optional[float], ours: Optional[float]) -> str:
    """How ours compares with the printed value: "calibrated" (the
    parameter set was fitted to it, and ours agrees with it within the
    printed digits), "off its calibration" (fitted to it, but ours no
    longer agrees: a changed model or parameter set), "agrees" (within the
    printed digits), "close" (relative error up to CLOSE), "off", or
    "missing"."""
    if ours is None or not numpy.isfinite(ours):
        return "missing"
    agrees = abs(ours - printed) <= printed_precision(printed) * (1 + 1e-9)
    if (figure, quantity) in CALIBRATED:
        return "calibrated" if agrees else "off its calibration"
    if agrees:
        return "agrees"
    return "close" if abs(ours - printed) <= CLOSE * abs(printed) else "off"


def changed_status(ours: Optional[float]) -> str:
    """The status of a printed quantity at a changed gear, where the paper's
    number describes another gear: "vanished" (no such point any more),
    "changed gear" (the relative error is to the paper's gear's number)."""
    if ours is None or not numpy.isfinite(ours):
        return "vanished"
    return "changed gear"


def rows(figure: str, ours: Mapping[str, Optional[float]],
         ours_table: Optional[Mapping[str, Optional[float]]] = None) -> List[Dict[str, Any]]:
    """[{"quantity", "paper", "ours", "ours_table", "rel_error", "status",
    "held_out"}]: the printed quantities first, then the rest of ours."""
    paper = PAPER.get(figure, {})
    held = HELD_OUT.get(figure, {})
    ours_table = ours_table or {}
    # at a side-stay geometry: the baseline's numbers beside ours ({} if not computed)
    base = None if gear.current().baseline else (gear.baseline_numbers(figure) or {})
    out = []
    for quantity in list(paper) + [q for q in ours if q not in paper]:
        value, printed = ours.get(quantity), paper.get(quantity)
        value = None if value is None else float(value)
        row = {"quantity": quantity, "paper": printed, "ours": value,
               "ours_table": ours_table.get(quantity), "rel_error": None, "status": None,
               "held_out": held.get(quantity)}
        if base is not None:
            row["baseline"] = base.get(quantity)
        if printed is not None:
            if value is not None:
                row["rel_error"] = (value - printed) / printed
            row["status"] = status(figure, quantity, printed, value) if base is None else \
                changed_status(value)
        elif row["held_out"]:
            row["status"] = "held out"
        out.append(row)
    return out


def _cell(value):
    return "-" if value is None else f"{value:.6g}"


def relative(error: Optional[float]) -> str:
    """A relative error as text: +1.24%, or +7.2e-09 when below 0.005 %."""
    if error is None:
        return "-"
    return f"{error:+.1e}" if abs(error) < 5e-5 else f"{error:+.2%}"


def text_of(figure: str, table: Sequence[Mapping[str, Any]]) -> str:
    """The plain-text table of rows()."""
    printed = any(r["paper"] is not None for r in table)
    with_table = any(r["ours_table"] is not None for r in table)
    with_base = any("baseline" in r for r in table)
    head = ["quantity"] + (["paper"] if printed else []) + ["ours"] \
        + (["ours, printed c_psi"] if with_table else []) \
        + (["rel. error", "status"] if printed else []) \
        + (["paper's gear"] if with_base else [])
    lines = [head]
    for r in table:
        line = [r["quantity"]] + ([_cell(r["paper"])] if printed else []) + [_cell(r["ours"])]
        if with_table:
            line.append(_cell(r["ours_table"]))
        if printed:
            line += [relative(r["rel_error"]), r["status"] or "-"]
        if with_base:
            line.append(_cell(r.get("baseline")))
        lines.append(line)
    widths = [max(len(line[k]) for line in lines) for k in range(len(head))]
    body = "\n".join("  ".join(c.ljust(w) for c, w in zip(line, widths)).rstrip()
                     for line in lines)
    if printed:
        title = f"{figure}: paper vs ours (our calibrated parameter set; its rel. error, status)"
    else:
        title = f"{figure}: ours (the paper prints no number for this figure)"
    held = [r["held_out"] + ("" if r["held_out"] == r["quantity"] else f" ({r['quantity']})")
            for r in table if r["held_out"]]
    note = ("\nheld out by the paper (its values replaced by symbols): " + ", ".join(held)
            if held else "")
    at = gear.current()
    if not at.baseline:
        title += (f"\n{figure}: at {at.describe()}; the paper and the baseline column: "
                  "rho = mu = 0, eom_terms = 0"
                  + ("" if with_base and any(r.get("baseline") is not None for r in table)
                     else f" (baseline not computed: make {figure})"))
    return f"{title}\n{body}{note}\n"


def table_path(figure: str, ext: str = "txt") -> str:
    return os.path.join(paths.tables_dir(), f"{figure}.{ext}")


def report(figure: str, ours: Mapping[str, Optional[float]],
           ours_table: Optional[Mapping[str, Optional[float]]] = None,
           notes: Sequence[str] = ()) -> str:
    """Print and store the table (<fig>.txt, and <fig>.json for the
    reproduction report); notes: lines after it (what each named point is);
    returns its text."""
    table = rows(figure, ours, ours_table)
    text = text_of(figure, table) + "".join(f"  {line}\n" for line in notes)
    write_text(table_path(figure), text)
    write_text(table_path(figure, "json"),
               json.dumps({"figure": figure, "rows": table, "notes": list(notes)}, indent=1)
               + "\n")
    print(text, end="")
    return text


def read_table(figure: str) -> Optional[List[Dict[str, Any]]]:
    """The rows a figure's plot step stored (report()), or None."""
    try:
        with open(table_path(figure, "json")) as source:
            return json.load(source)["rows"]
    except (OSError, ValueError, KeyError):
        return None


def in_degrees(numbers: Mapping[str, Optional[float]]) -> Dict[str, Optional[float]]:
    """A copy of {quantity: value} with the quantities in radians ("[rad]",
    "[rad/mm]") in degrees, as the figures plot them."""
    out = {}
    for quantity, value in numbers.items():
        if "[rad" in quantity and value is not None:
            quantity, value = quantity.replace("[rad", "[deg"), float(numpy.degrees(value))
        out[quantity] = value
    return out
