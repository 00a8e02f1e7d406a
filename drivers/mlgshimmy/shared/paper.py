"""The paper's printed numbers next to ours: one table per figure, printed
and stored as build/tables/<fig>.txt.

    paper.report("fig10", ours_figures, ours_table)

ours_* map a quantity (e.g. "H1 [m/s]") to a value; quantities the paper
does not print are listed with "-" in its column."""
import os

from mlgshimmy.shared import geometry
from mlgshimmy.shared import paths
from mlgshimmy.shared.jobs.atomic import write_text

# Section IV of the paper (the `figures` set is calibrated on the first one).
PAPER = {
    "fig07": {"H, F* = 1 [m/s]": 346.1},
    "fig10": {"H1 [m/s]": 1.5, "H2 [m/s]": 28.1, "H3 [m/s]": 142.5, "S1 [m/s]": 41.5},
    # IV.D.1: the Fig. 10 diagram is the y_fp = 1 mm slice of Fig. 13
    "fig13": {"y_fp = 1: H1 [m/s]": 1.5, "y_fp = 1: H2 [m/s]": 28.1,
              "y_fp = 1: H3 [m/s]": 142.5, "y_fp = 1: S1 [m/s]": 41.5},
}


def _cell(value):
    return "-" if value is None else f"{value:.6g}"


def report(figure, ours, ours_table=None):
    """Print and store the table; returns its text.  At a side-stay
    geometry (shared.geometry) the table says so and has a column of the
    baseline's numbers (rho = mu = 0, printed equations) where its figure
    has been computed (make <fig> without RHO, MU)."""
    paper = PAPER.get(figure, {})
    ours_table = ours_table or {}
    at = geometry.current()
    base = None if at.baseline else (geometry.baseline_numbers(figure) or {})
    rows = [("quantity", "paper", "ours (figures)", "ours (table)", "rel. error")
            + (("baseline (figures)",) if base is not None else ())]
    for quantity in list(paper) + [q for q in ours if q not in paper]:
        value, printed = ours.get(quantity), paper.get(quantity)
        error = (f"{(value - printed) / printed:+.2%}"
                 if value is not None and printed is not None else "-")
        rows.append((quantity, _cell(printed), _cell(value), _cell(ours_table.get(quantity)),
                     error) + ((_cell(base.get(quantity)),) if base is not None else ()))
    widths = [max(len(row[k]) for row in rows) for k in range(len(rows[0]))]
    lines = ["  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip() for row in rows]
    head = f"{figure}: paper vs ours (rel. error of the figures set)"
    if base is not None:
        head += (f"\n{figure}: at {at.describe()}; the paper and the baseline column: "
                 "rho = mu = 0, eom_terms = 0"
                 + ("" if base else f" (baseline not computed: make {figure})"))
    text = head + "\n" + "\n".join(lines) + "\n"
    write_text(os.path.join(paths.tables_dir(), f"{figure}.txt"), text)
    print(text, end="")
    return text
