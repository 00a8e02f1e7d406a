"""The c_psi calibration of the `figures` parameter set (docs/model.md, c_psi):
continue the zero-freeplay Hopf point of straight rolling at F* = 1 from the
`table` set (c_psi = 410) in (V, c_psi) up to the paper's V = 346.1 m/s."""
from __future__ import annotations

import os
import sys
from typing import Tuple

from mlgshimmy.shared import runerror
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import paths
from mlgshimmy.shared import jobs

# What make, make help, make submit and the report know of this study
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "calibrate": {
        "help": "the c_psi of the `figures` parameter set",
        "time": "2 s",
        "report": {
            "command": "make calibrate",
            "text": ("The c_psi of the `figures` parameter set: the zero-freeplay Hopf point "
                     "at F* = 1 continued in (V, c_psi) from the printed 410 up to 346.1 m/s "
                     "(docs/model.md section 5)."),
            "tables": ["calibration/c_psi.txt"],
            "figures": [],
        },
    },
}

V_PAPER = 346.1


def calibrate(where: str = "calibration") -> Tuple[float, float]:
    rundir = paths.rundir(where)
    start = ct.Start("table", Fstar=1.0, V=0.0)
    eq = ct.equilibria(rundir, "eq", start, stop={"V": 600.0}, expect=["HB"])
    curve = ct.hopf_curve(rundir, "hopf_c_psi", eq("HB1"), parameters=("V", "c_psi"), DS=1.0,
                          DSMAX=5.0, stop={"V": V_PAPER}, expect=["UZ"], NMX=500)
    return eq("HB1")["V"], curve("UZ1")["c_psi"]


def main() -> None:
    try:
        v_table, c_psi = calibrate()
    except (runerror.RunError, ValueError, RuntimeError) as exc:
        sys.exit(f"calibrate_c_psi: {exc}")
    lines = [f"Hopf speed at F* = 1 with the table c_psi = 410: V = {v_table:.3f} m/s",
             f"c_psi putting it at V = {V_PAPER} m/s: {c_psi:.4f} N m s/rad",
             f"MLG_C_PSI_FIGURES in c/parameters.c: {mlgmodel.C_PSI_FIGURES}"]
    path = os.path.join(paths.rundir("calibration"), "c_psi.txt")
    jobs.write_text(path, "\n".join(lines) + "\n")
    print("\n".join("calibrate_c_psi: " + line for line in lines))
    if abs(c_psi - mlgmodel.C_PSI_FIGURES) > 0.05:
        sys.exit("calibrate_c_psi: MLG_C_PSI_FIGURES differs from the calibration by more "
                 "than 0.05: update c/parameters.c")


if __name__ == "__main__":
    main()
