"""Eq. (17)'s allowed freeplay kappa* for every freeplay law of
c/freeplay_laws.h, by the criterion's recipe (shared.kappa_criterion.criterion:
eigenvalue scans, no AUTO): the largest y_fp / eps with straight rolling
stable up to 120 m/s at every load, eps = 0.1 mm.  With eq. (14), which
has no eps, the number read is the freeplay y_fp itself that first
destabilises straight rolling, over 0.1 mm.

    make laws          # under a minute; the table in build/tables/laws.txt
    make laws-plot     # the table again from the cache
"""
from __future__ import annotations

from typing import Any, Dict, Mapping

from mlgshimmy.shared import freeplay
from mlgshimmy.shared import gear, jobs, mlgmodel, paths
from mlgshimmy.shared import kappa_criterion
from mlgshimmy.shared import yfp_runs

DECLARED = {
    "laws": {
        "help": "eq. (17): kappa* for every freeplay law (c/freeplay_laws.h)",
        "time": "20 s",
        "report": {
            "command": "make laws",
            "text": "Eq. (17)'s kappa* for every freeplay law the library ships.",
            "tables": ["tables/laws.txt"],
            "figures": [],
        },
    },
}
FIGURE = "laws"


def compute() -> Dict[str, Any]:
    out = {}
    for law, name in enumerate(mlgmodel.LAWS):
        found = kappa_criterion.criterion({**gear.parameters(), "freeplay_law": law})
        print(f"laws: {name}: kappa* = {found['kappa']:.6g} at F* = {found['Fstar']:g}, "
              f"V = {found['V']} m/s ({found['mode']} mode)")
        out[name] = found
    return {"kappa": out, "eps_mm": freeplay.EPSILON}


def plot(result: Mapping[str, Any]) -> None:
    rows = [("law", "kappa*", "y_fp allowed [mm]", "F*", "V [m/s]", "mode")]
    for name, k in result["kappa"].items():
        rows.append((name, f"{k['kappa']:.6g}", f"{k['kappa'] * result['eps_mm']:.6g}",
                     f"{k['Fstar']:g}", "-" if k["V"] is None else f"{k['V']:g}",
                     str(k["mode"])))
    widths = [max(len(r[c]) for r in rows) for c in range(len(rows[0]))]
    text = (f"laws: eq. (17)'s kappa* by freeplay law (eps = {result['eps_mm']:g} mm; "
            f"straight rolling stable up to {yfp_runs.V_LIMIT:g} m/s at every load)"
            + (f" at {gear.describe()}" if not gear.current().baseline else "") + "\n"
            + "\n".join("  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip()
                        for r in rows) + "\n")
    jobs.write_text(f"{paths.tables_dir()}/{FIGURE}.txt", text)
    print(text, end="")


if __name__ == "__main__":
    jobs.run_figure(FIGURE, compute, plot, module="mlgshimmy.studies.laws")
