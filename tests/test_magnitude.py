"""Freeplay magnitude (drivers/magnitude.py, Figs. 13-19), fast checks:
with eps = 0.1 y_fp the Hopf speeds do not move with y_fp and the orbits
scale linearly with the same frequency (low-frequency branch at y_fp = 0.5
and 1 mm, V = 15 m/s); with eps = 0.1 mm the y_fp thresholds a, b at
V = 120 m/s (eigenvalue scan) agree with AUTO's Hopf points in y_fp and with
the values reported in docs/reproduction.md; the rescaled profiles of the
fixed ratio coincide."""
import os
import sys

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "drivers"))
from mlgshimmy.shared import autoglue  # noqa: E402
from mlgshimmy.shared import continuation as ct  # noqa: E402
from mlgshimmy.shared import spectrum  # noqa: E402
from mlgshimmy.figures import fig15  # noqa: E402
from mlgshimmy.shared import magnitude as mg  # noqa: E402
from mlgshimmy.shared import mlgmodel  # noqa: E402
from check import check, check_close  # noqa: E402

RUNDIR = os.path.join(autoglue.BUILD, "tests", "magnitude")
# docs/reproduction.md, Fig. 16/17 (F* = 1, eps = 0.1 mm, V = 120 m/s)
A_REPORTED, B_REPORTED = 0.054242, 0.213609


def low_branch(yfp):
    """The orbit at V = 15 m/s on the branch born at the first Hopf point."""
    vals = mg.values("ratio", yfp)
    hopf = [v for v, kind, _ in spectrum.stability_changes("figures", "V", mg.V_SCAN, **vals)
            if kind == "HB"]
    hb = ct.hopf_point(RUNDIR, f"hb_{yfp:g}", "figures", "V", hopf[0], **vals)
    run = ct.periodic_from(RUNDIR, f"po_{yfp:g}", hb, stop={"V": 15.5}, UZR={"V": [15.0]},
                           expect=["UZ"], DS=1e-4, DSMAX=mg.DSMAX_V, DSMIN=1e-9, THU=mg.THU)
    return hopf, run("UZ1")


def linear_scaling():
    (hopf_half, half), (hopf_one, one) = low_branch(0.5), low_branch(1.0)
    for k, (h, g) in enumerate(zip(hopf_half, hopf_one)):
        check_close(f"eps = 0.1 y_fp: Hopf speed {k + 1} the same at y_fp = 0.5 and 1 mm",
                    h, g, rel=1e-9)
    check_close("eps = 0.1 y_fp: psi amplitude at V = 15 doubles from y_fp = 0.5 to 1 mm",
                one["psi_amp"] / half["psi_amp"], 2.0, rel=1e-4)
    check_close("eps = 0.1 y_fp: frequency at V = 15 the same at y_fp = 0.5 and 1 mm",
                one["freq"], half["freq"], rel=1e-4)


def thresholds():
    a, b = mg.yfp_crossings(mg.FSTAR, mg.V_LIMIT, "high")[:2]
    check_close("eps = 0.1 mm: a (V = 120) as reported", a, A_REPORTED, rel=2e-5)
    check_close("eps = 0.1 mm: b (V = 120) as reported", b, B_REPORTED, rel=2e-5)
    vals = {"Fstar": mg.FSTAR, "V": mg.V_LIMIT, **mg.SCALINGS["fixed"]}
    for name, y in (("a", a), ("b", b)):
        hb = ct.hopf_point(RUNDIR, f"hb_{name}", "figures", "yfp", y, width=0.05 * y, **vals)
        check_close(f"eps = 0.1 mm: AUTO's Hopf point in y_fp at {name}", hb["yfp"], y, rel=1e-5)
    check("eps = 0.1 mm: straight rolling stable up to 120 m/s just below a",
          all(max(mg.growth(mg.FSTAR, 0.99 * a, V).values()) < 0
              for V in numpy.linspace(mg.V_MIN, mg.V_LIMIT, 25)))


def profiles():
    k_tlk = mlgmodel.Model("figures")["k_tlk"]
    check("eps = 0.1 y_fp: rescaled profiles coincide (spread < 1e-12)",
          fig15.spread("ratio", (0.2, 0.5, 1.0, 2.0), k_tlk) < 1e-12)
    check("eps = 0.1 mm: rescaled profiles differ (spread > 0.1)",
          fig15.spread("fixed", (0.05, 0.35, 1.0), k_tlk) > 0.1)


def main():
    os.makedirs(RUNDIR, exist_ok=True)
    profiles()
    thresholds()
    linear_scaling()


if __name__ == "__main__":
    main()
